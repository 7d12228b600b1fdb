#pragma once
// The replay file format: a replay in memory, and its text as ReplayWriter writes it.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "rules/actions.h"
#include "rules/game.h"

namespace polar::game {

// The replay file format this build reads and writes (the number on a replay's first line).
inline constexpr int kReplayFormat = 1;
// A checkpoint (state hash, counters, per-object digests) is recorded every this many ticks, and
// after the last tick.
inline constexpr std::uint64_t kCheckpointInterval = 60;
// Longer replays are refused (46 hours at 60 Hz), so a corrupt count cannot exhaust memory.
inline constexpr std::uint64_t kMaxReplayTicks = 10'000'000;

// The game's version, as replays record it ("0.1.0").
const char* gameVersion();

// A file the game read when it started (the scene, every bounds file), by name and FNV-1a hash of
// its bytes: a replay only reproduces its game with the very same files.
struct AssetStamp {
    std::string name;  // a logical asset path, or a file path relative to the replay's folder
    std::uint64_t hash = 0;
    int line = 0;  // where the replay file names it (0 when made in memory)
};

// A golden picture of the frame after `tick` (drawn by the game's own drawGame at alpha 1).
struct ReplayScreenshot {
    std::uint64_t tick = 0;
    std::string png;  // as written in the replay: relative to the replay's folder
    int line = 0;
};

// One object's state at a checkpoint, folded to 16 bits: enough to say which objects differ.
struct ObjectDigest {
    ObjectId id = 0;
    std::uint16_t digest = 0;
    bool operator==(const ObjectDigest&) const = default;
};

// The recorded state after a tick: the full game hash plus what a desync report can name.
struct Checkpoint {
    std::uint64_t tick = 0;
    std::uint64_t hash = 0;  // Game::hash()
    std::uint64_t rng = 0;   // the game Rng's state
    int score = 0;
    int lives = 0;
    int wave = 0;
    std::vector<ObjectDigest> objects;  // in creation order
    // Where it is written (all 0 when made in memory): the check line and the columns of its values,
    // the objects line and the column of each digest, so a damaged value is pointed at.
    int line = 0;
    struct Columns {
        int tick = 0, hash = 0, rng = 0, score = 0, lives = 0, wave = 0;
    } columns;
    int objectsLine = 0;
    std::vector<int> objectColumns;  // objectColumns[i] belongs to objects[i]
    bool hasObjects = true;          // false when the file ends before the objects line: not compared
};

// Everything needed to start the recorded game again.
struct ReplayHeader {
    std::string gameVersion = polar::game::gameVersion();
    std::string scene = "scenes/cave.json";  // a logical asset path, or (sceneIsFile) relative to the replay
    bool sceneIsFile = false;
    std::uint64_t seed = 1;
    Tuning tuning;  // tuning.tickRate is the file's "tick-rate"
    // The rules version the game was played under (Game::Config::rules). A file without a "rules"
    // line was recorded before there were versions: rules 1.
    int rules = 1;
    int speed = kMaxGameSpeed;       // the game-speed assist in percent; a file without "speed": 100
    std::vector<std::string> mods;   // the mod folders it was recorded with, for messages
    std::vector<AssetStamp> assets;  // in the order the game read them
    std::vector<ReplayScreenshot> screenshots;
    std::vector<std::string> comments;  // the header's "#" lines, kept when the file is rewritten
    // The lines of the values the game starts from (0 when made in memory or not written).
    int gameLine = 0, sceneLine = 0, seedLine = 0, tickRateLine = 0, tuningLine = 0;
};

// How a recording ends: the reasons an end line may give. A recording that was interrupted before
// it could write one (a crash, a kill, a full disk) has no end line, and fails verification.
inline constexpr const char* kEndReasons[] = {
    "game-over",    // the last life was lost
    "quit",         // the player left the game
    "restart",      // the player started a new game
    "ticks",        // a headless run played its --ticks
    "interrupted",  // a headless run was stopped by a signal, between two ticks
};
// Whether `reason` is one of kEndReasons.
bool isEndReason(std::string_view reason);

// How a recording ended.
struct ReplayEnd {
    std::uint64_t tick = 0;
    std::string reason;  // one of kEndReasons
    int line = 0;
};

// Where the text of a stretch of ticks begins: a run of an "in" line (every tick of the run is
// written at its column) or a trace line's tokens (two characters a tick from its column on).
struct TickPlace {
    std::uint64_t firstTick = 0;
    int line = 0;
    int column = 0;
    int columnsPerTick = 0;  // 0 for a run, 2 for a trace line
};
// The line and column where `tick` is written among `places` (in tick order), or nothing.
std::optional<TickPlace> placeOf(const std::vector<TickPlace>& places, std::uint64_t tick);

// A replay in memory: the header, one Actions byte per tick, a 12-bit hash per tick (the trace,
// which pins down the first tick that differs) and the checkpoints.
struct Replay {
    std::string path;
    ReplayHeader header;
    std::vector<Actions> actions;
    std::vector<std::uint16_t> trace;  // trace[t - 1] belongs to tick t; may be shorter than actions
    std::vector<Checkpoint> checkpoints;
    std::optional<ReplayEnd> end;  // missing when the recording was cut off
    int cutOffLine = 0;            // the incomplete last line that was ignored, if any
    int lines = 0;                 // the complete lines read
    // Where each tick's input and trace token are written (empty when made in memory).
    std::vector<TickPlace> inputPlaces, tracePlaces;
};

// The 12 bits of a state hash that the trace keeps for one tick.
inline std::uint16_t traceOf(std::uint64_t hash) {
    return static_cast<std::uint16_t>(hash >> 52);
}
// The first value where two tunings differ, named as a replay's tuning line names it ("tick-rate",
// "thrust"); "" when they are the same.
std::string firstTuningDifference(const Tuning& a, const Tuning& b);
// The text of a whole replay, exactly as ReplayWriter would have written it.
std::string formatReplay(const Replay& replay);

}  // namespace polar::game
