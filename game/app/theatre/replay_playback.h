#pragma once
#include <memory>
#include <optional>
#include <string>

#include "app/hud/game_drawing.h"
#include "app/theatre/replay_markers.h"
#include "app/theatre/replay_seek.h"
#include "files/assets.h"
#include "polar/render/canvas.h"
#include "replay/replay.h"

namespace polar::game {

// A replay being played back: the file, its player and the pictures' state. Every tick is checked
// against the recording; the first desync is reported on stderr and kept.
class Playback {
  public:
    // Reads and starts the replay at `path` (its notes go to stderr); the error (file:line:column)
    // when it cannot be read or started. The replay's world steps on `tasks`; its high-score marker
    // measures the game against `scores` (scoreToBeat), or marks the first points without them.
    static Result<std::unique_ptr<Playback>> open(const std::string& path, const AssetFs& assets,
                                                  TaskSystem& tasks, const HighScores* scores = nullptr);

    // Plays one tick (its markers noted the first time it is played); false when `stopAtDesync` and
    // this tick found the first desync.
    bool tick(bool stopAtDesync);
    // Goes to `tick` by the keyframes (ReplaySeek): the state is straight play's there; false as
    // tick() is.
    bool seekTo(std::uint64_t tick, bool stopAtDesync);
    // Draws the game as it stands, `alpha` of the way through the tick.
    void draw(render::Canvas& canvas, SpriteCache& sprites, TaskSystem& tasks, double alpha,
              bool debugOverlay) const;
    // Draws the game as the verifier draws its screenshots: at the tick itself, no overlay.
    void drawStill(render::Canvas& canvas, SpriteCache& sprites, TaskSystem& tasks) const;
    // Prints the summary; the exit code: under --verify 1 after a desync or a damaged line, and for a
    // replay without its end line unless `allowIncomplete` (then it is a note, as it is unverified);
    // else 0.
    int finish(bool verify, bool allowIncomplete) const;
    // The replay has no end line: its recording was interrupted, so it may hold less than was played.
    bool incomplete() const { return !replay_->end; }

    const Replay& replay() const { return *replay_; }
    const ReplayPlayer& player() const { return *player_; }
    const std::optional<Desync>& desync() const { return desync_; }
    const ReplayMarkers& markers() const { return markers_; }
    const ReplaySeek::Split& lastSeek() const { return seek_->lastSeek(); }
    std::uint64_t tickNow() const { return player_->game().tickCount(); }

  private:
    Playback() = default;
    std::unique_ptr<Replay> replay_;  // on the heap: the player points at it
    std::optional<ReplayPlayer> player_;
    Interpolation interpolation_;
    Particles particles_;
    std::optional<ReplaySeek> seek_;  // keyframes of player_ and particles_
    std::optional<Desync> desync_;
    ReplayMarkers markers_{0};

    bool report(const std::optional<Desync>& found, bool stopAtDesync);
};

}  // namespace polar::game
