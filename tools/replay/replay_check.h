#pragma once
#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "rules/game.h"

namespace polar::game {

// What polarcade-replay does with one replay file.
struct CheckOptions {
    std::string assetRoot;  // the asset folder (AssetFs::findRoot)
    std::vector<std::string> mods;
    std::string failureDir =
        "replay-failures";           // NAME-TICK.actual.png and .diff.png of differing screenshots
    bool updateScreenshots = false;  // verify, then rewrite the screenshot PNGs from this build
    bool update = false;             // re-record checkpoints, trace, file stamps and screenshots
    bool allowIncomplete = false;    // a replay without its end line passes when what it holds does
    std::atomic<std::uint64_t>* ticksDone = nullptr;  // progress, added to as ticks are played
    StepThreads threads;  // what each replay's world steps on (results do not depend on it)
};

// The outcome for one replay file.
struct CheckResult {
    // kDamaged: a trace token or checkpoint value disagrees with a game that matches the rest of the
    // recording (the line is damaged, not the game); kIncomplete: everything recorded matched, but
    // the end line is missing (the recording was interrupted or the file cut short).
    enum Status { kPassed, kUpdated, kDesynced, kDamaged, kScreenshotDiffers, kIncomplete, kUnplayable };
    Status status = kUnplayable;
    std::string path;
    std::uint64_t ticks = 0;            // played
    std::size_t checkpoints = 0;        // matched
    std::size_t screenshots = 0;        // matched (or written)
    std::uint64_t desyncTick = 0;       // the first tick that differs (desynced or damaged)
    std::string report;                 // what went wrong, several lines (empty when passed)
    std::vector<std::string> notes;     // remarks that do not fail it
    std::vector<std::string> pictures;  // the actual and diff PNGs written for differing screenshots
    double seconds = 0;                 // wall-clock time spent verifying it
};

// The ticks a replay file holds (0 when it cannot be read), for sizing progress.
std::uint64_t replayTicks(const std::string& path);

// Verifies one replay: every tick against its trace, every checkpoint, and every screenshot line
// (drawn headless with the game's own drawGame at alpha 1, compared pixel for pixel). Safe to run
// on several threads at once: nothing is shared between calls.
CheckResult checkReplayFile(const std::string& path, const CheckOptions& options);

}  // namespace polar::game
