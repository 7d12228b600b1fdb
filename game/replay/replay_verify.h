#pragma once
// Playing a replay's inputs into a fresh game and saying where it differs from the recording.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "files/assets.h"
#include "polar/error.h"
#include "replay/replay_format.h"
#include "rules/game.h"

namespace polar::game {

// The checkpoint of a game as it is now.
Checkpoint checkpointOf(const Game& game);

// Where a replayed game first differs from its recording, or where the recording disagrees with
// itself. The trace (a token per tick) and the checkpoints (a full state hash and the values it
// covers) both record the game: where the game matches one but not the other, the other's line is
// damaged and the game is not at fault.
struct Desync {
    enum class Kind {
        kGame,        // the game differs from the recording (a changed input, rule or file)
        kTrace,       // trace tokens differ, no two ticks in a row, and the game matches the checkpoint after
                      // them (or, with no checkpoint after them, a later token): the trace line is damaged
        kCheckpoint,  // a checkpoint's value differs, but the game matches every tick's trace token or
                      // the checkpoint's own state hash: the check or objects line is damaged
    };
    Kind kind = Kind::kGame;
    std::uint64_t firstTick =
        0;                // the first tick whose trace token differs (the checkpoint's, for kCheckpoint)
    bool traced = false;  // kGame: the trace placed firstTick; false: it differs somewhere in
                          // firstTick…checkpointTick
    std::uint64_t checkpointTick = 0;  // the checkpoint compared (0: the replay ended before one)
    int checkpointLine = 0;            // that checkpoint's line in the file
    int line = 0, column = 0;          // where the report points: the first differing tick's input (kGame),
                               // its trace token (kTrace), the differing value (kCheckpoint); 0: nowhere
    std::uint64_t expected = 0, actual = 0;            // the checkpoint's state hashes, recorded and now
    std::uint16_t traceExpected = 0, traceActual = 0;  // firstTick's trace token, recorded and now
    std::size_t tokensDiffering = 0;                   // trace tokens that differ from firstTick on
    // kCheckpoint: the value that differs ("state hash", "score", "digest of object 7").
    std::string value;
    std::vector<std::string> differences;  // values and objects that differ, one per line
    // Header lines a difference from the very first tick may come from (kGame at tick 1).
    int seedLine = 0, tickRateLine = 0, tuningLine = 0;
};
// The report of a desync: a first line in file:line:column form that says which kind it is
// ("desync", "damaged trace", "damaged checkpoint"), then indented detail lines with the expected and
// actual values in full.
std::string describe(const Desync& desync, const std::string& path);
// The word of a kind as reports say it: "desync", "damaged trace" or "damaged checkpoint".
const char* kindWord(Desync::Kind kind);

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
    // reason that has nothing to do with the simulation. The world steps on `threads`.
    static Result<ReplayPlayer> start(const Replay& replay, const AssetFs& assets,
                                      const StepThreads& threads = {});

    bool done() const { return game_.tickCount() >= replay_->actions.size(); }
    std::uint64_t totalTicks() const { return replay_->actions.size(); }
    // Plays the next recorded tick. Returns the desync once the state has differed and the next
    // checkpoint (or the end of the replay) is reached, or at a checkpoint line that is damaged.
    std::optional<Desync> step();
    const Game& game() const { return game_; }
    std::size_t checkpointsMatched() const { return matched_; }

    // The player's whole state at a tick: the game's snapshot and where the checks stand (the next
    // checkpoint, the matches so far, the first tick whose trace differed). A keyframe for seeking.
    struct Mark {
        GameSnapshot game;
        std::size_t nextCheckpoint = 0;
        std::size_t matched = 0;
        std::uint64_t lastMatched = 0;
        std::optional<std::uint64_t> firstDiffers;
        std::uint16_t traceActual = 0;
        std::size_t differing = 0, matchedAfter = 0;
        std::uint64_t lastDiffers = 0;
        bool twoInARow = false;
    };
    void mark(Mark& out) const;
    // Goes back (or ahead) to a mark of this replay's player: the game and the checks are as they were
    // at its tick, so stepping on verifies the trace and the later checkpoints as straight play does.
    // An error (and nothing changed) for a damaged mark.
    std::optional<Error> resume(const Mark& mark);

  private:
    ReplayPlayer(const Replay& replay, Game game) : replay_(&replay), game_(std::move(game)) {}

    const Replay* replay_;
    Game game_;
    std::size_t nextCheckpoint_ = 0;
    std::size_t matched_ = 0;
    std::uint64_t lastMatched_ = 0;              // the tick of the last checkpoint that matched
    std::optional<std::uint64_t> firstDiffers_;  // the first tick whose trace token differed
    std::uint16_t traceActual_ = 0;              // the game's token at that tick
    std::size_t differing_ = 0;                  // tokens that differed from then on
    std::size_t matchedAfter_ = 0;               // tokens that matched after it
    std::uint64_t lastDiffers_ = 0;              // the last tick whose token differed
    bool twoInARow_ = false;  // two ticks in a row differed: the game did, as a damaged character changes
                              // one token

    Desync differs(Desync::Kind kind, const Checkpoint* expected, const Checkpoint* actual) const;
};

// What verifying a whole replay found.
struct Verification {
    std::uint64_t ticks = 0;      // played
    std::size_t checkpoints = 0;  // matched
    std::optional<Desync> desync;
};
// Plays a replay to its end or its first desync, without drawing.
Result<Verification> verifyReplay(const Replay& replay, const AssetFs& assets,
                                  const StepThreads& threads = {});

}  // namespace polar::game
