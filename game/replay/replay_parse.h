#pragma once
// Reading replay text back into a Replay, with file:line:column errors.
#include <string>
#include <string_view>
#include <vector>

#include "polar/error.h"
#include "replay/replay_format.h"

namespace polar::game {

// Parses replay text; `path` names the file in messages and anchors relative paths.
Result<Replay> parseReplay(const std::string& path, std::string_view text);
// Reads and parses a replay file.
Result<Replay> readReplay(const std::string& path);
// Remarks a reader should see: another game version, a recording that was cut off.
std::vector<std::string> replayNotes(const Replay& replay);

}  // namespace polar::game
