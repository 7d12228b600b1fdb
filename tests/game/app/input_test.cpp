#include "app/input.h"

#include <gtest/gtest.h>

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;
using platform::KeyPressed;

Input::Commands commandsFor(const platform::Event& event) {
    Input input;
    input.handle(event);
    return input.takeCommands();
}

TEST(Input, KeysGiveMenuCommandsByTheirLayoutMeaning) {
    EXPECT_TRUE(commandsFor(KeyPressed{Key::Escape, Key::Escape}).back);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::Escape, Key::Escape}).pause);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::P, Key::P}).pause);
    EXPECT_FALSE(commandsFor(KeyPressed{Key::P, Key::P}).back);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::Space, Key::Space}).confirm);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::KeypadEnter, Key::KeypadEnter}).confirm);
    EXPECT_FALSE(commandsFor(KeyPressed{Key::Enter, Key::Enter, platform::kModAlt}).confirm);  // fullscreen
    EXPECT_TRUE(commandsFor(KeyPressed{Key::F1, Key::F1}).debugOverlay);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::F5, Key::F5}).reload);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::W, Key::Z}).up);  // "W" typed on an AZERTY keyboard
    EXPECT_TRUE(commandsFor(KeyPressed{Key::Down, Key::Down}).down);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::A, Key::Q}).left);
    EXPECT_TRUE(commandsFor(KeyPressed{Key::D, Key::D}).right);
    EXPECT_FALSE(commandsFor(KeyPressed{Key::P, Key::P, platform::kModNone, true}).pause);  // held: once
    EXPECT_FALSE(commandsFor(platform::KeyReleased{Key::P, Key::P}).pause);
}

TEST(Input, GamepadButtonsAndQuit) {
    EXPECT_TRUE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::Start}).pause);
    EXPECT_TRUE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::A}).confirm);
    EXPECT_TRUE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::Back}).back);
    EXPECT_TRUE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::DpadUp}).up);
    EXPECT_TRUE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::DpadRight}).right);
    EXPECT_FALSE(commandsFor(platform::GamepadButtonReleased{3, GamepadButton::Start}).pause);
    EXPECT_TRUE(commandsFor(platform::QuitRequested{}).quit);
}

TEST(Input, ClicksAndALostFocus) {
    EXPECT_TRUE(
        commandsFor(platform::MouseButtonPressed{platform::MouseButton::Left, 5, 7, {2.5, 3.5}}).click);
    EXPECT_FALSE(
        commandsFor(platform::MouseButtonPressed{platform::MouseButton::Right, 5, 7, {2.5, 3.5}}).click);
    EXPECT_FALSE(
        commandsFor(platform::MouseButtonReleased{platform::MouseButton::Left, 5, 7, {2.5, 3.5}}).click);
    EXPECT_FALSE(commandsFor(platform::MouseButtonPressed{}).confirm);  // a click is not a key's confirm
    EXPECT_TRUE(commandsFor(platform::WindowFocusLost{}).focusLost);
    EXPECT_FALSE(commandsFor(platform::WindowFocusLost{}).pause);
}

TEST(Input, CommandsAreTakenOnce) {
    Input input;
    input.handle(KeyPressed{Key::Space, Key::Space});
    input.handle(KeyPressed{Key::F1, Key::F1});
    Input::Commands first = input.takeCommands();
    EXPECT_TRUE(first.confirm);
    EXPECT_TRUE(first.debugOverlay);
    Input::Commands second = input.takeCommands();
    EXPECT_FALSE(second.confirm);
    EXPECT_FALSE(second.debugOverlay);
}

}  // namespace
}  // namespace polar::game
