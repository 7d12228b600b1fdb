#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// The player's game (Session::game, started before this screen opens): the held keys and pads
// become the tick's actions, recorded, with sound. Pause opens the pause menu; at game over the
// game over screen takes its place.
std::unique_ptr<Screen> makePlayingScreen();

}  // namespace polar::game
