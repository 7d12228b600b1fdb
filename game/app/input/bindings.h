#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "polar/platform/events.h"
#include "rules/actions.h"

namespace polar::game {

// The actions a player can bind: the four the game records, and pause.
enum class BoundAction : std::uint8_t { TurnLeft, TurnRight, Thrust, Fire, Pause, Count };
inline constexpr std::size_t kBoundActions = static_cast<std::size_t>(BoundAction::Count);

// The action's name in settings.json and on screen: "turn-left", "turn-right", "thrust", "fire",
// "pause".
const char* boundActionName(BoundAction action);
std::optional<BoundAction> boundActionFromName(const std::string& name);

// Which keys and pad buttons give which action. Each action holds up to kSlots keys and kSlots
// buttons; a key or a button gives one action only.
//
// Why keys by position? The bindings name keys as a US keyboard prints them and match them by
// their place (Key `position`), so WASD stays under the left hand on any layout, as before. The
// left stick and the right trigger are not rebindable: they keep turning and thrusting beside the
// d-pad whatever the buttons do, so a pad with a remapped d-pad still steers.
class Bindings {
  public:
    static constexpr std::size_t kSlots = 2;
    using Keys = std::array<platform::Key, kSlots>;               // Key::Unknown: empty slot
    using Buttons = std::array<platform::GamepadButton, kSlots>;  // GamepadButton::Count: empty slot

    // Today's controls: arrows and WASD, space fires, P pauses (Esc pauses too, always: it is the
    // way back and cannot be bound away); d-pad, B thrusts, A fires, Start pauses.
    static Bindings defaults();
    // Nothing bound.
    Bindings();

    const Keys& keys(BoundAction action) const { return keys_[index(action)]; }
    const Buttons& buttons(BoundAction action) const { return buttons_[index(action)]; }

    // Binds `key` to slot `slot` of `action`. Refused, with a reason a screen can show, when the key
    // gives another action already, or is one the menus keep (Esc, Enter, F1, F5, F11).
    std::optional<std::string> bindKey(BoundAction action, std::size_t slot, platform::Key key);
    std::optional<std::string> bindButton(BoundAction action, std::size_t slot,
                                          platform::GamepadButton button);
    // Empties a slot.
    void clearKey(BoundAction action, std::size_t slot);
    void clearButton(BoundAction action, std::size_t slot);

    // The action a key or a button gives, if any.
    std::optional<BoundAction> actionOfKey(platform::Key key) const;
    std::optional<BoundAction> actionOfButton(platform::GamepadButton button) const;

    // One pad as it is held now.
    struct PadState {
        std::array<bool, static_cast<std::size_t>(platform::GamepadButton::Count)> buttons{};
        double leftX = 0, leftY = 0, rightTrigger = 0;  // of ±1 (the trigger 0…1)
    };
    // What the player holds as game actions (Pause is not one: it is a menu command), from a query
    // of the held keys (by position) and the pads' states.
    template <class KeyHeld>
    Actions actions(const KeyHeld& keyHeld, const std::vector<PadState>& pads) const;

    bool operator==(const Bindings&) const = default;

  private:
    static std::size_t index(BoundAction action) { return static_cast<std::size_t>(action); }
    std::array<Keys, kBoundActions> keys_{};
    std::array<Buttons, kBoundActions> buttons_{};
};

template <class KeyHeld>
Actions Bindings::actions(const KeyHeld& keyHeld, const std::vector<PadState>& pads) const {
    // Axis readings past which a stick counts as pushed and a trigger as pulled (of ±1).
    constexpr double kStickDeadZone = 12000.0 / 32768.0;
    constexpr double kTriggerPressed = 8000.0 / 32768.0;
    constexpr Actions kGameAction[kBoundActions] = {kTurnLeft, kTurnRight, kThrust, kFire, 0};
    Actions out = 0;
    for (std::size_t a = 0; a < kBoundActions; ++a)
        for (platform::Key key : keys_[a])
            if (key != platform::Key::Unknown && keyHeld(key)) out |= kGameAction[a];
    for (const PadState& pad : pads) {
        if (pad.leftX < -kStickDeadZone) out |= kTurnLeft;
        if (pad.leftX > kStickDeadZone) out |= kTurnRight;
        if (pad.leftY < -kStickDeadZone || pad.rightTrigger > kTriggerPressed) out |= kThrust;
        for (std::size_t a = 0; a < kBoundActions; ++a)
            for (platform::GamepadButton button : buttons_[a])
                if (button != platform::GamepadButton::Count && pad.buttons[static_cast<std::size_t>(button)])
                    out |= kGameAction[a];
    }
    return out;
}

// The reason a key cannot be bound at all (kept by the menus), or nothing.
std::optional<std::string> reservedKeyReason(platform::Key key);
// A pad button's name in settings.json and on screen: "a", "b", "x", "y", "back", "guide", "start",
// "left-stick", "right-stick", "left-shoulder", "right-shoulder", "dpad-up", "dpad-down",
// "dpad-left", "dpad-right".
const char* gamepadButtonName(platform::GamepadButton button);
std::optional<platform::GamepadButton> gamepadButtonFromName(const std::string& name);

}  // namespace polar::game
