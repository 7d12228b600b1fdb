#include "app/input/bindings.h"

#include <gtest/gtest.h>

#include <set>

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;

// The controls before bindings existed (game/app/input.cpp until issue 26), kept here as the
// reference the default bindings must reproduce bit for bit: replays record these Actions.
Actions todaysActions(const std::set<Key>& held, const std::vector<Bindings::PadState>& pads) {
    auto has = [&](Key k) { return held.count(k) > 0; };
    Actions actions = 0;
    if (has(Key::Left) || has(Key::A)) actions |= kTurnLeft;
    if (has(Key::Right) || has(Key::D)) actions |= kTurnRight;
    if (has(Key::Up) || has(Key::W)) actions |= kThrust;
    if (has(Key::Space)) actions |= kFire;
    const double dead = 12000.0 / 32768.0, trigger = 8000.0 / 32768.0;
    for (const Bindings::PadState& pad : pads) {
        auto button = [&](GamepadButton b) { return pad.buttons[static_cast<std::size_t>(b)]; };
        if (pad.leftX < -dead || button(GamepadButton::DpadLeft)) actions |= kTurnLeft;
        if (pad.leftX > dead || button(GamepadButton::DpadRight)) actions |= kTurnRight;
        if (pad.leftY < -dead || button(GamepadButton::B) || pad.rightTrigger > trigger) actions |= kThrust;
        if (button(GamepadButton::A)) actions |= kFire;
    }
    return actions;
}

TEST(Bindings, DefaultsGiveTodaysActionsForEveryKeyCombination) {
    const std::vector<Key> keys = {Key::Left, Key::A,     Key::Right, Key::D, Key::Up,
                                   Key::W,    Key::Space, Key::P,     Key::S, Key::Down};
    const Bindings bindings = Bindings::defaults();
    for (unsigned mask = 0; mask < (1u << keys.size()); ++mask) {
        std::set<Key> held;
        for (std::size_t i = 0; i < keys.size(); ++i)
            if (mask & (1u << i)) held.insert(keys[i]);
        auto keyHeld = [&](Key k) { return held.count(k) > 0; };
        ASSERT_EQ(bindings.actions(keyHeld, {}), todaysActions(held, {})) << "keys mask " << mask;
    }
}

TEST(Bindings, DefaultsGiveTodaysActionsForEveryPadButtonAndAxis) {
    const Bindings bindings = Bindings::defaults();
    auto none = [](Key) { return false; };
    for (std::size_t b = 0; b < static_cast<std::size_t>(GamepadButton::Count); ++b) {
        Bindings::PadState pad;
        pad.buttons[b] = true;
        EXPECT_EQ(bindings.actions(none, {pad}), todaysActions({}, {pad}))
            << gamepadButtonName(GamepadButton(b));
    }
    for (double x : {-1.0, -0.37, -0.36, 0.0, 0.36, 0.37, 1.0})
        for (double y : {-1.0, -0.37, 0.0, 1.0})
            for (double t : {0.0, 0.24, 0.25, 1.0}) {
                Bindings::PadState pad;
                pad.leftX = x, pad.leftY = y, pad.rightTrigger = t;
                Bindings::PadState second;
                second.buttons[static_cast<std::size_t>(GamepadButton::A)] = true;
                EXPECT_EQ(bindings.actions(none, {pad, second}), todaysActions({}, {pad, second}));
            }
}

TEST(Bindings, RemappedKeyMovesItsAction) {
    Bindings b = Bindings::defaults();
    ASSERT_EQ(b.bindKey(BoundAction::Fire, 1, Key::F), std::nullopt);
    auto held = [](Key k) { return k == Key::F; };
    EXPECT_EQ(b.actions(held, {}), kFire);
    b.clearKey(BoundAction::Fire, 0);
    auto space = [](Key k) { return k == Key::Space; };
    EXPECT_EQ(b.actions(space, {}), 0);
    EXPECT_EQ(b.actionOfKey(Key::F), BoundAction::Fire);
    EXPECT_EQ(b.actionOfKey(Key::Space), std::nullopt);
}

TEST(Bindings, ConflictsAreRefusedWithAReason) {
    Bindings b = Bindings::defaults();
    const Bindings before = b;
    EXPECT_EQ(b.bindKey(BoundAction::Fire, 0, Key::W), std::optional<std::string>("w already gives thrust"));
    EXPECT_EQ(b.bindKey(BoundAction::Fire, 1, Key::Escape),
              std::optional<std::string>("Esc is the way back and always pauses"));
    EXPECT_EQ(b.bindKey(BoundAction::Thrust, 0, Key::Enter),
              std::optional<std::string>("Enter confirms in the menus"));
    EXPECT_EQ(b.bindKey(BoundAction::TurnLeft, 1, Key::Left),
              std::optional<std::string>("left is already in the other slot"));
    EXPECT_EQ(b.bindButton(BoundAction::Fire, 0, GamepadButton::B),
              std::optional<std::string>("b already gives thrust"));
    EXPECT_EQ(b.bindButton(BoundAction::Fire, 1, GamepadButton::Back),
              std::optional<std::string>("back is the way back"));
    EXPECT_EQ(b, before);                                                     // nothing changed by a refusal
    EXPECT_EQ(b.bindKey(BoundAction::TurnLeft, 0, Key::Left), std::nullopt);  // the same key again: fine
    EXPECT_EQ(b, before);
}

TEST(Bindings, NamesRoundTrip) {
    for (std::size_t a = 0; a < kBoundActions; ++a)
        EXPECT_EQ(boundActionFromName(boundActionName(BoundAction(a))), BoundAction(a));
    for (std::size_t b = 0; b < static_cast<std::size_t>(GamepadButton::Count); ++b)
        EXPECT_EQ(gamepadButtonFromName(gamepadButtonName(GamepadButton(b))), GamepadButton(b));
    EXPECT_EQ(boundActionFromName("jump"), std::nullopt);
    EXPECT_EQ(gamepadButtonFromName("z"), std::nullopt);
}

}  // namespace
}  // namespace polar::game
