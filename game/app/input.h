#pragma once
#include "app/bindings.h"
#include "polar/platform/events.h"
#include "rules/actions.h"

namespace polar::platform {
class Window;
}

namespace polar::game {

// Turns the window's keyboard and gamepad input into the per-tick Actions the game records, and
// into menu commands (pause, confirm, …) that never reach the simulation.
//
// The game's actions and pause come from the Bindings (the options' key map; by default arrows or
// WASD turn and thrust, space fires, P pauses; on a pad the d-pad turns, B thrusts, A fires, Start
// pauses; the left stick and right trigger always steer and thrust). The menu keys are fixed:
// Esc pauses and goes back, Enter or space confirms, arrows or WASD move, Back goes back.
class Input {
  public:
    struct Commands {
        bool pause = false;
        bool confirm = false;
        bool back = false;
        bool debugOverlay = false;                                   // F1
        bool reload = false;                                         // F5
        bool up = false, down = false, left = false, right = false;  // menu navigation
        bool quit = false;
    };

    // Notes the menu commands in one event.
    void handle(const platform::Event& event);
    // What the player holds right now, as game actions: keys by their position (WASD stays under
    // the left hand on any layout), and every connected gamepad.
    Actions actions(const platform::Window& window) const { return bindings_.actions(window); }
    void setBindings(const Bindings& bindings) { bindings_ = bindings; }
    const Bindings& bindings() const { return bindings_; }
    // Menu commands since the last call.
    Commands takeCommands();
    // Drains the window's events into handle() and returns takeCommands(): what a frame of any
    // windowed loop starts with.
    Commands pollEvents(platform::Window& window);

  private:
    Commands commands_;
    Bindings bindings_ = Bindings::defaults();
};

}  // namespace polar::game
