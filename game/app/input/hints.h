#pragma once
#include <string>

#include "app/input/bindings.h"
#include "app/input/input.h"

namespace polar::game {

// The words a hint names the player's controls by, on the device in use and as the controls are
// bound: a hint never says "SPACE FIRES" once fire is on F, nor names a key on a phone.
//
// Why one place? Every screen's help line names the same few controls (how to play, confirm,
// back); written here once, a remapped key or another device changes every line alike.

// How to play, for the title: "ARROWS/WASD TURN AND THRUST   SPACE FIRES   P PAUSES   F1 BOUNDS
// F11 FULLSCREEN" on a keyboard with the default keys, the bound keys' names otherwise; the pad's
// buttons; the touch controls.
std::string playHint(const Bindings& bindings, Device device);
// The control that confirms in menus: "ENTER", "A", "TAP".
std::string confirmWord(Device device);
// The control that goes back: "ESC", "B"; empty on a touch screen, which has none (the page's
// pause button pauses a game, a tap chooses).
std::string backWord(Device device);
// The control that pauses a game: the first key bound to pause and Esc ("P OR ESC"), the pad's
// bound button ("START"), the touch controls' pause button ("II").
std::string pauseWord(const Bindings& bindings, Device device);

}  // namespace polar::game
