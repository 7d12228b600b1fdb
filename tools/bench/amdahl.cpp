#include "amdahl.h"

#include <algorithm>
#include <cstdio>

namespace polar::bench {

AmdahlFit fitAmdahl(double oneMs, double manyMs, double threads) {
    AmdahlFit fit;
    if (!(oneMs > 0.0) || !(manyMs > 0.0) || !(threads > 1.0)) {
        fit.serialFraction = 0.0;
        return fit;
    }
    fit.speedUp = oneMs / manyMs;
    const double s = (threads / fit.speedUp - 1.0) / (threads - 1.0);
    fit.serialFraction = std::clamp(s, 0.0, 1.0);
    fit.clamped = fit.serialFraction != s;
    return fit;
}

double projectedGain(std::span<const PhaseTime> phases, double threads, double target) {
    double one = 0.0, projected = 0.0;
    for (const PhaseTime& p : phases) {
        const AmdahlFit fit = fitAmdahl(p.oneMs, p.manyMs, threads);
        one += p.oneMs;
        projected += p.oneMs / fit.gainAt(target);
    }
    return projected > 0.0 ? one / projected : 1.0;
}

void printAmdahl(const std::string& title, std::span<const PhaseTime> phases, std::uint32_t threads) {
    const double n = threads;
    std::printf("%s\n", title.c_str());
    char many[32];
    std::snprintf(many, sizeof many, "%u thr ms", threads);
    std::printf("%-14s %10s %10s %9s %7s %10s %8s %8s\n", "phase", "1 thr ms", many, "speed-up", "s",
                "serial ms", "gain 16", "gain 64");
    PhaseTime sum{"sum", 0.0, 0.0};
    auto row = [&](const PhaseTime& p, double gain16, double gain64, bool clamped, double s) {
        std::printf("%-14s %10.3f %10.3f %8.2f× %6.3f%s %10.3f %7.2f× %7.2f×\n", p.name.c_str(), p.oneMs,
                    p.manyMs, p.manyMs > 0.0 ? p.oneMs / p.manyMs : 0.0, s, clamped ? "*" : " ", s * p.oneMs,
                    gain16, gain64);
    };
    for (const PhaseTime& p : phases) {
        const AmdahlFit fit = fitAmdahl(p.oneMs, p.manyMs, n);
        row(p, fit.gainAt(kProjectedThreads[0]), fit.gainAt(kProjectedThreads[1]), fit.clamped,
            fit.serialFraction);
        sum.oneMs += p.oneMs;
        sum.manyMs += p.manyMs;
    }
    // The sum's s is the serial parts' share of its time; its gains are the phases' composed.
    double serial = 0.0;
    for (const PhaseTime& p : phases) serial += fitAmdahl(p.oneMs, p.manyMs, n).serialFraction * p.oneMs;
    row(sum, projectedGain(phases, n, kProjectedThreads[0]), projectedGain(phases, n, kProjectedThreads[1]),
        false, sum.oneMs > 0.0 ? serial / sum.oneMs : 0.0);
}

}  // namespace polar::bench
