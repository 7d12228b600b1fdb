#pragma once
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "actions.h"
#include "assets.h"
#include "game.h"
#include "polar/error.h"

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
    int line = 0;
};

// Everything needed to start the recorded game again.
struct ReplayHeader {
    std::string gameVersion = polar::game::gameVersion();
    std::string scene = "scenes/cave.json";  // a logical asset path, or (sceneIsFile) relative to the replay
    bool sceneIsFile = false;
    std::uint64_t seed = 1;
    Tuning tuning;                   // tuning.tickRate is the file's "tick-rate"
    std::vector<std::string> mods;   // the mod folders it was recorded with, for messages
    std::vector<AssetStamp> assets;  // in the order the game read them
    std::vector<ReplayScreenshot> screenshots;
    std::vector<std::string> comments;  // the header's "#" lines, kept when the file is rewritten
    int sceneLine = 0;
};

// How a recording ended.
struct ReplayEnd {
    std::uint64_t tick = 0;
    std::string reason;  // "game-over", "quit" or "ticks"
    int line = 0;
};

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
};

// Parses replay text; `path` names the file in messages and anchors relative paths.
Result<Replay> parseReplay(const std::string& path, std::string_view text);
// Reads and parses a replay file.
Result<Replay> readReplay(const std::string& path);
// The text of a whole replay, exactly as ReplayWriter would have written it.
std::string formatReplay(const Replay& replay);

// The 12 bits of a state hash that the trace keeps for one tick.
inline std::uint16_t traceOf(std::uint64_t hash) {
    return static_cast<std::uint16_t>(hash >> 52);
}
// The checkpoint of a game as it is now.
Checkpoint checkpointOf(const Game& game);
// Creates a game as Game::create does and stamps every file it reads. Absolute paths are named as
// logical paths when they lie in `assets` (its mods or its root), otherwise relative to `anchor`'s
// folder (the replay file).
Result<Game> createStampedGame(const Game::Config& config, const AssetFs* assets, const std::string& anchor,
                               std::vector<AssetStamp>& stamps);
// The header for recording `game` (just created, with those stamps) into the file `replayPath`.
ReplayHeader headerFor(const Game& game, const std::string& replayPath, std::vector<std::string> mods,
                       std::vector<AssetStamp> stamps);
// The game config a replay starts from: its scene (resolved against the replay's folder), seed and
// tuning, read through `assets`.
Game::Config configFor(const Replay& replay, const AssetFs& assets);
// Remarks a reader should see: another game version, a recording that was cut off.
std::vector<std::string> replayNotes(const Replay& replay);

// The steps of writing a replay; a test can make any of them fail as a full disk would.
enum class ReplayWriteStep { kOpen, kFlush, kFinish };
using ReplayWriteFault = std::function<bool(ReplayWriteStep)>;

// Writes a replay while the game runs.
//
// Why a ".part" file? The recording grows for minutes and must survive a crash, so it cannot be
// written in one piece at the end; but an existing replay of the same name must not be lost to a
// half-written one either. So the lines go to `path + ".part"`, flushed to the operating system
// after every checkpoint (every second of play): a crash keeps all but the last second there, and
// a reader takes it up to its last complete line. When the game ends the file is synced and renamed
// over `path` in one step.
class ReplayWriter {
  public:
    // Creates `path + ".part"` and writes the header.
    static Result<std::unique_ptr<ReplayWriter>> open(const std::string& path, const ReplayHeader& header,
                                                      ReplayWriteFault fault = {});
    ~ReplayWriter();
    ReplayWriter(const ReplayWriter&) = delete;
    ReplayWriter& operator=(const ReplayWriter&) = delete;

    // Records the tick the game has just played with `actions`; flushes at every checkpoint.
    std::optional<Error> record(Actions actions, const Game& game);
    // Writes the last checkpoint and the end line, then syncs and renames the file into place.
    std::optional<Error> finish(const Game& game, std::string_view reason);

    const std::string& path() const { return path_; }
    const std::string& partPath() const { return partPath_; }

  private:
    ReplayWriter(std::string path, std::FILE* file, ReplayWriteFault fault);
    std::optional<Error> flush(std::string text);

    std::string path_, partPath_;
    std::FILE* file_ = nullptr;
    ReplayWriteFault fault_;
    std::vector<Actions> actions_;  // since the last checkpoint
    std::vector<std::uint16_t> trace_;
    std::uint64_t lastCheckpoint_ = 0;
    bool finished_ = false;
};

// Records the games a player plays: every game into the data folder's replays/ (the newest `keep`
// kept), and the first game into --record FILE too. A failure to write is reported once and stops
// that recording; the game goes on.
class GameRecorder {
  public:
    struct Options {
        std::string recordPath;  // --record FILE; empty for none
        std::string folder;      // where every game is kept; empty for none
        std::size_t keep = 20;
        std::vector<std::string> mods;
        ReplayWriteFault fault;  // for tests
    };
    explicit GameRecorder(Options options);
    ~GameRecorder();

    // Starts recording a game that has just been created (reading its files again to stamp them).
    void start(const Game& game, const AssetFs& assets);
    // Records the tick just played; at game over the recordings end by themselves.
    void record(Actions actions, const Game& game);
    // Ends the recordings early (the player quit).
    void finish(const Game& game, std::string_view reason);
    bool recording() const { return !writers_.empty(); }

  private:
    void stop(const Game* game, std::string_view reason);

    Options options_;
    std::vector<std::unique_ptr<ReplayWriter>> writers_;
    bool recordPathUsed_ = false;
};

// A new replay file name in `folder` from the local date and time ("2024-05-01_18-04-09.replay").
std::string newReplayPath(const std::string& folder);
// Deletes the oldest replays in `folder` (by name) until `keep` are left; returns how many went.
std::size_t pruneReplays(const std::string& folder, std::size_t keep);
// Renames recordings a crash left as ".part" (untouched for over 10 s) to ".replay" so they can be
// played; returns their new paths.
std::vector<std::string> recoverInterruptedReplays(const std::string& folder);

// Where a replayed game first differs from its recording.
struct Desync {
    std::uint64_t firstTick = 0;  // the first tick whose state hash differs (from the trace)
    bool traced = false;          // false: no trace there; it differs somewhere in firstTick…checkpointTick
    bool traceAgrees = false;     // the trace matched every tick: only the checkpoint line disagrees
    std::uint64_t checkpointTick = 0;  // the checkpoint compared (0: the replay ended before one)
    int line = 0;                      // that checkpoint's line in the file
    std::uint64_t expected = 0, actual = 0;
    std::vector<std::string> differences;  // counters and objects that differ, one per line
};
// The report of a desync: a first line in file:line:column form, then indented detail lines.
std::string describe(const Desync& desync, const std::string& path);

// Plays a replay's recorded inputs into a fresh game and checks each tick against the trace and
// each checkpoint against the recording.
//
// Why one tick at a time? Its users differ in what they do between ticks: the window draws a frame,
// polarcade-replay compares screenshots, the benchmark draws or does not. The player owns only the
// checks, which are the same for all of them.
class ReplayPlayer {
  public:
    // Starts the replay's game through `assets`. An Error (file:line:column) when the scene is
    // missing or a file the game read differs from the one recorded: that would desync for a
    // reason that has nothing to do with the simulation.
    static Result<ReplayPlayer> start(const Replay& replay, const AssetFs& assets);

    bool done() const { return game_.tickCount() >= replay_->actions.size(); }
    std::uint64_t totalTicks() const { return replay_->actions.size(); }
    // Plays the next recorded tick. Returns the desync once the state has differed and the next
    // checkpoint (or the end of the replay) is reached.
    std::optional<Desync> step();
    const Game& game() const { return game_; }
    std::size_t checkpointsMatched() const { return matched_; }

  private:
    ReplayPlayer(const Replay& replay, Game game) : replay_(&replay), game_(std::move(game)) {}

    const Replay* replay_;
    Game game_;
    std::size_t nextCheckpoint_ = 0;
    std::size_t matched_ = 0;
    std::uint64_t lastMatched_ = 0;  // the tick of the last checkpoint that matched
    std::optional<std::uint64_t> firstDiffers_;
};

// What verifying a whole replay found.
struct Verification {
    std::uint64_t ticks = 0;      // played
    std::size_t checkpoints = 0;  // matched
    std::optional<Desync> desync;
};
// Plays a replay to its end or its first desync, without drawing.
Result<Verification> verifyReplay(const Replay& replay, const AssetFs& assets);

}  // namespace polar::game
