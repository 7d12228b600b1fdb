#include "app/input/hints.h"

#include <algorithm>

namespace polar::game {
namespace {

using platform::GamepadButton;
using platform::Key;

std::string upper(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return c == '-' ? ' ' : static_cast<char>(std::toupper(c)); });
    return text;
}

// The bound keys of an action joined by "/" ("LEFT/A"), or "-" when none is bound.
std::string keysOf(const Bindings& bindings, BoundAction action) {
    std::string out;
    for (Key key : bindings.keys(action))
        if (key != Key::Unknown) out += (out.empty() ? "" : "/") + upper(platform::keyName(key));
    return out.empty() ? "-" : out;
}

std::string buttonsOf(const Bindings& bindings, BoundAction action) {
    std::string out;
    for (GamepadButton button : bindings.buttons(action))
        if (button != GamepadButton::Count)
            out += (out.empty() ? "" : "/") + upper(gamepadButtonName(button));
    return out;
}

bool defaultSteering(const Bindings& bindings) {
    const Bindings defaults = Bindings::defaults();
    for (BoundAction action : {BoundAction::TurnLeft, BoundAction::TurnRight, BoundAction::Thrust})
        if (bindings.keys(action) != defaults.keys(action)) return false;
    return true;
}

}  // namespace

std::string playHint(const Bindings& bindings, Device device) {
    switch (device) {
        case Device::Touch:
            return "TOUCH: ARROWS TURN   THRUST   FIRE   II PAUSES   TAP A ROW TO CHOOSE";
        case Device::Gamepad: {
            std::string thrust = buttonsOf(bindings, BoundAction::Thrust);
            std::string fire = buttonsOf(bindings, BoundAction::Fire);
            std::string pause = buttonsOf(bindings, BoundAction::Pause);
            return "STICK TURNS   STICK UP" + (thrust.empty() ? std::string() : " OR " + thrust) +
                   " THRUSTS" + (fire.empty() ? std::string() : "   " + fire + " FIRES") +
                   (pause.empty() ? std::string() : "   " + pause + " PAUSES");
        }
        case Device::Keyboard:
            break;
    }
    const std::string steer = defaultSteering(bindings)
                                  ? "ARROWS/WASD TURN AND THRUST"
                                  : keysOf(bindings, BoundAction::TurnLeft) + " " +
                                        keysOf(bindings, BoundAction::TurnRight) + " TURN   " +
                                        keysOf(bindings, BoundAction::Thrust) + " THRUSTS";
    return steer + "   " + keysOf(bindings, BoundAction::Fire) + " FIRES   " + pauseWord(bindings, device) +
           " PAUSES   F1 BOUNDS   F11 FULLSCREEN";
}

std::string confirmWord(Device device) {
    switch (device) {
        case Device::Gamepad:
            return "A";
        case Device::Touch:
            return "TAP";
        case Device::Keyboard:
            break;
    }
    return "ENTER";
}

std::string backWord(Device device) {
    switch (device) {
        case Device::Gamepad:
            return "B";
        case Device::Touch:
            return "";
        case Device::Keyboard:
            break;
    }
    return "ESC";
}

std::string pauseWord(const Bindings& bindings, Device device) {
    switch (device) {
        case Device::Gamepad: {
            const std::string pause = buttonsOf(bindings, BoundAction::Pause);
            return pause.empty() ? "START" : pause;
        }
        case Device::Touch:
            return "II";
        case Device::Keyboard:
            break;
    }
    // Esc always pauses; a bound key is named first.
    const Key first = bindings.keys(BoundAction::Pause)[0];
    return first == Key::Unknown ? "ESC" : upper(platform::keyName(first));
}

}  // namespace polar::game
