#pragma once
#include <memory>
#include <string>

#include "app/screens/screen.h"

namespace polar::game {

// The replay theatre: reads the replay at `path` ahead once (its keyframes and markers), then plays
// it at its own tick rate, checked against the recording, with a seek bar that scrubs while dragged
// and marks the moments worth seeing, and transport by keys, pad and mouse (the help line lists
// them; H hides the bar for a clean view). With `standalone` (polarcade --replay FILE) it is the
// only screen: back leaves the game with the replay's exit code (1 after a desync or a damaged
// line under --verify, which also stops there, or for a replay without its end line unless
// --allow-incomplete), and --seek's tick is where watching starts. A replay without its end line (an
// interrupted recording) plays as far as it goes, with INCOMPLETE in the bar and at its end. Nothing (with
// the error told on screen and stderr) when the replay cannot be read or started.
std::unique_ptr<Screen> makeTheatreScreen(Session& session, const std::string& path, bool standalone);

}  // namespace polar::game
