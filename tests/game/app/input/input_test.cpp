#include "app/input/input.h"

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

TEST(Input, TextPointerAndWheelReachTheMenus) {
    Input input;
    input.handle(platform::TextEntered{"bo"});
    input.handle(KeyPressed{Key::Backspace, Key::Backspace, platform::kModNone, true});  // held: repeats
    input.handle(platform::MouseMoved{10, 20, Vec2(5.5, 10.5)});
    input.handle(platform::MouseButtonPressed{platform::MouseButton::Left, 30, 40, Vec2(15.5, 20.5)});
    input.handle(platform::MouseWheelScrolled{0, -2});
    const Input::Commands c = input.takeCommands();
    EXPECT_EQ(c.text, "bo");
    EXPECT_TRUE(c.erase);
    ASSERT_TRUE(c.pointer && c.click);
    EXPECT_EQ(*c.click, Vec2(15.5, 20.5));
    EXPECT_EQ(c.wheel, -2);
    EXPECT_EQ(c.events.size(), 5u);
    Input right;
    right.handle(platform::MouseButtonPressed{platform::MouseButton::Right, 0, 0, Vec2(1, 1)});
    EXPECT_FALSE(right.takeCommands().click) << "only the left button clicks";
}

// Actions come from what the events say is held, so a script and a window play alike.
TEST(Input, HeldKeysAndPadsAreTheActions) {
    Input input;
    EXPECT_EQ(input.actions(), 0);
    input.handle(KeyPressed{Key::W, Key::Z});  // by position: the key where W is on a US layout
    EXPECT_EQ(input.actions(), 0) << "Z's place is not thrust";
    input.handle(KeyPressed{Key::Z, Key::W});
    input.handle(KeyPressed{Key::Space, Key::Space});
    EXPECT_EQ(input.actions(), kThrust | kFire);
    input.handle(platform::KeyReleased{Key::Z, Key::W});
    EXPECT_EQ(input.actions(), kFire);
    input.handle(platform::GamepadAxisMoved{2, platform::GamepadAxis::LeftX, -0.9});
    input.handle(platform::GamepadButtonPressed{2, GamepadButton::B});
    EXPECT_EQ(input.actions(), kFire | kTurnLeft | kThrust);
    input.handle(platform::GamepadDisconnected{2});
    EXPECT_EQ(input.actions(), kFire) << "a pad that is gone holds nothing";
}

TEST(Input, PadBGoesBackAndTheStickStepsMenus) {
    EXPECT_TRUE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::B}).back);
    EXPECT_FALSE(commandsFor(platform::GamepadButtonPressed{3, GamepadButton::B}).pause)
        << "B thrusts in play";
    Input input;
    input.handle(platform::GamepadAxisMoved{3, platform::GamepadAxis::LeftY, 0.9});
    EXPECT_TRUE(input.takeCommands().down);
    input.handle(platform::GamepadAxisMoved{3, platform::GamepadAxis::LeftY, 1.0});
    EXPECT_FALSE(input.takeCommands().down) << "held past the dead zone: one step";
    input.handle(platform::GamepadAxisMoved{3, platform::GamepadAxis::LeftY, 0});
    input.handle(platform::GamepadAxisMoved{3, platform::GamepadAxis::LeftY, -0.9});
    EXPECT_TRUE(input.takeCommands().up);
}

}  // namespace
}  // namespace polar::game
