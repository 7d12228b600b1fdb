#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// The scenes of assets/scenes/ and of every mod (with the mod's name); the chosen one becomes the
// scene of every game from now on and starts at once.
std::unique_ptr<Screen> makeScenesScreen();

}  // namespace polar::game
