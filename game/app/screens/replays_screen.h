#pragma once
#include <memory>
#include <string>
#include <vector>

#include "app/screens/screen.h"

namespace polar::game {

// The replays the game kept in the data folder's replays/, newest first; the chosen one plays in
// the replay screen.
std::unique_ptr<Screen> makeReplaysScreen();

// The .replay files in `folder`, newest first (their names are their start's date and time).
std::vector<std::string> listReplays(const std::string& folder);

}  // namespace polar::game
