#pragma once
// Repetitions of one piece of work: untimed warm-ups, then timed runs, each on the wall clock and
// a CPU clock.
#include <type_traits>
#include <vector>

#include "clock.h"
#include "samples.h"

namespace polar::bench {

struct Repetitions {
    int warmup = 1;  // untimed calls first (caches, lazy loading, the allocator's first blocks)
    int runs = 11;   // timed calls
    CpuClock cpu = CpuClock::Process;
};

// Every timed run's wall and CPU time, in order.
struct Timings {
    std::vector<double> wallMs, cpuMs;
    Summary wall() const { return summarize(wallMs); }
    Summary cpu() const { return summarize(cpuMs); }
};

// Times one call of `work` and appends it to `t`: for benchmarks that interleave several pieces of
// work call by call, so that all of them see the same machine.
template <class Work>
void timeInto(Timings& t, CpuClock cpu, Work&& work) {
    const Stopwatch watch(cpu);
    work();
    const Lap lap = watch.lap();
    t.wallMs.push_back(lap.wallMs);
    t.cpuMs.push_back(lap.cpuMs);
}

// Calls `work` plan.warmup times untimed, then plan.runs times timed one by one. `work` takes the
// call's index (0, 1, … in each phase) or nothing.
template <class Work>
Timings repeat(const Repetitions& plan, Work&& work) {
    auto call = [&work](int k) {
        if constexpr (std::is_invocable_v<Work&, int>)
            work(k);
        else
            work();
    };
    for (int k = 0; k < plan.warmup; ++k) call(k);
    Timings t;
    t.wallMs.reserve(static_cast<std::size_t>(plan.runs));
    t.cpuMs.reserve(static_cast<std::size_t>(plan.runs));
    for (int k = 0; k < plan.runs; ++k) {
        const Stopwatch watch(plan.cpu);
        call(k);
        const Lap lap = watch.lap();
        t.wallMs.push_back(lap.wallMs);
        t.cpuMs.push_back(lap.cpuMs);
    }
    return t;
}

}  // namespace polar::bench
