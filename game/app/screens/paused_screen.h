#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// The pause menu over the stopped game: Resume, Restart, Options, Quit to title. Pause or
// back resumes; Options comes back here. No sound plays while it is on top.
std::unique_ptr<Screen> makePausedScreen();

}  // namespace polar::game
