// polarcade-bench scale: step time, pairs tested, hits and peak memory of rock fields of growing
// size, for the all-pairs reference and the broad phases, on 1, 2, … threads (--threads), and with
// --box2d the same field stepped by Box2D 2.4 beside them; a table, CSV and a log-log plot.
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
#include "median.h"
#include "polar/atomic_file.h"
#include "polar/authoring/random_scene.h"
#include "polar/world.h"
#include "scale_box2d.h"
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
    double cpuMsPerStep = 0;  // the same step in the process's CPU time (every thread): what the step
                              // cost, without the time other processes had the cores (machines are shared)
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
    Box2dResult box2d;  // a Box2D run's figures (Plan::box2d)
};
static_assert(std::is_trivially_copyable_v<RunResult>, "a run's result crosses a pipe as bytes");

// This process's CPU time in milliseconds, every thread's (a run has a process of its own).
double processCpuMs() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
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
    std::uint32_t threads = 1;  // WorldDef::workers
    bool box2d = false;         // step the field in Box2D instead (from the same start)
};

// Builds and steps one world; runs in a child process so that its peak memory is its own.
RunResult measure(const Plan& plan) {
    RunResult r;
    // Every method is measured on the same states: the warm-up runs on the grid (methods give
    // identical results, so the trajectory is the same), then the method under test takes over.
    World world = buildRockField(kSeed, plan.n, 4.0, BroadPhase::Grid, plan.threads);
    if (plan.box2d) {
        r.box2d = measureBox2d(world, world.def().restitution, plan.warmup, plan.steps, kCountedSteps);
        r.steps = plan.steps;
        r.ok = r.box2d.ok;
        return r;
    }
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
        double cpuStart = processCpuMs();
        auto start = std::chrono::steady_clock::now();
        world.step(kStep);
        auto end = std::chrono::steady_clock::now();
        cpu.push_back(processCpuMs() - cpuStart);
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
    std::vector<std::uint32_t> threads{1};
    bool box2d = false;
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
    for (std::uint32_t t : options.threads) {
        if (t < 1 || t > 256) {
            std::fprintf(stderr, "polarcade-bench scale: %u threads is out of range; expected 1 to 256\n", t);
            return cli::kBadInput;
        }
    }
    struct Row {
        Plan plan;
        RunResult result;
    };
    std::vector<Row> rows, box2dRows;
    auto runOne = [&](const Plan& plan, const char* name) {
        std::fflush(stdout);
        std::fprintf(stderr, "scale: n = %zu, %s, %u thread%s: %d warm-up + %d measured steps ...\n", plan.n,
                     name, plan.threads, plan.threads == 1 ? "" : "s", plan.warmup, plan.steps);
        RunResult result = measureInChild(plan);
        if (!result.ok)
            std::fprintf(stderr, "polarcade-bench scale: the run for n = %zu, %s failed\n", plan.n, name);
        return result;
    };
    for (std::size_t n : options.sizes) {
        for (BroadPhase method : methods) {
            if (method == BroadPhase::AllPairs && n > options.allPairsMax) continue;
            Plan plan{n, method, kWarmup, 0, options.resting};
            if (method == BroadPhase::AllPairs)
                plan.steps = n > 5000 ? 3 : 9;
            else
                plan.steps = n >= 100000 ? 21 : 41;
            if (options.steps > 0) plan.steps = options.steps;
            for (std::uint32_t threads : options.threads) {
                plan.threads = threads;
                RunResult result = runOne(plan, broadPhaseName(method));
                if (!result.ok) return 1;
                rows.push_back({plan, result});
            }
        }
        if (options.box2d) {
            Plan plan{n, BroadPhase::Grid, kWarmup, n >= 100000 ? 21 : 41, options.resting};
            if (options.steps > 0) plan.steps = options.steps;
            plan.box2d = true;
            RunResult result = runOne(plan, "box2d 2.4");
            if (!result.ok) return 1;
            box2dRows.push_back({plan, result});
        }
    }
    // The same n and method at one thread, for the speed-up column.
    auto oneThread = [&](const Row& row) -> const RunResult* {
        for (const Row& other : rows)
            if (other.plan.n == row.plan.n && other.plan.method == row.plan.method && other.plan.threads == 1)
                return &other.result;
        return nullptr;
    };

    std::printf(
        "%s rock field: physics + collisions + response, dt = 1/60 s; medians over the measured steps\n",
        options.resting ? "Resting" : "Moving");
    // The columns of the one-thread table first, in their order; thr and x1 thr after them.
    std::printf("%8s %-15s %10s %10s %10s %9s %9s %9s %9s %12s %9s %8s %6s %3s %7s\n", "n", "method",
                "ms/step", "cpu ms", "det+resp", "physics", "broad", "collide", "response", "pairs", "hits",
                "peak MB", "neigh", "thr", "x1 thr");
    for (const Row& row : rows) {
        const RunResult& r = row.result;
        const RunResult* one = oneThread(row);
        char speedUp[32] = "-";
        if (one && r.msPerStep > 0)
            std::snprintf(speedUp, sizeof speedUp, "%.2f×", one->msPerStep / r.msPerStep);
        std::printf(
            "%8zu %-15s %10.3f %10.3f %10.3f %9.3f %9.3f %9.3f %9.3f %12.0f %9.0f %8.1f %6.2f %3u %8s\n",
            row.plan.n, broadPhaseName(row.plan.method), r.msPerStep, r.cpuMsPerStep, r.msDetection,
            r.msPhysics, r.msBroadPhase, r.msCollisions, r.msResponse, r.pairsTested, r.hits, r.peakMb,
            r.neighbours, row.plan.threads, speedUp);
    }
    std::printf(
        "ms/step: wall clock; cpu ms: the process's CPU time for the same steps, every thread;\n"
        "det+resp = collisions + containers + response (wall); broad: per-step data and broad phase, part\n"
        "of collide; pairs and hits: medians of the first %zu measured steps (the same states for every\n"
        "method); peak MB: VmHWM of the process that built and stepped the world; neigh: measured other\n"
        "centres within reach; thr: WorldDef::workers; x1 thr: the 1-thread ms/step over this one.\n",
        kCountedSteps);
    if (!box2dRows.empty()) {
        std::printf(
            "\nBox2D 2.4 on the same field (one thread; its own 30 warm-up steps from the same start), "
            "beside\n"
            "Polarcade's 1-thread grid:\n");
        std::printf("%8s %11s %11s %10s %9s %9s %9s %10s %10s %9s %12s %10s\n", "n", "b2 step", "b2 bp+coll",
                    "b2 broad", "b2 coll", "b2 solve", "contacts", "touching", "pc step", "pc coll",
                    "pc det+resp", "b2/pc coll");
        for (const Row& row : box2dRows) {
            const Box2dResult& b = row.result.box2d;
            const RunResult* pc = nullptr;
            for (const Row& other : rows)
                if (other.plan.n == row.plan.n && other.plan.method == BroadPhase::Grid &&
                    other.plan.threads == 1)
                    pc = &other.result;
            char ratio[32] = "-";
            if (pc && pc->msCollisions > 0)
                std::snprintf(ratio, sizeof ratio, "%.1f×", b.pairsNarrowMs / pc->msCollisions);
            std::printf("%8zu %11.3f %11.3f %10.3f %9.3f %9.3f %9.0f %10.0f %10.3f %9.3f %12.3f %11s\n",
                        row.plan.n, b.stepMs, b.pairsNarrowMs, b.broadPhaseMs, b.collideMs, b.solveMs,
                        b.contacts, b.touching, pc ? pc->msPerStep : 0.0, pc ? pc->msCollisions : 0.0,
                        pc ? pc->msDetection : 0.0, ratio);
        }
        std::printf(
            "b2 step: b2Profile::step; b2 bp+coll: broadphase (moving proxies, finding new pairs) + collide\n"
            "(every contact's manifold); contacts: pairs whose fattened boxes overlap; touching: of those,\n"
            "with manifold points; pc coll: Polarcade's collisions effect (per-step data, broad phase and "
            "pair\n"
            "tests), the like of b2 bp+coll; b2/pc coll: how many times longer Box2D takes for it. Box2D "
            "also\n"
            "computes what Polarcade does not: contact manifolds (points, normals, separations), kept per\n"
            "pair from step to step for warm starting, and an iterative solver (8 velocity + 3 position\n"
            "iterations) with islands, mass and inertia.\n");
    }
    std::printf(
        "\nPer effect, averaged over the measured steps (World::totalStats, as polarcade --stats shows "
        "it):\n");
    for (const Row& row : rows) {
        std::printf(
            "n = %zu, %s, %u thread%s:\n%s", row.plan.n, broadPhaseName(row.plan.method), row.plan.threads,
            row.plan.threads == 1 ? "" : "s",
            formatStepStats(row.result.measured, static_cast<std::uint64_t>(row.result.steps)).c_str());
    }
    std::printf("\n");
    // Growth exponent from 10k to 100k: log(t100k / t10k) / log(10).
    for (BroadPhase method : methods) {
        for (std::uint32_t threads : options.threads) {
            const RunResult *small = nullptr, *large = nullptr;
            for (const Row& row : rows) {
                if (row.plan.method != method || row.plan.threads != threads) continue;
                if (row.plan.n == 10000) small = &row.result;
                if (row.plan.n == 100000) large = &row.result;
            }
            if (small && large)
                std::printf(
                    "%s, %u thread%s, growth 10k -> 100k: exponent %.3f (wall), %.3f (cpu), %.3f (detection "
                    "+ "
                    "response)\n",
                    broadPhaseName(method), threads, threads == 1 ? "" : "s",
                    std::log10(large->msPerStep / small->msPerStep),
                    std::log10(large->cpuMsPerStep / small->cpuMsPerStep),
                    std::log10(large->msDetection / small->msDetection));
        }
    }

    if (!options.csv.empty()) {
        // Columns keep their meaning; threads and pairs_narrow_ms were added at the end. Box2D rows:
        // method box2d-2.4, ms_per_step its b2Profile step, pairs_tested its contacts, hits its
        // touching contacts, peak_mb empty (not measured); pairs_narrow_ms is Box2D's broadphase +
        // collide and Polarcade's collisions effect.
        std::ostringstream out;
        out << "n,method,ms_per_step,pairs_tested,hits,peak_mb,threads,pairs_narrow_ms\n";
        for (const Row& row : rows) {
            char line[256];
            std::snprintf(line, sizeof line, "%zu,%s,%.4f,%.0f,%.0f,%.1f,%u,%.4f\n", row.plan.n,
                          broadPhaseName(row.plan.method), row.result.msPerStep, row.result.pairsTested,
                          row.result.hits, row.result.peakMb, row.plan.threads, row.result.msCollisions);
            out << line;
        }
        for (const Row& row : box2dRows) {
            const Box2dResult& b = row.result.box2d;
            char line[256];
            std::snprintf(line, sizeof line, "%zu,box2d-2.4,%.4f,%.0f,%.0f,,1,%.4f\n", row.plan.n, b.stepMs,
                          b.contacts, b.touching, b.pairsNarrowMs);
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
        plot.yLabel = "ms per step (median): wall, and cpu dashed";
        const std::uint32_t colours[] = {0xFFD0342C, 0xFF1F6FD0, 0xFF2E9E44};
        const std::uint32_t light[] = {0xFFE8918C, 0xFF7FAEE6, 0xFF86C995};
        const std::uint32_t threadColours[] = {0xFF8E44AD, 0xFFE67E22, 0xFF16A085, 0xFF7F8C8D};
        for (BroadPhase method : methods) {
            for (std::size_t t = 0; t < options.threads.size(); ++t) {
                const std::uint32_t threads = options.threads[t];
                std::string name = broadPhaseName(method);
                if (options.threads.size() > 1 || threads != 1)
                    name += ", " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");
                // One thread in the method's colours; more threads (drawn for the grid) in their own.
                const bool first = t == 0;
                if (!first && method != BroadPhase::Grid) continue;
                const std::uint32_t colour =
                    first ? colours[static_cast<int>(method)] : threadColours[(t - 1) % 4];
                PlotSeries wall{name, colour, {}};
                PlotSeries cpu{name + " cpu", first ? light[static_cast<int>(method)] : colour, {}, true};
                for (const Row& row : rows) {
                    if (row.plan.method != method || row.plan.threads != threads) continue;
                    wall.points.push_back({double(row.plan.n), row.result.msPerStep});
                    cpu.points.push_back({double(row.plan.n), row.result.cpuMsPerStep});
                }
                if (wall.points.empty()) continue;
                plot.series.push_back(wall);
                if (first) plot.series.push_back(cpu);
            }
        }
        if (!box2dRows.empty()) {
            PlotSeries step{"box2d 2.4 step", 0xFF555555, {}};
            PlotSeries pairs{"box2d 2.4 pairs+narrow", 0xFF999999, {}, true};
            for (const Row& row : box2dRows) {
                step.points.push_back({double(row.plan.n), row.result.box2d.stepMs});
                pairs.points.push_back({double(row.plan.n), row.result.box2d.pairsNarrowMs});
            }
            plot.series.push_back(step);
            plot.series.push_back(pairs);
        }
        plot.levels.push_back({"goal 10 ms at 100k", 0xFF9A6ADB, 10.0});
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
         sub.add_option("--csv", options->csv,
                        "Write n,method,ms_per_step,pairs_tested,hits,peak_mb,threads,pairs_narrow_ms");
         sub.add_option("--plot", options->plot, "Write a log-log plot of step time against n (PNG)");
         sub.add_option("--sizes", options->sizes, "Object counts")->delimiter(',');
         sub.add_option("--methods", options->methods, "all-pairs, grid, sort-and-sweep")->delimiter(',');
         sub.add_option("--all-pairs-max", options->allPairsMax, "Largest n measured with all-pairs");
         sub.add_option("--steps", options->steps, "Measured steps per run (default: by size)");
         sub.add_option("--threads", options->threads,
                        "Thread counts (WorldDef::workers) to run each size and method at, e.g. 1,2")
             ->delimiter(',');
         sub.add_flag("--box2d", options->box2d,
                      "Also step the same field in Box2D 2.4 (one thread) and show it beside Polarcade");
         sub.add_flag("--resting", options->resting,
                      "Settle the field and stop every object first: what sleeping could save");
         return [options] { return run(*options); };
     }}};

}  // namespace
}  // namespace polar::bench
