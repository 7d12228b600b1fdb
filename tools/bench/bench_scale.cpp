// polarcade-bench scale: step time, pairs tested, hits and peak memory of rock fields of growing
// size, for the all-pairs reference and the broad phases, on 1, 2, … threads (--threads), and with
// --box2d the same field stepped by Box2D 2.4 beside them; a table, CSV and a log-log plot.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include "amdahl.h"
#include "bench.h"
#include "cli.h"
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
// The largest field --sizes and --all-pairs-max take.
constexpr std::size_t kMaxObjects = 10'000'000;

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
    double msRest = 0;  // the step's wall time outside its effects (lists of effects, stats, memory)
    double pairsTested = 0;
    double hits = 0;
    double peakMb = 0;      // VmHWM of the process that built and stepped the world
    double neighbours = 0;  // measured: other centres within contact reach, per object
    StepStats measured;     // the World's own counters and times, summed over the measured steps
    int steps = 0;
    Box2dResult box2d;  // a Box2D run's figures (Plan::box2d)
};
static_assert(std::is_trivially_copyable_v<RunResult>, "a run's result crosses a pipe as bytes");

// The reach radius of an object with unit scale: max_k |c_k| + maxRadius_k.
double reachOf(const GameObject& o) {
    double reach = 0;
    for (const Bound& r : o.boundsOrEmpty()) reach = std::max(reach, r.centre().norm() + r.maxRadius());
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
    std::vector<double> total, cpu, detection, physics, broad, collisions, response, rest, pairs, hits;
    for (int s = 0; s < plan.steps; ++s) {
        const Stopwatch watch(CpuClock::Process);
        world.step(kStep);
        const Lap lap = watch.lap();
        cpu.push_back(lap.cpuMs);
        const StepStats& stats = world.lastStepStats();
        auto ms = [](std::uint64_t ns) { return static_cast<double>(ns) * 1e-6; };
        total.push_back(lap.wallMs);
        detection.push_back(ms(stats[kEffectCollisions].nanoseconds + stats[kEffectContainers].nanoseconds +
                               stats[kEffectResponse].nanoseconds));
        physics.push_back(ms(stats[kEffectPhysics].nanoseconds));
        broad.push_back(ms(stats.broadPhaseNanoseconds));
        collisions.push_back(ms(stats[kEffectCollisions].nanoseconds));
        response.push_back(ms(stats[kEffectResponse].nanoseconds));
        rest.push_back(std::max(0.0, total.back() - physics.back() - detection.back()));
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
    r.msRest = median(rest);
    // Counts come from the first kCountedSteps measured steps, which every method measures on the same
    // states, so that the columns compare like with like (times use every measured step).
    pairs.resize(std::min<std::size_t>(pairs.size(), kCountedSteps));
    hits.resize(std::min<std::size_t>(hits.size(), kCountedSteps));
    r.pairsTested = median(pairs);
    r.hits = median(hits);
    r.steps = plan.steps;
    r.peakMb = peakResidentMiB();
    r.ok = true;
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

// A measured run: what was asked and what came back.
struct Row {
    Plan plan;
    RunResult result;
};
struct Rows {
    std::vector<Row> polarcade, box2d;
};

// The broad phases named by --methods; nothing after a message on an unknown one.
std::optional<std::vector<BroadPhase>> checkedMethods(const Options& options) {
    std::vector<BroadPhase> methods;
    for (const std::string& name : options.methods) {
        auto method = broadPhaseFromName(name);
        if (!method) {
            std::fprintf(
                stderr,
                "polarcade-bench scale: unknown method \"%s\"; expected all-pairs, grid or sort-and-sweep\n",
                name.c_str());
            return std::nullopt;
        }
        methods.push_back(*method);
    }
    return methods;
}

// Every run in the order they are measured: per size, each method at each thread count, then
// Box2D. Measured steps: 9 for all-pairs (3 beyond 5000 objects), 41 otherwise (21 from 100k),
// unless --steps says.
std::vector<Plan> planRuns(const Options& options, const std::vector<BroadPhase>& methods) {
    std::vector<Plan> plans;
    for (std::size_t n : options.sizes) {
        const int steps = n >= 100000 ? 21 : 41;
        for (BroadPhase method : methods) {
            if (method == BroadPhase::AllPairs && n > options.allPairsMax) continue;
            Plan plan{n, method, kWarmup, method == BroadPhase::AllPairs ? (n > 5000 ? 3 : 9) : steps,
                      options.resting};
            if (options.steps > 0) plan.steps = options.steps;
            for (std::uint32_t threads : options.threads) {
                plan.threads = threads;
                plans.push_back(plan);
            }
        }
        if (options.box2d) {
            Plan plan{n, BroadPhase::Grid, kWarmup, options.steps > 0 ? options.steps : steps,
                      options.resting};
            plan.box2d = true;
            plans.push_back(plan);
        }
    }
    return plans;
}

// Each plan in a child process of its own (its peak memory is its own); nothing after a message
// when a run fails.
std::optional<Rows> measureAll(const std::vector<Plan>& plans) {
    Rows rows;
    for (const Plan& plan : plans) {
        const char* name = plan.box2d ? "box2d 2.4" : broadPhaseName(plan.method);
        std::fflush(stdout);
        std::fprintf(stderr, "scale: n = %zu, %s, %u thread%s: %d warm-up + %d measured steps ...\n", plan.n,
                     name, plan.threads, plan.threads == 1 ? "" : "s", plan.warmup, plan.steps);
        const std::optional<RunResult> result = inChildProcess([&] { return measure(plan); });
        if (!result || !result->ok) {
            std::fprintf(stderr, "polarcade-bench scale: the run for n = %zu, %s failed\n", plan.n, name);
            return std::nullopt;
        }
        (plan.box2d ? rows.box2d : rows.polarcade).push_back({plan, *result});
    }
    return rows;
}

// The Polarcade run with this size and method at `threads` threads, or null.
const RunResult* find(const Rows& rows, std::size_t n, BroadPhase method, std::uint32_t threads) {
    for (const Row& row : rows.polarcade)
        if (row.plan.n == n && row.plan.method == method && row.plan.threads == threads) return &row.result;
    return nullptr;
}

void printTable(const Rows& rows, bool resting) {
    std::printf(
        "%s rock field: physics + collisions + response, dt = 1/60 s; medians over the measured steps\n",
        resting ? "Resting" : "Moving");
    // The columns of the one-thread table first, in their order; thr and x1 thr after them.
    std::printf("%8s %-15s %10s %10s %10s %9s %9s %9s %9s %12s %9s %8s %6s %3s %7s\n", "n", "method",
                "ms/step", "cpu ms", "det+resp", "physics", "broad", "collide", "response", "pairs", "hits",
                "peak MB", "neigh", "thr", "x1 thr");
    for (const Row& row : rows.polarcade) {
        const RunResult& r = row.result;
        const RunResult* one = find(rows, row.plan.n, row.plan.method, 1);
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
}

// A run's step as phases one after another (wall, medians): physics, the broad phase, the narrow
// phase (collisions without the broad phase, containers and ccd included), the response (with the
// collidedWith lists) and the rest of the step.
std::vector<PhaseTime> phasesOf(const RunResult& one, const RunResult& many) {
    auto phases = [](const RunResult& r) {
        const double narrow = r.msDetection - r.msBroadPhase - r.msResponse;
        return std::array<double, 5>{r.msPhysics, r.msBroadPhase, narrow, r.msResponse, r.msRest};
    };
    const std::array<double, 5> a = phases(one), b = phases(many);
    const char* names[] = {"physics", "broad phase", "narrow phase", "response", "rest"};
    std::vector<PhaseTime> out;
    for (std::size_t k = 0; k < a.size(); ++k) out.push_back({names[k], a[k], b[k]});
    return out;
}

// For every run at N > 1 threads beside one at 1: each phase's Amdahl fit and the gains it allows.
void printAmdahlTables(const Rows& rows) {
    bool any = false;
    for (const Row& row : rows.polarcade) {
        const RunResult* one = find(rows, row.plan.n, row.plan.method, 1);
        if (row.plan.threads == 1 || !one) continue;
        if (!any) std::printf("\n");
        any = true;
        char title[160];
        std::snprintf(title, sizeof title, "Amdahl, n = %zu, %s, 1 -> %u threads (wall medians):", row.plan.n,
                      broadPhaseName(row.plan.method), row.plan.threads);
        printAmdahl(title, phasesOf(*one, row.result), row.plan.threads);
        std::printf("cpu ms per step: %.3f at 1 thread, %.3f at %u (the work the threads add: %+.1f %%)\n",
                    one->cpuMsPerStep, row.result.cpuMsPerStep, row.plan.threads,
                    100.0 * (row.result.cpuMsPerStep / one->cpuMsPerStep - 1.0));
    }
    if (any)
        std::printf(
            "s: the serial fraction that gives the measured speed-up by Amdahl's law (* clamped to [0, 1]:\n"
            "the speed-up was above N or below 1); serial ms: s x the 1-thread time; gain 16, 64: what\n"
            "that s allows at 16 and 64 threads; sum: the phases together, each by its own fit. A ceiling:\n"
            "the fit cannot see what only more threads cost (memory, wake-ups, splits capped at N).\n");
}

void printBox2d(const Rows& rows) {
    if (rows.box2d.empty()) return;
    std::printf(
        "\nBox2D 2.4 on the same field (one thread; its own 30 warm-up steps from the same start), "
        "beside\n"
        "Polarcade's 1-thread grid:\n");
    std::printf("%8s %11s %11s %10s %9s %9s %9s %10s %10s %9s %12s %10s\n", "n", "b2 step", "b2 bp+coll",
                "b2 broad", "b2 coll", "b2 solve", "contacts", "touching", "pc step", "pc coll",
                "pc det+resp", "b2/pc coll");
    for (const Row& row : rows.box2d) {
        const Box2dResult& b = row.result.box2d;
        const RunResult* pc = find(rows, row.plan.n, BroadPhase::Grid, 1);
        char ratio[32] = "-";
        if (pc && pc->msCollisions > 0)
            std::snprintf(ratio, sizeof ratio, "%.1f×", b.pairsNarrowMs / pc->msCollisions);
        std::printf("%8zu %11.3f %11.3f %10.3f %9.3f %9.3f %9.0f %10.0f %10.3f %9.3f %12.3f %11s\n",
                    row.plan.n, b.stepMs, b.pairsNarrowMs, b.broadPhaseMs, b.collideMs, b.solveMs, b.contacts,
                    b.touching, pc ? pc->msPerStep : 0.0, pc ? pc->msCollisions : 0.0,
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

void printPerEffect(const Rows& rows) {
    std::printf(
        "\nPer effect, averaged over the measured steps (World::totalStats, as polarcade --stats shows "
        "it):\n");
    for (const Row& row : rows.polarcade) {
        std::printf(
            "n = %zu, %s, %u thread%s:\n%s", row.plan.n, broadPhaseName(row.plan.method), row.plan.threads,
            row.plan.threads == 1 ? "" : "s",
            formatStepStats(row.result.measured, static_cast<std::uint64_t>(row.result.steps)).c_str());
    }
    std::printf("\n");
}

// Growth exponent from 10k to 100k: log(t100k / t10k) / log(10).
void printGrowth(const Rows& rows, const std::vector<BroadPhase>& methods, const Options& options) {
    for (BroadPhase method : methods) {
        for (std::uint32_t threads : options.threads) {
            const RunResult* small = find(rows, 10000, method, threads);
            const RunResult* large = find(rows, 100000, method, threads);
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
}

// Columns keep their meaning; threads and pairs_narrow_ms were added at the end, then the phases
// (cpu_ms the process's CPU time per step; physics, broad, narrow and response as the Amdahl table
// splits the step) and, on rows at N > 1 threads with a 1-thread row beside them, the step's serial
// fraction and the gains at 16 and 64 threads from its phases' fits (empty otherwise). Box2D rows:
// method box2d-2.4, ms_per_step its b2Profile step, pairs_tested its contacts, hits its touching
// contacts, peak_mb empty (not measured); pairs_narrow_ms is Box2D's broadphase + collide and
// Polarcade's collisions effect; the phase columns empty.
bool writeCsv(const Rows& rows, const std::string& path) {
    Csv csv(
        "n,method,ms_per_step,pairs_tested,hits,peak_mb,threads,pairs_narrow_ms,cpu_ms,physics_ms,broad_ms,"
        "narrow_ms,response_ms,serial_fraction,gain16,gain64");
    for (const Row& row : rows.polarcade) {
        const RunResult& r = row.result;
        const RunResult* one = find(rows, row.plan.n, row.plan.method, 1);
        const std::vector<PhaseTime> phases = phasesOf(r, r);
        if (row.plan.threads == 1 || !one) {
            csv.row(row.plan.n, broadPhaseName(row.plan.method), Fixed{r.msPerStep, 4},
                    Fixed{r.pairsTested, 0}, Fixed{r.hits, 0}, Fixed{r.peakMb, 1}, row.plan.threads,
                    Fixed{r.msCollisions, 4}, Fixed{r.cpuMsPerStep, 4}, Fixed{r.msPhysics, 4},
                    Fixed{r.msBroadPhase, 4}, Fixed{phases[2].oneMs, 4}, Fixed{r.msResponse, 4}, "", "", "");
            continue;
        }
        // The step's serial fraction and gains, from its phases' fits (as the table's sum row).
        const std::vector<PhaseTime> fitted = phasesOf(*one, r);
        double serial = 0.0, total = 0.0;
        for (const PhaseTime& p : fitted) {
            serial += fitAmdahl(p.oneMs, p.manyMs, row.plan.threads).serialFraction * p.oneMs;
            total += p.oneMs;
        }
        csv.row(row.plan.n, broadPhaseName(row.plan.method), Fixed{r.msPerStep, 4}, Fixed{r.pairsTested, 0},
                Fixed{r.hits, 0}, Fixed{r.peakMb, 1}, row.plan.threads, Fixed{r.msCollisions, 4},
                Fixed{r.cpuMsPerStep, 4}, Fixed{r.msPhysics, 4}, Fixed{r.msBroadPhase, 4},
                Fixed{phases[2].oneMs, 4}, Fixed{r.msResponse, 4},
                Fixed{total > 0.0 ? serial / total : 0.0, 4},
                Fixed{projectedGain(fitted, row.plan.threads, kProjectedThreads[0]), 2},
                Fixed{projectedGain(fitted, row.plan.threads, kProjectedThreads[1]), 2});
    }
    for (const Row& row : rows.box2d) {
        const Box2dResult& b = row.result.box2d;
        csv.row(row.plan.n, "box2d-2.4", Fixed{b.stepMs, 4}, Fixed{b.contacts, 0}, Fixed{b.touching, 0}, "",
                1, Fixed{b.pairsNarrowMs, 4}, "", "", "", "", "", "", "", "");
    }
    return csv.write(path);
}

// The log-log plot of step time against n; false after a message when it cannot be written.
bool writePlot(const Rows& rows, const std::vector<BroadPhase>& methods, const Options& options) {
#ifdef POLAR_BENCH_PLOTS
    LogLogPlot plot;
    plot.title = options.resting ? "resting rock field: step time" : "rock field: step time against objects";
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
            for (const Row& row : rows.polarcade) {
                if (row.plan.method != method || row.plan.threads != threads) continue;
                wall.points.push_back({double(row.plan.n), row.result.msPerStep});
                cpu.points.push_back({double(row.plan.n), row.result.cpuMsPerStep});
            }
            if (wall.points.empty()) continue;
            plot.series.push_back(wall);
            if (first) plot.series.push_back(cpu);
        }
    }
    if (!rows.box2d.empty()) {
        PlotSeries step{"box2d 2.4 step", 0xFF555555, {}};
        PlotSeries pairs{"box2d 2.4 pairs+narrow", 0xFF999999, {}, true};
        for (const Row& row : rows.box2d) {
            step.points.push_back({double(row.plan.n), row.result.box2d.stepMs});
            pairs.points.push_back({double(row.plan.n), row.result.box2d.pairsNarrowMs});
        }
        plot.series.push_back(step);
        plot.series.push_back(pairs);
    }
    plot.levels.push_back({"goal 10 ms at 100k", 0xFF9A6ADB, 10.0});
    if (auto error = savePng(plot.draw(900, 560), options.plot)) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        return false;
    }
    std::fflush(stdout);
    std::printf("wrote %s\n", options.plot.c_str());
    return true;
#else
    (void)rows, (void)methods, (void)options;
    return false;
#endif
}

int run(const Options& options) {
#ifndef POLAR_BENCH_PLOTS
    if (!options.plot.empty()) {
        std::fprintf(
            stderr,
            "polarcade-bench scale: --plot needs a build with the game (POLAR_BUILD_GAME) for PNG output\n");
        return cli::kBadInput;
    }
#endif
    const std::optional<std::vector<BroadPhase>> methods = checkedMethods(options);
    if (!methods) return cli::kBadInput;
    const std::optional<Rows> rows = measureAll(planRuns(options, *methods));
    if (!rows) return 1;
    printTable(*rows, options.resting);
    printAmdahlTables(*rows);
    printBox2d(*rows);
    printPerEffect(*rows);
    printGrowth(*rows, *methods, options);
    if (!options.csv.empty() && !writeCsv(*rows, options.csv)) return 1;
    if (!options.plot.empty() && !writePlot(*rows, *methods, options)) return 1;
    return 0;
}

Registrar registrar{
    {"scale",
     "Rock fields of 1k, 10k, 100k moving objects: step time, pairs tested, hits, peak memory per broad "
     "phase",
     [](polar::cli::Command& sub) -> std::function<int()> {
         auto options = std::make_shared<Options>();
         sub.option("--csv", options->csv,
                    "Write n,method,ms_per_step,pairs_tested,hits,peak_mb,threads,pairs_narrow_ms,cpu_ms,"
                    "physics_ms,broad_ms,narrow_ms,response_ms,serial_fraction,gain16,gain64")
             .outputFile();
         sub.option("--plot", options->plot, "Write a log-log plot of step time against n (PNG)")
             .outputFile();
         sub.option("--sizes", options->sizes, "Object counts", {2, kMaxObjects}).delimiter(',');
         sub.option("--methods", options->methods, "all-pairs, grid, sort-and-sweep").delimiter(',');
         sub.option("--all-pairs-max", options->allPairsMax, "Largest n measured with all-pairs",
                    {0, kMaxObjects});
         sub.option("--steps", options->steps, "Measured steps per run (default: by size)", {0, 100000});
         sub.option("--threads", options->threads,
                    "Thread counts (WorldDef::workers) to run each size and method at, e.g. 1,2", {1, 256})
             .delimiter(',');
         sub.flag("--box2d", options->box2d,
                  "Also step the same field in Box2D 2.4 (one thread) and show it beside Polarcade");
         sub.flag("--resting", options->resting,
                  "Settle the field and stop every object first: what sleeping could save");
         return [options] { return run(*options); };
     }}};

}  // namespace
}  // namespace polar::bench
