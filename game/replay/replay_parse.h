#pragma once
// Reading replay text back into a Replay, with file:line:column errors.
#include <optional>
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
// Remarks a reader should see: another game version, a last line that was cut off.
std::vector<std::string> replayNotes(const Replay& replay);
// Why a replay without its end line fails verification (nothing when it has one): its recording
// was interrupted, or the file was cut short, so it may hold less than was played. It points where
// the end line is missing. The theatre plays such a replay and says it is incomplete; the verifiers
// fail it unless told to allow incomplete replays (--allow-incomplete).
std::optional<Error> missingEnd(const Replay& replay);

}  // namespace polar::game
