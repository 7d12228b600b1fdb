// polarcade-bench scale: step time, pairs tested, hits and peak memory of rock fields of growing
// size, for the all-pairs reference and the broad phases; a table, CSV and a log-log plot.
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "bench.h"
#include "cli.h"
#include "polar/atomic_file.h"
#include "polar/authoring/random_scene.h"
#include "polar/world.h"
#ifdef POLAR_BENCH_PLOTS
#include "log_plot.h"
#endif

namespace polar::bench {
namespace {

constexpr double kStep = 1.0 / 60.0;
constexpr std::uint64_t kSeed = 0x5CA1E;
// Steps before measuring: the random placement's first overlaps have been pushed apart by then.
constexpr int kWarmup = 30;
constexpr std::size_t kCountedSteps = 3;

// What one run (one size, one method) measured: medians over the measured steps.
struct RunResult {
    bool ok = false;
    double msPerStep = 0;     // the whole step: physics + collisions + response (wall clock)
    double cpuMsPerStep = 0;  // the same step in this thread's CPU time: what the step cost, without
                              // the time other processes had the core (the machines are shared)
    double msDetection = 0;   // collisions + containers + response: the figure the step-time goal is about
    double msPhysics = 0;
    double msBroadPhase = 0;  // per-step data and broad phase (part of collisions)
    double msCollisions = 0;
    double msResponse = 0;
    double pairsTested = 0;
    double hits = 0;
    double peakMb = 0;      // VmHWM of the process that built and stepped the world
    double neighbours = 0;  // measured: other centres within contact reach, per object
    StepStats measured;     // the World's own counters and times, summed over the measured steps
    int steps = 0;
};
static_assert(std::is_trivially_copyable_v<RunResult>, "a run's result crosses a pipe as bytes");

double median(std::vector<double> v) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    std::size_t m = v.size() / 2;
    return v.size() % 2 ? v[m] : 0.5 * (v[m - 1] + v[m]);
}

// This thread's CPU time in milliseconds.
double threadCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

// Peak resident set size of this process in MiB, from /proc/self/status (VmHWM).
double peakResidentMb() {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line))
        if (line.rfind("VmHWM:", 0) == 0) return std::stod(line.substr(6)) / 1024.0;  // kB
    return 0;
}

// The reach radius of an object with unit scale: max_k |c_k| + maxRadius_k.
double reachOf(const GameObject& o) {
    double reach = 0;
    for (const CollisionRadii& r : o.radii()) reach = std::max(reach, r.centre().norm() + r.maxRadius());
    return reach;
}

// Average number of other centres within R_a + R_b of each object, counted with a bucket grid.
double measureNeighbours(const World& world) {
    const auto& objects = world.objects();
    double maxReach = 0;
    for (const GameObject& o : objects) maxReach = std::max(maxReach, reachOf(o));
    double cell = 2 * maxReach;
    std::vector<std::pair<std::int64_t, std::uint32_t>> keyed;
    auto key = [&](std::int64_t cx, std::int64_t cy) { return cx * 1000003 + cy; };
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        const Vec2& p = objects[i].transform.position();
        keyed.push_back(
            {key(std::int64_t(std::floor(p.x() / cell)), std::int64_t(std::floor(p.y() / cell))), i});
    }
    std::sort(keyed.begin(), keyed.end());
    std::size_t count = 0;
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        const Vec2& p = objects[i].transform.position();
        std::int64_t cx = std::int64_t(std::floor(p.x() / cell)), cy = std::int64_t(std::floor(p.y() / cell));
        for (std::int64_t dy = -1; dy <= 1; ++dy)
            for (std::int64_t dx = -1; dx <= 1; ++dx) {
                auto range =
                    std::equal_range(keyed.begin(), keyed.end(), std::make_pair(key(cx + dx, cy + dy), 0u),
                                     [](auto& a, auto& b) { return a.first < b.first; });
                for (auto it = range.first; it != range.second; ++it) {
                    if (it->second == i) continue;
                    double reach = reachOf(objects[i]) + reachOf(objects[it->second]);
                    if ((objects[it->second].transform.position() - p).squaredNorm() <= reach * reach)
                        ++count;
                }
            }
    }
    return static_cast<double>(count) / static_cast<double>(objects.size());
}

struct Plan {
    std::size_t n;
    BroadPhase method;
    int warmup;
    int steps;
    bool resting;
};

// Builds and steps one world; runs in a child process so that its peak memory is its own.
RunResult measure(const Plan& plan) {
    RunResult r;
    // Every method is measured on the same states: the warm-up runs on the grid (methods give
    // identical results, so the trajectory is the same), then the method under test takes over.
    World world = buildRockField(kSeed, plan.n, 4.0, BroadPhase::Grid);
    r.neighbours = measureNeighbours(world);
    if (plan.resting) {
        // Settle the field with heavy damping, then stop everything: a scene at rest.
        for (GameObject& o : world.objects()) o.damping = 30.0;
        for (int s = 0; s < 40; ++s) world.step(kStep);
        for (GameObject& o : world.objects()) o.velocity = Vec2::Zero(), o.spin = 0.0;
    }
    for (int s = 0; s < plan.warmup; ++s) world.step(kStep);
    world.setBroadPhase(plan.method);
    world.setTiming(true);
    std::vector<double> total, cpu, detection, physics, broad, collisions, response, pairs, hits;
    for (int s = 0; s < plan.steps; ++s) {
        double cpuStart = threadCpuMs();
        auto start = std::chrono::steady_clock::now();
        world.step(kStep);
        auto end = std::chrono::steady_clock::now();
        cpu.push_back(threadCpuMs() - cpuStart);
        const StepStats& stats = world.lastStepStats();
        auto ms = [](std::uint64_t ns) { return static_cast<double>(ns) * 1e-6; };
        total.push_back(std::chrono::duration<double, std::milli>(end - start).count());
        detection.push_back(ms(stats[kEffectCollisions].nanoseconds + stats[kEffectContainers].nanoseconds +
                               stats[kEffectResponse].nanoseconds));
        physics.push_back(ms(stats[kEffectPhysics].nanoseconds));
        broad.push_back(ms(stats.broadPhaseNanoseconds));
        collisions.push_back(ms(stats[kEffectCollisions].nanoseconds));
        response.push_back(ms(stats[kEffectResponse].nanoseconds));
        pairs.push_back(static_cast<double>(stats.pairsTested));
        hits.push_back(static_cast<double>(stats.hits));
        r.measured += stats;
    }
    r.msPerStep = median(total);
    r.cpuMsPerStep = median(cpu);
    r.msDetection = median(detection);
    r.msPhysics = median(physics);
    r.msBroadPhase = median(broad);
    r.msCollisions = median(collisions);
    r.msResponse = median(response);
    // Counts come from the first kCountedSteps measured steps, which every method measures on the same
    // states, so that the columns compare like with like (times use every measured step).
    pairs.resize(std::min<std::size_t>(pairs.size(), kCountedSteps));
    hits.resize(std::min<std::size_t>(hits.size(), kCountedSteps));
    r.pairsTested = median(pairs);
    r.hits = median(hits);
    r.steps = plan.steps;
    r.peakMb = peakResidentMb();
    r.ok = true;
    return r;
}

RunResult measureInChild(const Plan& plan) {
    int fds[2];
    if (pipe(fds) != 0) return {};
    pid_t child = fork();
    if (child < 0) return {};
    if (child == 0) {
        close(fds[0]);
        RunResult r = measure(plan);
        ssize_t written = write(fds[1], &r, sizeof r);
        _exit(written == static_cast<ssize_t>(sizeof r) ? 0 : 1);
    }
    close(fds[1]);
    RunResult r;
    ssize_t got = read(fds[0], &r, sizeof r);
    close(fds[0]);
    int status = 0;
    waitpid(child, &status, 0);
    if (got != static_cast<ssize_t>(sizeof r) || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    return r;
}

struct Options {
    std::string csv;
    std::string plot;
    std::vector<std::size_t> sizes{1000, 10000, 100000};
    std::vector<std::string> methods{"all-pairs", "grid", "sort-and-sweep"};
    std::size_t allPairsMax = 10000;
    int steps = 0;  // 0: chosen by size
    bool resting = false;
};

int run(const Options& options) {
    std::vector<BroadPhase> methods;
    for (const std::string& name : options.methods) {
        auto method = broadPhaseFromName(name);
        if (!method) {
            std::fprintf(
                stderr,
                "polarcade-bench scale: unknown method \"%s\"; expected all-pairs, grid or sort-and-sweep\n",
                name.c_str());
            return cli::kBadInput;
        }
        methods.push_back(*method);
    }
    for (std::size_t n : options.sizes) {
        if (n < 2 || n > 10'000'000) {
            std::fprintf(stderr,
                         "polarcade-bench scale: size %zu is out of range; expected object counts from 2 to "
                         "10000000\n",
                         n);
            return cli::kBadInput;
        }
    }
    struct Row {
        Plan plan;
        RunResult result;
    };
    std::vector<Row> rows;
    for (std::size_t n : options.sizes) {
        for (BroadPhase method : methods) {
            if (method == BroadPhase::AllPairs && n > options.allPairsMax) continue;
            Plan plan{n, method, kWarmup, 0, options.resting};
            if (method == BroadPhase::AllPairs)
                plan.steps = n > 5000 ? 3 : 9;
            else
                plan.steps = n >= 100000 ? 21 : 41;
            if (options.steps > 0) plan.steps = options.steps;
            std::fflush(stdout);
            std::fprintf(stderr, "scale: n = %zu, %s: %d warm-up + %d measured steps ...\n", n,
                         broadPhaseName(method), plan.warmup, plan.steps);
            RunResult result = measureInChild(plan);
            if (!result.ok) {
                std::fprintf(stderr, "polarcade-bench scale: the run for n = %zu, %s failed\n", n,
                             broadPhaseName(method));
                return 1;
            }
            rows.push_back({plan, result});
        }
    }

    std::printf(
        "%s rock field: physics + collisions + response, one thread, dt = 1/60 s; medians over the measured "
        "steps\n",
        options.resting ? "Resting" : "Moving");
    std::printf("%8s %-15s %10s %10s %10s %9s %9s %9s %9s %12s %9s %8s %6s\n", "n", "method", "ms/step",
                "cpu ms", "det+resp", "physics", "broad", "collide", "response", "pairs", "hits", "peak MB",
                "neigh");
    for (const Row& row : rows) {
        const RunResult& r = row.result;
        std::printf("%8zu %-15s %10.3f %10.3f %10.3f %9.3f %9.3f %9.3f %9.3f %12.0f %9.0f %8.1f %6.2f\n",
                    row.plan.n, broadPhaseName(row.plan.method), r.msPerStep, r.cpuMsPerStep, r.msDetection,
                    r.msPhysics, r.msBroadPhase, r.msCollisions, r.msResponse, r.pairsTested, r.hits,
                    r.peakMb, r.neighbours);
    }
    std::printf(
        "ms/step: wall clock; cpu ms: this thread's CPU time for the same steps; det+resp = collisions +\n"
        "containers + response (wall); broad: per-step data and broad phase, part of collide; pairs and\n"
        "hits: medians of the first %zu measured steps (the same states for every method); peak MB: VmHWM\n"
        "of the process that built and stepped the world; neigh: measured other centres within reach.\n",
        kCountedSteps);
    std::printf(
        "\nPer effect, averaged over the measured steps (World::totalStats, as polarcade --stats shows "
        "it):\n");
    for (const Row& row : rows) {
        std::printf(
            "n = %zu, %s:\n%s", row.plan.n, broadPhaseName(row.plan.method),
            formatStepStats(row.result.measured, static_cast<std::uint64_t>(row.result.steps)).c_str());
    }
    std::printf("\n");
    // Growth exponent from 10k to 100k: log(t100k / t10k) / log(10).
    for (BroadPhase method : methods) {
        const RunResult *small = nullptr, *large = nullptr;
        for (const Row& row : rows) {
            if (row.plan.method != method) continue;
            if (row.plan.n == 10000) small = &row.result;
            if (row.plan.n == 100000) large = &row.result;
        }
        if (small && large)
            std::printf(
                "%s growth 10k -> 100k: exponent %.3f (wall), %.3f (cpu), %.3f (detection + response)\n",
                broadPhaseName(method), std::log10(large->msPerStep / small->msPerStep),
                std::log10(large->cpuMsPerStep / small->cpuMsPerStep),
                std::log10(large->msDetection / small->msDetection));
    }

    if (!options.csv.empty()) {
        std::ostringstream out;
        out << "n,method,ms_per_step,pairs_tested,hits,peak_mb\n";
        for (const Row& row : rows) {
            char line[256];
            std::snprintf(line, sizeof line, "%zu,%s,%.4f,%.0f,%.0f,%.1f\n", row.plan.n,
                          broadPhaseName(row.plan.method), row.result.msPerStep, row.result.pairsTested,
                          row.result.hits, row.result.peakMb);
            out << line;
        }
        if (std::optional<Error> error = writeFileAtomically(options.csv, out.str())) {
            std::fprintf(stderr, "polarcade-bench scale: %s\n", error->message().c_str());
            return 1;
        }
        std::fflush(stdout);
        std::fprintf(stderr, "scale: wrote %s\n", options.csv.c_str());
    }
    if (!options.plot.empty()) {
#ifdef POLAR_BENCH_PLOTS
        LogLogPlot plot;
        plot.title =
            options.resting ? "resting rock field: step time" : "rock field: step time against objects";
        plot.xLabel = "objects n (4 neighbours within contact reach)";
        plot.yLabel = "ms per step (median, one thread): wall, and cpu dashed";
        const std::uint32_t colours[] = {0xFFD0342C, 0xFF1F6FD0, 0xFF2E9E44};
        const std::uint32_t light[] = {0xFFE8918C, 0xFF7FAEE6, 0xFF86C995};
        for (BroadPhase method : methods) {
            PlotSeries wall{broadPhaseName(method), colours[static_cast<int>(method)], {}};
            PlotSeries cpu{
                std::string(broadPhaseName(method)) + " cpu", light[static_cast<int>(method)], {}, true};
            for (const Row& row : rows) {
                if (row.plan.method != method) continue;
                wall.points.push_back({double(row.plan.n), row.result.msPerStep});
                cpu.points.push_back({double(row.plan.n), row.result.cpuMsPerStep});
            }
            if (wall.points.empty()) continue;
            plot.series.push_back(wall);
            plot.series.push_back(cpu);
        }
        plot.levels.push_back({"goal 10 ms at 100k", 0xFF9A6ADB, 10.0});
        plot.ranges.push_back({"box2d v3 pairs+narrow", 0xFF999999, 10000, 7.7, 10});
        plot.ranges.push_back({"box2d v3 pairs+narrow", 0xFF999999, 100000, 190, 300});
        if (auto error = savePng(plot.draw(900, 560), options.plot)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 1;
        }
        std::fflush(stdout);
        std::fprintf(stderr, "scale: wrote %s\n", options.plot.c_str());
#else
        std::fprintf(
            stderr,
            "polarcade-bench scale: --plot needs a build with the game (POLAR_BUILD_GAME) for PNG output\n");
        return cli::kBadInput;
#endif
    }
    return 0;
}

Registrar registrar{
    {"scale",
     "Rock fields of 1k, 10k, 100k moving objects: step time, pairs tested, hits, peak memory per broad "
     "phase",
     [](CLI::App& sub) -> std::function<int()> {
         auto options = std::make_shared<Options>();
         sub.add_option("--csv", options->csv, "Write n,method,ms_per_step,pairs_tested,hits,peak_mb");
         sub.add_option("--plot", options->plot, "Write a log-log plot of step time against n (PNG)");
         sub.add_option("--sizes", options->sizes, "Object counts")->delimiter(',');
         sub.add_option("--methods", options->methods, "all-pairs, grid, sort-and-sweep")->delimiter(',');
         sub.add_option("--all-pairs-max", options->allPairsMax, "Largest n measured with all-pairs");
         sub.add_option("--steps", options->steps, "Measured steps per run (default: by size)");
         sub.add_flag("--resting", options->resting,
                      "Settle the field and stop every object first: what sleeping could save");
         return [options] { return run(*options); };
     }}};

}  // namespace
}  // namespace polar::bench
