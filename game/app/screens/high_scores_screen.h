#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// The high-score table over the attract demo; back (or confirm, or a click) returns to the title.
std::unique_ptr<Screen> makeHighScoresScreen();

}  // namespace polar::game
