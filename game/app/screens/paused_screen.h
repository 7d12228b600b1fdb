#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// The pause menu over the stopped game: Resume, Restart, Quit to title. Pause or back resumes.
std::unique_ptr<Screen> makePausedScreen();

}  // namespace polar::game
