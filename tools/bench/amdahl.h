#pragma once
// Amdahl's law fitted to a measured speed-up, to say from a machine of few cores what many would
// give: each phase's serial fraction from its time at 1 thread and at N, and the gain that fraction
// allows at 16 and 64 threads.
#include <array>
#include <cstdint>
#include <span>
#include <string>

namespace polar::bench {

// The thread counts every projection is made for.
constexpr std::array<double, 2> kProjectedThreads{16.0, 64.0};

// One phase's fit: speed-up S = t₁ / t_N = 1 / (s + (1 − s)/N), so s = (N/S − 1) / (N − 1).
//
// Why a fit from one N? It is all a small machine measures. It sees what runs on one thread while
// the others wait and what sharing costs at N, not what more threads would add (contention for
// memory, a split into at most N parts, the wake-up of more workers), so it is a ceiling on the
// gain, and a phase whose parallelism is capped at N (two jobs side by side) looks serial-free.
struct AmdahlFit {
    double speedUp = 1.0;
    double serialFraction = 1.0;  // s, within [0, 1]
    bool clamped = false;         // S lay outside [1, N] (noise): s was clamped

    // 1 / (s + (1 − s)/threads).
    double gainAt(double threads) const { return 1.0 / (serialFraction + (1.0 - serialFraction) / threads); }
};

// The fit from a phase's time at 1 thread and at `threads` (> 1); a phase too short to time
// (either time ≤ 0) counts as wholly parallel.
AmdahlFit fitAmdahl(double oneMs, double manyMs, double threads);

// A phase's time at 1 thread and at N.
struct PhaseTime {
    std::string name;
    double oneMs = 0.0;
    double manyMs = 0.0;
};

// The gain at `target` threads of phases that run one after another, each by its own fit:
// Σ t₁ / Σ t₁·(s + (1 − s)/target).
double projectedGain(std::span<const PhaseTime> phases, double threads, double target);

// Prints one table (title, then a row per phase and one for their sum): times at 1 and N threads,
// speed-up, s, the serial part (s·t₁ ms) and the gains at kProjectedThreads.
void printAmdahl(const std::string& title, std::span<const PhaseTime> phases, std::uint32_t threads);

}  // namespace polar::bench
