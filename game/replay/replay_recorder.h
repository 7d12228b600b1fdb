#pragma once
// Recording the games a player plays, and keeping the data folder's replays in order.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "files/assets.h"
#include "replay/replay_writer.h"
#include "rules/actions.h"
#include "rules/game.h"

namespace polar::game {

// Records the games a player plays: every game into the data folder's replays/ (the newest `keep`
// kept), and the first game into --record FILE too. A failure to write is reported once and stops
// that recording; the game goes on. A game that hot reload modified is not kept at all (abandon).
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
    // Gives the recordings up and deletes their ".part" files: hot reload changed the game, so no
    // replay could reproduce it. The game goes on unrecorded; the next start() records again.
    void abandon();
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

}  // namespace polar::game
