#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// "Quit?" over the title: Yes leaves the game, No (or back) returns to the title.
std::unique_ptr<Screen> makeQuitConfirmScreen();

}  // namespace polar::game
