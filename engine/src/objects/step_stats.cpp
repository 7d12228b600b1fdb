#include "polar/step_stats.h"

#include <cstdio>

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

std::string formatStepStats(const StepStats& total, std::uint64_t steps) {
    double n = steps > 0 ? static_cast<double>(steps) : 1.0;
    std::string text;
    char line[160];
    std::snprintf(line, sizeof line, "%-11s %9s %11s %11s %9s %9s\n", "effect", "calls", "objects", "pairs",
                  "ms", "KiB");
    text += line;
    for (Effect e : kAllEffects) {
        const EffectStats& s = total[e];
        std::snprintf(line, sizeof line, "%-11s %9.2f %11.1f %11.1f %9.3f %9.1f\n", effectName(e),
                      s.calls / n, s.objects / n, s.pairs / n, s.nanoseconds * 1e-6 / n, s.bytes / 1024.0);
        text += line;
    }
    std::snprintf(
        line, sizeof line, "per step: %.1f candidates, %.1f pair tests, %.1f hits; broad phase %.3f ms\n",
        total.candidates / n, total.pairsTested / n, total.hits / n, total.broadPhaseNanoseconds * 1e-6 / n);
    text += line;
    return text;
}

}  // namespace polar
