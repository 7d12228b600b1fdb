#pragma once
#include <array>
#include <cstdint>
#include <string>

#include "polar/effects.h"

namespace polar {

// What one effect did during a step.
struct EffectStats {
    std::uint64_t calls = 0;        // passes it made over objects or pairs
    std::uint64_t objects = 0;      // objects it visited
    std::uint64_t pairs = 0;        // pairs it tested (narrow phase) or responded to
    std::uint64_t nanoseconds = 0;  // time spent, only with timing on; the simulation never reads it
    std::uint64_t bytes = 0;        // memory it holds after the step (capacities of its buffers)

    bool idle() const { return calls == 0 && objects == 0 && pairs == 0 && nanoseconds == 0 && bytes == 0; }
    EffectStats& operator+=(const EffectStats& other);
};

// What a World did during a step, per effect, filled by World::step.
//
// Why counters as well as times? Times vary from run to run and machine to machine; counts do not,
// so tests can assert on them ("an absent effect makes no pass and visits no object") while the
// times answer "where does my frame go?" for a game's stats display or a benchmark.
struct StepStats {
    std::array<EffectStats, kEffectCount> effects{};
    std::uint64_t candidates = 0;             // objects that took part in detection
    std::uint64_t pairsTested = 0;            // narrow-phase tests, every effect together
    std::uint64_t hits = 0;                   // hits reported
    std::uint64_t broadPhaseNanoseconds = 0;  // part of collisions' time: per-step data and broad phase

    EffectStats& operator[](Effect effect) { return effects[effectIndex(effect)]; }
    const EffectStats& operator[](Effect effect) const { return effects[effectIndex(effect)]; }
    StepStats& operator+=(const StepStats& other);
};

// A table of per-effect averages over `steps` steps of `total` (World::totalStats()), one line per
// effect: calls, objects and pairs per step, milliseconds per step (when timing was on), memory held.
std::string formatStepStats(const StepStats& total, std::uint64_t steps);

}  // namespace polar
