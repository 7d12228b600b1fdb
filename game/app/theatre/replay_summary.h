#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "files/assets.h"

namespace polar::game {

// What the replay list shows of one replay: when, where, how it went, and whether this game can
// play it.
struct ReplaySummary {
    enum class Playable : std::uint8_t { Yes, Caution, No };
    std::string path;
    std::string when;               // "2026-01-02 12:00", from the file's name, else its modification time
    std::string scene;              // the scene's name ("CAVE"), or the scene file's
    std::vector<std::string> mods;  // the mods it was recorded with, by folder name
    int score = 0, wave = 0;        // at its last checkpoint
    std::uint64_t ticks = 0;
    double tickRate = 60;
    Playable playable = Playable::No;
    std::string reason;  // why it is not (or may not be) playable here, in a few words
    std::string detail;  // the whole message (file:line:column)
};

// The start time a recorder's file name holds ("2026-01-02_12-00-00.replay", or "…_02.replay" for
// a second game in that second) as "2026-01-02 12:00"; nothing for any other name.
std::optional<std::string> recorderTimeOf(const std::string& path);

// Reads the replay at `path` and checks it can start here, with the files `assets` has: the same
// scene and bounds files (hashes), the mods it names among this run's, the same game version
// (a different one may play, with a caution). Never fails: an unreadable replay is summarised as
// not playable, with its error.
ReplaySummary summariseReplay(const std::string& path, const AssetFs& assets);

}  // namespace polar::game
