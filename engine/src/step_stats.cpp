#include "polar/step_stats.h"

namespace polar {

EffectStats& EffectStats::operator+=(const EffectStats& other) {
    calls += other.calls;
    objects += other.objects;
    pairs += other.pairs;
    nanoseconds += other.nanoseconds;
    bytes = other.bytes;  // held memory is a level, not a flow: keep the latest
    return *this;
}

StepStats& StepStats::operator+=(const StepStats& other) {
    for (std::size_t i = 0; i < effects.size(); ++i) effects[i] += other.effects[i];
    candidates += other.candidates;
    pairsTested += other.pairsTested;
    hits += other.hits;
    broadPhaseNanoseconds += other.broadPhaseNanoseconds;
    return *this;
}

}  // namespace polar
