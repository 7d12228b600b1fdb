// polarcade-bench cores: what a second (third, ...) thread can give on this machine, the floor under
// every threads goal. Three kinds of work, the same amount on each thread, timed at 1 thread and at
// N at once: arithmetic in registers, a streaming read of a large array, and reads at random
// positions of one, with many misses in flight (what a loop over objects in the grid's order, not
// their memory order, does). Throughput gain = N × (1-thread time) / (N-thread time): N on N real
// cores with nothing shared; less where the threads share a core's units or the memory system.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bench.h"
#include "cli.h"
#include "polar/tasks.h"

namespace polar::bench {
namespace {

struct Options {
    std::uint32_t threads = 0;  // 0: every hardware thread, at least 2
    int runs = 7;
    std::string csv;
};

// Keeps each kernel's result alive, so that the compiler cannot drop the work.
volatile double gSink = 0.0;

// Sixteen independent multiply-add chains: the core's arithmetic units, data in registers.
double arithmetic() {
    double a[16];
    for (int i = 0; i < 16; ++i) a[i] = 1.0 + i * 1e-3;
    for (long r = 0; r < 10'000'000; ++r)
        for (double& x : a) x = x * 0.9999999 + 1e-7;
    double sum = 0.0;
    for (double x : a) sum += x;
    return sum;
}

struct Memory {
    std::vector<double> values = std::vector<double>(8u << 20, 1.0);  // 64 MiB, far beyond the caches
    std::vector<std::uint32_t> order;                                 // random positions in it
    Memory() : order(4u << 20) {
        std::uint64_t x = 88172645463325252ull;  // xorshift64: a fixed sequence
        for (std::uint32_t& o : order) {
            x ^= x << 13, x ^= x >> 7, x ^= x << 17;
            o = static_cast<std::uint32_t>(x % values.size());
        }
    }
};

double stream(const Memory& m) {
    double sum = 0.0;
    for (int r = 0; r < 4; ++r)
        for (double v : m.values) sum += v;
    return sum;
}

// Independent loads: the next position never waits for the last value, so misses overlap.
double randomReads(const Memory& m) {
    double sum = 0.0;
    for (int r = 0; r < 2; ++r)
        for (std::uint32_t i : m.order) sum += m.values[i];
    return sum;
}

// The median wall time of `runs` rounds, each with `threads` threads running `work` once at once.
template <class Work>
double timed(std::uint32_t threads, int runs, const Work& work) {
    const Timings t = repeat({0, runs, CpuClock::None}, [&] {
        std::vector<std::thread> pool;
        for (std::uint32_t k = 0; k < threads; ++k) pool.emplace_back([&] { gSink = work(); });
        for (std::thread& thread : pool) thread.join();
    });
    return t.wall().median;
}

struct Kernel {
    const char* name;
    std::function<double()> work;
};

struct Gain {
    double one = 0, all = 0, gain = 0;
};

int run(const Options& options) {
    const std::uint32_t threads = options.threads ? options.threads : std::max(2u, hardwareThreads());
    Memory memory;
    const Kernel kernels[] = {
        {"arithmetic", [] { return arithmetic(); }},
        {"stream 64 MiB", [&] { return stream(memory); }},
        {"random reads 64 MiB", [&] { return randomReads(memory); }},
    };
    Csv csv("kernel,threads,ms_one,ms_all,gain");
    std::printf("The same work on each thread, medians of %d rounds; gain = %u x (1 thread) / (%u at once)\n",
                options.runs, threads, threads);
    std::printf("%-22s %12s %14s %8s\n", "kernel", "1 thread ms", "threads ms", "gain");
    for (const Kernel& kernel : kernels) {
        std::fprintf(stderr, "cores: %s at 1 and %u threads ...\n", kernel.name, threads);
        Gain g;
        g.one = timed(1, options.runs, kernel.work);
        g.all = timed(threads, options.runs, kernel.work);
        g.gain = threads * g.one / g.all;
        std::printf("%-22s %12.1f %14.1f %7.2fx\n", kernel.name, g.one, g.all, g.gain);
        csv.row(kernel.name, threads, Fixed{g.one, 3}, Fixed{g.all, 3}, Fixed{g.gain, 3});
    }
    std::printf("A threads goal above the gain of the work it does is beyond this machine.\n");
    if (!options.csv.empty() && !csv.write(options.csv)) return 1;
    return 0;
}

Registrar registrar{
    {"cores",
     "What more threads give on this machine: arithmetic, streaming and random reads at 1 "
     "thread and at N",
     [](polar::cli::Command& sub) -> std::function<int()> {
         auto options = std::make_shared<Options>();
         sub.option("--threads", options->threads,
                    "Threads at once (default: every hardware thread, at least 2)", {2, 1024});
         sub.option("--runs", options->runs, "Rounds per kernel and thread count", {1, 1000});
         sub.option("--csv", options->csv, "Write kernel,threads,ms_one,ms_all,gain").outputFile();
         return [options] { return run(*options); };
     }}};

}  // namespace
}  // namespace polar::bench
