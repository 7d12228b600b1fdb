#pragma once
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/screens/screen.h"
#include "polar/error.h"

namespace polar::game {

// The replay list: the replays in `folder` (by default the data folder's replays/), newest first,
// each with its date, scene, mods, score, wave and length, and whether it plays here (and why not).
// The chosen one plays in the replay theatre; one can be deleted (after a question) or exported.
// With `standalone` (polarcade --replay DIR) it is the first screen, and back leaves the game.
std::unique_ptr<Screen> makeReplayListScreen(std::string folder = {}, bool standalone = false);

// The .replay files in `folder`, newest first: those a recorder named by their start's date and
// time ("2026-01-02_12-00-00.replay") by that name, then any other by its file's time.
std::vector<std::string> listReplays(const std::string& folder);

// Hands a copy of the replay at `path` to the player as polarcade-NAME.replay (platform::offerFile:
// into the downloads folder, or a browser download); where it went, or the Error.
Result<std::string> exportReplay(const std::string& path);

}  // namespace polar::game
