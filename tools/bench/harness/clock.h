#pragma once
// Wall-clock and CPU time from one start, in milliseconds. On a shared machine the wall clock also
// counts the time other processes had the cores; the CPU time is the work itself.
#include <time.h>

#include <chrono>

namespace polar::bench {

// Which CPU clock a stopwatch reads beside the wall clock.
enum class CpuClock {
    Process,  // every thread of this process (a pool's idle threads sleep, so they add nothing)
    Thread,   // the calling thread only
    None,     // wall clock only: for calls of microseconds, which a CPU clock's system call would swell
};

// One interval on both clocks.
struct Lap {
    double wallMs = 0;
    double cpuMs = 0;  // 0 with CpuClock::None
};

// The clock's reading in milliseconds, 0 for CpuClock::None.
inline double cpuClockMs(CpuClock clock) {
    if (clock == CpuClock::None) return 0.0;
    timespec t{};
    clock_gettime(clock == CpuClock::Process ? CLOCK_PROCESS_CPUTIME_ID : CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// Started when made. The CPU interval sits inside the wall one, as the work's own does: on one
// thread a wall time is never less than its CPU time. Allocates nothing.
class Stopwatch {
  public:
    explicit Stopwatch(CpuClock cpu = CpuClock::Process) : cpu_(cpu) { restart(); }

    void restart() {
        wallStart_ = std::chrono::steady_clock::now();
        cpuStart_ = cpuClockMs(cpu_);
    }
    // Both clocks since the start.
    Lap lap() const {
        const double cpu = cpuClockMs(cpu_) - cpuStart_;
        return {wallMs(), cpu};
    }
    // The wall clock alone since the start.
    double wallMs() const {
        return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - wallStart_)
            .count();
    }

  private:
    CpuClock cpu_;
    double cpuStart_ = 0;
    std::chrono::steady_clock::time_point wallStart_{};
};

}  // namespace polar::bench
