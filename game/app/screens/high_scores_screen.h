#pragma once
#include <cstddef>
#include <memory>
#include <optional>

#include "app/screens/screen.h"

namespace polar::game {

// The high-score table over the attract demo, headed by the scene (and the mods and game speed)
// it is kept for; back (or confirm, or a click) returns to the screen below, the title. `highlight`:
// the rank of the entry just made, drawn in gold and marked.
std::unique_ptr<Screen> makeHighScoresScreen(std::optional<std::size_t> highlight = std::nullopt);

}  // namespace polar::game
