#pragma once
#include "polar/platform/events.h"
#include "rules/actions.h"

namespace polar::platform {
class Window;
}

namespace polar::game {

// Turns the window's keyboard and gamepad input into the per-tick Actions the game records, and
// into menu commands (pause, confirm, …) that never reach the simulation.
//
// Keyboard: arrows or WASD turn and thrust, space fires, Esc or P pauses, Enter confirms.
// Gamepads (plugged in or out at any time; the window opens them): left stick or d-pad turns,
// stick up, B or right trigger thrusts, A fires, Start pauses. Mouse: a left click (in a browser,
// also a tap) on the canvas is a click, which starts and resumes.
class Input {
  public:
    struct Commands {
        bool pause = false;
        bool confirm = false;
        bool back = false;
        bool debugOverlay = false;                                   // F1
        bool reload = false;                                         // F5
        bool up = false, down = false, left = false, right = false;  // menu navigation
        bool click = false;      // the left mouse button, or a tap, on the canvas
        bool focusLost = false;  // the window lost the focus, or the page was hidden
        bool quit = false;
    };

    // Notes the menu commands in one event.
    void handle(const platform::Event& event);
    // What the player holds right now, as game actions: keys by their position (WASD stays under
    // the left hand on any layout), and every connected gamepad.
    static Actions actions(const platform::Window& window);
    // Menu commands since the last call.
    Commands takeCommands();
    // Drains the window's events into handle() and returns takeCommands(): what a frame of any
    // windowed loop starts with.
    Commands pollEvents(platform::Window& window);

  private:
    Commands commands_;
};

}  // namespace polar::game
