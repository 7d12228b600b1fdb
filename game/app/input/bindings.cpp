#include "app/input/bindings.h"

#include <algorithm>

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;

constexpr std::array<const char*, kBoundActions> kActionNames = {"turn-left", "turn-right", "thrust", "fire",
                                                                 "pause"};
constexpr std::array<const char*, static_cast<std::size_t>(GamepadButton::Count)> kButtonNames = {
    "a",
    "b",
    "x",
    "y",
    "back",
    "guide",
    "start",
    "left-stick",
    "right-stick",
    "left-shoulder",
    "right-shoulder",
    "dpad-up",
    "dpad-down",
    "dpad-left",
    "dpad-right"};

}  // namespace

const char* boundActionName(BoundAction action) {
    return kActionNames[static_cast<std::size_t>(action)];
}

std::optional<BoundAction> boundActionFromName(const std::string& name) {
    for (std::size_t i = 0; i < kBoundActions; ++i)
        if (name == kActionNames[i]) return static_cast<BoundAction>(i);
    return std::nullopt;
}

const char* gamepadButtonName(GamepadButton button) {
    return kButtonNames[static_cast<std::size_t>(button)];
}

std::optional<GamepadButton> gamepadButtonFromName(const std::string& name) {
    for (std::size_t i = 0; i < kButtonNames.size(); ++i)
        if (name == kButtonNames[i]) return static_cast<GamepadButton>(i);
    return std::nullopt;
}

std::optional<std::string> reservedKeyReason(Key key) {
    switch (key) {
        case Key::Escape:
            return std::string("Esc is the way back and always pauses");
        case Key::Enter:
        case Key::KeypadEnter:
            return std::string("Enter confirms in the menus");
        case Key::F1:
            return std::string("F1 shows the debug panel");
        case Key::F5:
            return std::string("F5 reloads the bounds files");
        case Key::F11:
            return std::string("F11 toggles fullscreen");
        case Key::Unknown:
        case Key::Count:
            return std::string("that key has no name");
        default:
            return std::nullopt;
    }
}

Bindings::Bindings() {
    for (Buttons& buttons : buttons_) buttons.fill(GamepadButton::Count);
}

Bindings Bindings::defaults() {
    Bindings b;
    b.keys_[index(BoundAction::TurnLeft)] = {Key::Left, Key::A};
    b.keys_[index(BoundAction::TurnRight)] = {Key::Right, Key::D};
    b.keys_[index(BoundAction::Thrust)] = {Key::Up, Key::W};
    b.keys_[index(BoundAction::Fire)] = {Key::Space, Key::Unknown};
    b.keys_[index(BoundAction::Pause)] = {Key::P, Key::Unknown};
    b.buttons_[index(BoundAction::TurnLeft)][0] = GamepadButton::DpadLeft;
    b.buttons_[index(BoundAction::TurnRight)][0] = GamepadButton::DpadRight;
    b.buttons_[index(BoundAction::Thrust)][0] = GamepadButton::B;
    b.buttons_[index(BoundAction::Fire)][0] = GamepadButton::A;
    b.buttons_[index(BoundAction::Pause)][0] = GamepadButton::Start;
    return b;
}

std::optional<BoundAction> Bindings::actionOfKey(Key key) const {
    if (key == Key::Unknown) return std::nullopt;
    for (std::size_t a = 0; a < kBoundActions; ++a)
        if (std::find(keys_[a].begin(), keys_[a].end(), key) != keys_[a].end())
            return static_cast<BoundAction>(a);
    return std::nullopt;
}

std::optional<BoundAction> Bindings::actionOfButton(GamepadButton button) const {
    if (button == GamepadButton::Count) return std::nullopt;
    for (std::size_t a = 0; a < kBoundActions; ++a)
        if (std::find(buttons_[a].begin(), buttons_[a].end(), button) != buttons_[a].end())
            return static_cast<BoundAction>(a);
    return std::nullopt;
}

std::optional<std::string> Bindings::bindKey(BoundAction action, std::size_t slot, Key key) {
    if (slot >= kSlots) return "there are " + std::to_string(kSlots) + " keys an action";
    if (std::optional<std::string> reserved = reservedKeyReason(key)) return reserved;
    std::optional<BoundAction> owner = actionOfKey(key);
    if (owner && *owner != action)
        return std::string(platform::keyName(key)) + " already gives " + boundActionName(*owner);
    Keys& keys = keys_[index(action)];
    if (owner && keys[slot] != key)
        return std::string(platform::keyName(key)) + " is already in the other slot";
    keys[slot] = key;
    return std::nullopt;
}

std::optional<std::string> Bindings::bindButton(BoundAction action, std::size_t slot, GamepadButton button) {
    if (slot >= kSlots) return "there are " + std::to_string(kSlots) + " buttons an action";
    if (button == GamepadButton::Count) return std::string("that button has no name");
    if (button == GamepadButton::Back || button == GamepadButton::Guide)
        return std::string(gamepadButtonName(button)) + " is the way back";
    std::optional<BoundAction> owner = actionOfButton(button);
    if (owner && *owner != action)
        return std::string(gamepadButtonName(button)) + " already gives " + boundActionName(*owner);
    Buttons& buttons = buttons_[index(action)];
    if (owner && buttons[slot] != button)
        return std::string(gamepadButtonName(button)) + " is already in the other slot";
    buttons[slot] = button;
    return std::nullopt;
}

void Bindings::clearKey(BoundAction action, std::size_t slot) {
    if (slot < kSlots) keys_[index(action)][slot] = Key::Unknown;
}

void Bindings::clearButton(BoundAction action, std::size_t slot) {
    if (slot < kSlots) buttons_[index(action)][slot] = GamepadButton::Count;
}

}  // namespace polar::game
