#pragma once
// The server's own verdict on a replay: played again with the game's rules, headless, under a cap
// on ticks and CPU time. Its score, wave and length are the facts a board shows; the replay's own
// lines are only claims, each of which must match what the server computed.
#include <cstdint>
#include <map>
#include <string>
#include <string_view>

namespace polar::server {

// What this server runs: the game version and rules versions are this build's; the scenes are
// the asset folder's, each known by the hash of its bytes.
struct ServerGames {
    std::string assetRoot;
    std::map<std::string, std::uint64_t> scenes;  // logical path -> stamp hash of its bytes
    std::uint64_t maxTicks = 216'000;             // an hour at 60 ticks a second
    double cpuSeconds = 5.0;                      // verification CPU time for one run
};

// The scenes of `assetRoot` (its scenes/ folder) with their hashes; the limits at their defaults.
ServerGames serverGames(const std::string& assetRoot);

// The verdict on one replay. `refusal` is empty for a replay that verified; otherwise a word a
// client can act on (unreadable, version, scene, mods, tuning, incomplete, too-long, unverifiable,
// desync, damaged, cpu-limit) with `reason` saying why in a sentence.
struct Verdict {
    std::string refusal;
    std::string reason;
    // The server's own results (valid when the refusal is empty).
    int score = 0;
    int wave = 0;
    std::uint64_t ticks = 0;
    double tickRate = 60.0;
    std::string scene;
    std::string mode;
    int rules = 0;
    int speed = 0;
    std::uint64_t seed = 0;
    std::string runHash;  // the run itself: scene bytes, seed, rules, speed and every tick's input
};

// Plays `replayText` as the game would and checks every recorded trace token and checkpoint.
// Safe on several threads at once.
Verdict verifyRun(std::string_view replayText, const ServerGames& games);

// The mode of a board: the rules version, and the speed assist when it is on ("rules-2",
// "rules-2-speed-75"), so runs are only ranked against runs played by the same rules.
std::string boardMode(int rules, int speed);
// The mode of this build's newest rules at full speed: the board a query names by default.
std::string defaultMode();

}  // namespace polar::server
