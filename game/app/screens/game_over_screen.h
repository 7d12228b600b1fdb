#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// "GAME OVER" while the finished game runs on untouched. After 1.5 s confirm, a click or back (or
// after 6 s, by itself) moves on: to the name entry when the score earns a place, else the title.
std::unique_ptr<Screen> makeGameOverScreen();

}  // namespace polar::game
