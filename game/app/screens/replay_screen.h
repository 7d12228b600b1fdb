#pragma once
#include <memory>
#include <string>

#include "app/screens/screen.h"

namespace polar::game {

// Plays the replay at `path` at its own tick rate, checked against the recording: P pauses, →
// steps while paused, ↑/↓ change the speed, F1 shows the bounds, Esc goes back. With `standalone`
// (polarcade --replay FILE) it is the only screen: back leaves the game with the replay's exit
// code (1 after a desync under --verify, which also stops there). Nothing (with the error told on
// screen and stderr) when the replay cannot be read or started.
std::unique_ptr<Screen> makeReplayScreen(Session& session, const std::string& path, bool standalone);

}  // namespace polar::game
