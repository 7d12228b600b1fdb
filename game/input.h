#pragma once
#include <SDL.h>

#include <map>

#include "actions.h"

namespace polar::game {

class Display;

// Turns keyboard and game-controller events into the per-tick Actions the game records, and into
// menu commands (pause, confirm, …) that never reach the simulation.
//
// Keyboard: arrows or WASD turn and thrust, space fires, Esc or P pauses, Enter confirms.
// Controllers (SDL_GameController, plugged in or out at any time): left stick or d-pad turns,
// stick up, B or right trigger thrusts, A fires, Start pauses.
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

    Input();
    ~Input();
    Input(const Input&) = delete;
    Input& operator=(const Input&) = delete;

    void handle(const SDL_Event& event);
    // What the player holds right now, as game actions.
    Actions actions() const;
    // Menu commands since the last call.
    Commands takeCommands();
    // Drains SDL's event queue (window events go to the display, the rest to handle()) and returns
    // takeCommands(): what a frame of any windowed loop starts with.
    Commands pollEvents(Display& display);
    int controllers() const { return static_cast<int>(pads_.size()); }

  private:
    void openController(int deviceIndex);

    Commands commands_;
    std::map<SDL_JoystickID, SDL_GameController*> pads_;
};

}  // namespace polar::game
