#pragma once
#include <cstdint>
#include <optional>
#include <vector>

#include "files/high_scores.h"
#include "replay/replay_format.h"
#include "rules/game.h"

namespace polar::game {

// A moment worth jumping to in a replay, marked on the theatre's seek bar.
struct ReplayMarker {
    enum class Kind : std::uint8_t { LifeLost, WaveCleared, CometShot, HighScore };
    std::uint64_t tick = 0;  // the tick it happened in (the state after that tick shows it)
    Kind kind = Kind::LifeLost;
    int value = 0;  // the wave cleared, or the score that passed the high score; 0 otherwise
};

// The markers of a replay, found as its ticks are played: from the game's events of each tick
// (ShipHit, CometShot, the RockDestroyed that leaves no rock) and the score passing `toBeat`, the best
// score of the replay's table when it was opened. Each tick is looked at once, however often a seek
// plays it again, so the list stays in tick order with no repeats.
class ReplayMarkers {
  public:
    // `toBeat` 0 puts the high-score marker on the first point scored.
    explicit ReplayMarkers(int toBeat) : toBeat_(toBeat) {}

    // Looks at `game` just after its tick; ticks at or before the last one looked at are skipped.
    void observe(const Game& game);

    const std::vector<ReplayMarker>& all() const { return markers_; }
    // The first marker after `tick`, or the last one before it.
    std::optional<ReplayMarker> next(std::uint64_t tick) const;
    std::optional<ReplayMarker> previous(std::uint64_t tick) const;
    // The ticks looked at so far (the highest tick observed).
    std::uint64_t seen() const { return seen_; }

  private:
    int toBeat_;
    bool beaten_ = false;
    std::uint64_t seen_ = 0;
    std::vector<ReplayMarker> markers_;
};

// The score a replay's high-score marker measures against: the best of the replay's table (its
// scene and mods) in `scores`, or the best but one when the best is this very game's final score,
// so the replay that set the record marks where it passed the record before it.
int scoreToBeat(const HighScores& scores, const Replay& replay);

// A marker's word on screen ("LIFE LOST", "WAVE 3 CLEARED", "COMET SHOT", "HIGH SCORE").
std::string describe(const ReplayMarker& marker);

}  // namespace polar::game
