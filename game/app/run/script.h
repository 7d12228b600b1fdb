#pragma once
#include <string>
#include <vector>

#include "polar/error.h"
#include "polar/platform/events.h"

namespace polar::game {

// One line of a game script (polarcade --script FILE).
struct ScriptStep {
    enum class Kind {
        Events,      // one frame with these events
        Wait,        // `frames` frames with no event
        Screenshot,  // save the last frame drawn to `text`
        Expect,      // the screen on top must be `text`
        ExpectTick,  // the game on screen must be at tick `frames`
    };
    Kind kind = Kind::Events;
    std::vector<platform::Event> events;
    int frames = 0;
    std::string text;
    int line = 0;  // where it is in the script, for messages
};

// The steps of a script: what a player would do, written one per line, so a test drives every
// screen through the very events a window delivers. Each event line is one frame of its own (one
// tick: the loop runs at exactly 60 frames a second under a script); '#' starts a comment; X Y
// are canvas pixels:
//   key KEY [KEY…]     press and release each, a frame each (KEY as platform::keyName writes it)
//   down KEY, up KEY   press or release alone (hold "down space" over a "wait" to fire)
//   repeat KEY         a held key's auto-repeat: the press again, marked a repeat, with its letter
//                      typed as a window sends it (a letter or digit key)
//   type TEXT          the letters typed (as a keyboard's text input sends them)
//   move X Y           the pointer moves
//   click X Y          the left button goes down and up at X Y
//   press X Y, release X Y   the left button goes down, or up, alone at X Y (a drag between)
//   wheel DY           DY notches (> 0 away from the player, up a list)
//   pad BUTTON         a gamepad's BUTTON goes down and up: a b x y back start dpad-up dpad-down
//                      dpad-left dpad-right left-shoulder right-shoulder
//   stick X Y          the left stick moves to X Y (each −1 … 1)
//   wait N             N frames pass
//   screenshot FILE    the last frame is saved to FILE (a PNG; relative to the script's folder)
//   expect SCREEN      stop with an error unless SCREEN ("title", "paused", …) is on top
//   expect-tick N      stop with an error unless the game on screen is at tick N
//   quit               the window's close button
// Errors name the script's file, line and column.
Result<std::vector<ScriptStep>> parseScript(const SourceFile& file);

}  // namespace polar::game
