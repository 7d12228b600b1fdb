#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "app/input/bindings.h"
#include "polar/math.h"
#include "polar/platform/events.h"
#include "rules/actions.h"

namespace polar::game {

// The device the player uses, for the hints that name its controls: the keyboard (and mouse), a
// game controller, or a touch screen's controls (the web page on a phone says so).
enum class Device : std::uint8_t { Keyboard, Gamepad, Touch };

// Turns the platform's input events into the per-tick Actions the game records, and into menu
// commands (pause, confirm, a click, typed letters, …) that never reach the simulation.
//
// Why from events alone? A player's window and a test's script then reach the game by one path:
// whatever the events say is held is what the ship does, so a scripted run plays exactly as the
// same keys pressed by hand would.
//
// The game's actions and pause come from the Bindings (the options' key map: by default arrows or
// WASD turn and thrust, space fires, P pauses; the d-pad turns, B thrusts, A fires, Start pauses;
// the left stick and the right trigger always steer and thrust). Fixed: Esc pauses too, Enter
// confirms, Esc goes back. Gamepads are plugged in or out at any time (the window opens them); in
// menus the d-pad or the
// stick moves, A confirms, B or Back goes back. Mouse: the pointer focuses, the left button
// clicks, the wheel scrolls.
class Input {
  public:
    // The menu commands of one frame. Directions and buttons are presses (a held key counts once).
    struct Commands {
        bool pause = false;
        bool confirm = false;
        bool back = false;
        bool debugOverlay = false;                                   // F1
        bool reload = false;                                         // F5
        bool up = false, down = false, left = false, right = false;  // menu navigation
        bool quit = false;                                           // the window's close button
        bool focusLost = false;       // the window lost the focus, or the page was hidden (WindowFocusLost)
        std::optional<Vec2> pointer;  // where the mouse moved to, in canvas pixels
        std::optional<Vec2> click;    // where the left button went down, in canvas pixels
        double wheel = 0;             // notches; > 0 away from the player (up a list)
        // What was typed (UTF-8), for the name entry. A held key's repeats type nothing: a key
        // held down when the name entry opened (fire at the moment of death) is not a letter.
        std::string text;
        bool fire = false;   // a key or button bound to fire went down (hold fire toggles)
        bool erase = false;  // Backspace
        // Every event of the frame as it came, for a screen that must see raw keys (remapping).
        std::vector<platform::Event> events;
    };

    // Notes the menu commands in one event and follows what is held.
    void handle(const platform::Event& event);
    // What the player holds right now, as game actions: keys by their position (WASD stays under
    // the left hand on any layout), and every connected gamepad.
    Actions actions() const;
    // Menu commands since the last call.
    Commands takeCommands();
    // The device used last: the keyboard's or a pad's press (or the stick) makes it theirs. Once
    // pinned (the web page says a touch screen is in use), events no longer change it.
    Device device() const { return device_; }
    void pinDevice(Device device) {
        device_ = device;
        pinned_ = true;
    }
    // The key map actions() and pause follow (Bindings::defaults() until set).
    void setBindings(const Bindings& bindings) { bindings_ = bindings; }
    const Bindings& bindings() const { return bindings_; }

  private:
    struct Pad {
        std::array<bool, static_cast<std::size_t>(platform::GamepadButton::Count)> buttons{};
        std::array<double, static_cast<std::size_t>(platform::GamepadAxis::Count)> axes{};
    };
    void padAxis(const platform::GamepadAxisMoved& moved);

    Commands commands_;
    std::array<bool, static_cast<std::size_t>(platform::Key::Count)> keys_{};  // held, by position
    std::map<platform::GamepadId, Pad> pads_;                                  // connected, by id
    Bindings bindings_ = Bindings::defaults();
    bool lastPressRepeated_ = false;  // the key press before a text event was a repeat
    Device device_ = Device::Keyboard;
    bool pinned_ = false;
};

}  // namespace polar::game
