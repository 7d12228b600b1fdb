#pragma once
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "app/hud/game_drawing.h"
#include "replay/replay_verify.h"

namespace polar::game {

// Seeking in a replay being watched: keyframes of the player (its game's snapshot and where its
// checks stand) and of the particles, every `interval` ticks from tick 0, kept as play reaches them.
// A seek to tick T restores the latest keyframe at or before T, or steps on from where play is when
// that is nearer, and steps forward to T, checking every tick as straight play does; so the state at
// T is straight play's to the bit, and a desync on the way or later is reported as it would be.
//
// Why every 60 ticks? A seek costs a restore (about 10 µs), up to interval − 1 ticks of stepping
// (about 6 µs each headless) and the frame drawn after it (about 0.4 ms). At 60 the stepping is at
// most 0.35 ms, so a seek with its frame stays well inside 4 ms here and inside it on a device four
// times slower; a 10-minute replay then holds 600 keyframes of a few kilobytes (tools/bench/README.md,
// "seek"). When they outgrow the budget, every other one is dropped and the interval doubles.
class ReplaySeek {
  public:
    static constexpr std::uint64_t kDefaultInterval = 60;
    static constexpr std::size_t kDefaultBudget = std::size_t{8} << 20;

    // `player` at its start (tick 0); `particles` are the ones drawn with it.
    ReplaySeek(ReplayPlayer& player, Particles& particles, double tickSeconds,
               std::uint64_t interval = kDefaultInterval, std::size_t budget = kDefaultBudget);

    // One tick of play: the player's step, the particles', and a keyframe when one is due.
    std::optional<Desync> advance();
    // Goes to `tick` (at most the replay's end). Returns the first desync found on the way.
    std::optional<Desync> seek(std::uint64_t tick);

    std::uint64_t interval() const { return interval_; }
    std::size_t keyframes() const { return frames_.size(); }
    std::size_t heldBytes() const;

    // How the last seek went: the restore's time, the ticks stepped and their time (reported only).
    struct Split {
        bool restored = false;
        double restoreMs = 0;
        std::uint64_t ticks = 0;
        double steppingMs = 0;
    };
    const Split& lastSeek() const { return last_; }

  private:
    struct Keyframe {
        ReplayPlayer::Mark mark;
        Particles particles;
    };
    void keepIfDue();
    void thin();

    ReplayPlayer& player_;
    Particles& particles_;
    double tickSeconds_;
    std::uint64_t interval_;
    std::size_t budget_;
    std::vector<Keyframe> frames_;  // frames_[i] is at tick i · interval_
    Split last_;
};

}  // namespace polar::game
