#pragma once
// Writing a replay file while the game runs, so that a crash or a full disk loses little.
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "polar/error.h"
#include "replay/replay_format.h"
#include "rules/actions.h"
#include "rules/game.h"

namespace polar::game {

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
    // Where the lines go until the game ends: `path + ".part"`.
    static std::string partPathOf(const std::string& path) { return path + ".part"; }
    // Creates partPathOf(path) and writes the header.
    static Result<std::unique_ptr<ReplayWriter>> open(const std::string& path, const ReplayHeader& header,
                                                      ReplayWriteFault fault = {});
    ~ReplayWriter();
    ReplayWriter(const ReplayWriter&) = delete;
    ReplayWriter& operator=(const ReplayWriter&) = delete;

    // Records the tick the game has just played with `actions`; flushes at every checkpoint.
    std::optional<Error> record(Actions actions, const Game& game);
    // Writes the last checkpoint and the end line, then syncs and renames the file into place.
    // `reason` is one of kEndReasons.
    std::optional<Error> finish(const Game& game, std::string_view reason);

    // Closes and deletes the ".part" file: the recording is given up (a reload changed the game,
    // so no replay could reproduce it) and nothing is left for the next start to trip over.
    void abandon();

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

}  // namespace polar::game
