#pragma once
#include <memory>

#include "app/screens/screen.h"

namespace polar::game {

// The first screen, over the attract demo: Play, Scenes, Replays, High scores, Quit (no Quit in a
// browser, where the page is closed instead). Back asks "Quit?" first.
std::unique_ptr<Screen> makeTitleScreen();

}  // namespace polar::game
