// polarcade-bench soak: the demo game played headless for a long time (10⁶ ticks, 4.6 hours of
// play, by default) by the demo pilot with seeded random input mixed in; a new game starts whenever
// one ends. Every tick, every object's state is checked for NaN and infinity. Per window of ticks
// it records resident memory and the median time of one step (Game::tick plus the particles, as the
// game runs them). It fails when
//   - any state is not finite;
//   - RSS(end) − RSS(baseline tick, 10⁵ by default) > 1 MB;
//   - per-step time grows: median CPU time per step over the last tenth of the windows against the
//     first tenth, and the least-squares line through the window medians (its rise over the run,
//     relative to the mean), each beyond --time-tolerance.
// The bench's own bookkeeping is allocated before the first tick, so any growth is the game's.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

#include "app/hud/game_drawing.h"
#include "bench.h"
#include "cli.h"
#include "files/assets.h"
#include "rules/bot.h"
#include "soak_plot.h"

namespace {

using namespace polar;
using namespace polar::game;

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kAddressSanitizer = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kAddressSanitizer = true;
#else
constexpr bool kAddressSanitizer = false;
#endif
#else
constexpr bool kAddressSanitizer = false;
#endif

using polar::bench::CpuClock;
using polar::bench::medianInPlace;
using polar::bench::residentKiB;
using polar::bench::Stopwatch;

double medianOf(std::vector<double> v) {
    return medianInPlace(v);
}

// The first non-finite number in an object's state, or nullptr.
const char* nonFiniteField(const GameObject& o) {
    const Transform& t = o.transform;
    if (!std::isfinite(t.position().x()) || !std::isfinite(t.position().y())) return "position";
    if (!std::isfinite(t.rotation())) return "rotation";
    if (!std::isfinite(t.scaleFactors().x()) || !std::isfinite(t.scaleFactors().y())) return "scale";
    if (!std::isfinite(o.velocity.x()) || !std::isfinite(o.velocity.y())) return "velocity";
    if (!std::isfinite(o.spin)) return "spin";
    if (!std::isfinite(o.damping)) return "damping";
    return nullptr;
}

// The demo pilot with seeded noise: stretches of 20 to 200 ticks where it flies itself alternate
// with stretches where random buttons (re-rolled every 4 to 30 ticks) are held, about a quarter of
// the time. The noise makes it crash now and then, so games end and new ones start.
class NoisyPilot {
  public:
    NoisyPilot(std::uint64_t seed, double randomShare)
        : bot_(seed), rng_(seed ^ 0x5eed5eedull), randomShare_(randomShare) {}

    Actions decide(const Game& game) {
        if (stretch_ <= 0) {
            random_ = rng_.chance(randomShare_);
            stretch_ = 20 + static_cast<int>(rng_.below(181));
        }
        --stretch_;
        Actions bot = bot_.decide(game);  // always asked, so its own noise stays in step
        if (!random_) return bot;
        if (hold_ <= 0) {
            held_ = static_cast<Actions>(rng_.below(16));
            hold_ = 4 + static_cast<int>(rng_.below(27));
        }
        --hold_;
        return held_;
    }

  private:
    Bot bot_;
    Rng rng_;
    double randomShare_;
    bool random_ = false;
    int stretch_ = 0;
    Actions held_ = 0;
    int hold_ = 0;
};

struct Options {
    long ticks = 1000000;
    long memFrom = 100000;
    int window = 10000;
    std::uint64_t seed = 1;
    int drawEvery = 60;
    double noise = 0.25;
    double rssToleranceKb = 1024;
    double timeTolerance = 0.20;
    bool timeGoal = true;
    std::string csv;
    std::string plot;
};

struct Window {
    long endTick = 0;
    long rssKb = 0;
    double cpuUs = 0, wallUs = 0;
    double objects = 0;  // mean over the window
    int games = 0;       // games started so far
    int bestWave = 0;    // the highest wave reached so far
};

std::optional<Game> newGame(const AssetFs& assets, std::uint64_t seed) {
    Game::Config config;
    config.reader = assets.reader();
    config.seed = seed;
    Result<Game> game = Game::create(config);
    if (!game) {
        std::fprintf(stderr, "%s\n", game.error().message().c_str());
        return std::nullopt;
    }
    return std::move(*game);
}

// What the play gave: a window of figures per --window ticks, resident memory at the baseline tick
// and at the end, and the games played.
struct Played {
    std::vector<Window> windows;
    long rssBaseline = -1, rssEnd = -1;
    int games = 1;
    double seconds = 0;  // wall clock of the whole play, checks and drawing included
};

// The play: every tick timed (Game::tick and the particles), every object checked for a
// non-finite value, a frame drawn every --draw-every ticks, a new game whenever one ends. Nothing
// after a message when a state is not finite or a game cannot start. The bookkeeping is allocated
// before the first tick, so any growth is the game's.
std::optional<Played> play(const AssetFs& assets, const Options& options) {
    std::optional<Game> game = newGame(assets, options.seed);
    if (!game) return std::nullopt;
    NoisyPilot pilot(options.seed, options.noise);
    Particles particles;
    SpriteCache sprites(assets);
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    Played played;
    played.windows.reserve(static_cast<std::size_t>(options.ticks / options.window) + 1);
    std::vector<double> cpu(options.window), wall(options.window);
    double objectSum = 0;
    int bestWave = 0;
    const Stopwatch whole(CpuClock::None);
    const long progressEvery = std::max<long>(options.window, options.ticks / 10);

    for (long tick = 1; tick <= options.ticks; ++tick) {
        const Actions actions = pilot.decide(*game);
        const Stopwatch step(CpuClock::Thread);
        game->tick(actions);
        particles.spawnFor(game->events(), game->tickCount());
        particles.tick(1.0 / 60);
        const polar::bench::Lap lap = step.lap();
        const std::size_t slot = static_cast<std::size_t>((tick - 1) % options.window);
        cpu[slot] = lap.cpuMs * 1e3;
        wall[slot] = lap.wallMs * 1e3;
        objectSum += static_cast<double>(game->world().objects().size());

        for (const GameObject& o : game->world().objects()) {
            if (const char* field = nonFiniteField(o)) {
                std::fprintf(
                    stderr, "soak: tick %ld (game %d, its tick %llu): object %u \"%s\" has a non-finite %s\n",
                    tick, played.games, static_cast<unsigned long long>(game->tickCount()), o.id,
                    o.name.c_str(), field);
                return std::nullopt;
            }
        }
        if (options.drawEvery > 0 && tick % options.drawEvery == 0)
            drawGame(canvas, *game, sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        bestWave = std::max(bestWave, game->wave());
        if (game->over()) {
            ++played.games;
            game = newGame(assets, options.seed + static_cast<std::uint64_t>(played.games - 1));
            if (!game) return std::nullopt;
        }
        if (tick % options.window == 0) {
            Window w;
            w.endTick = tick;
            w.rssKb = residentKiB();
            w.cpuUs = medianInPlace(cpu);
            w.wallUs = medianInPlace(wall);
            w.objects = objectSum / options.window;
            w.games = played.games;
            w.bestWave = bestWave;
            played.windows.push_back(w);
            objectSum = 0;
            if (tick == options.memFrom) played.rssBaseline = w.rssKb;
        }
        if (tick == options.memFrom && played.rssBaseline < 0) played.rssBaseline = residentKiB();
        if (tick % progressEvery == 0)
            std::fprintf(stderr, "soak: %ld/%ld ticks (%.0f%%), %.1f s, RSS %.2f MB, %d games\n", tick,
                         options.ticks, 100.0 * tick / options.ticks, whole.wallMs() / 1e3,
                         residentKiB() / 1024.0, played.games);
    }
    played.rssEnd = residentKiB();
    played.seconds = whole.wallMs() / 1e3;
    return played;
}

// Per-step time over the run: the first tenth of the windows against the last tenth, the fitted
// line, and the window-to-window noise.
struct Growth {
    double earlyUs = 0, lateUs = 0;
    double ratio = 0;  // lateUs / earlyUs
    double rise = 0;   // the fitted line's rise over the run, relative to the mean
    double noise = 0;  // median absolute deviation of the window medians, relative
};

Growth growthOf(const std::vector<Window>& windows) {
    const std::size_t n = windows.size(), k = std::max<std::size_t>(1, n / 10);
    std::vector<double> early, late, all;
    for (std::size_t i = 0; i < n; ++i) {
        all.push_back(windows[i].cpuUs);
        if (i < k) early.push_back(windows[i].cpuUs);
        if (i >= n - k) late.push_back(windows[i].cpuUs);
    }
    Growth g;
    g.earlyUs = medianOf(early), g.lateUs = medianOf(late);
    const double allUs = medianOf(all);
    // Least squares y = a + b·t over the window medians; rise = b·(t_last − t_first) / mean(y).
    double tMean = 0, yMean = 0;
    for (const Window& w : windows) tMean += w.endTick, yMean += w.cpuUs;
    tMean /= std::max<std::size_t>(1, n), yMean /= std::max<std::size_t>(1, n);
    double stt = 0, sty = 0;
    for (const Window& w : windows)
        stt += (w.endTick - tMean) * (w.endTick - tMean), sty += (w.endTick - tMean) * (w.cpuUs - yMean);
    const double slope = stt > 0 ? sty / stt : 0;  // µs per tick
    g.rise = n > 1 ? slope * (windows.back().endTick - windows.front().endTick) / yMean : 0;
    std::vector<double> deviations;
    for (double y : all) deviations.push_back(std::fabs(y - allUs));
    g.noise = allUs > 0 ? medianOf(deviations) / allUs : 0;
    g.ratio = g.earlyUs > 0 ? g.lateUs / g.earlyUs : 0;
    return g;
}

// The windows at 1, 2, 5 × 10^k ticks, the baseline and the end; every window into the CSV.
void printWindows(const std::vector<Window>& windows, const Options& options, polar::bench::Csv& csv) {
    std::printf("\n%10s  %9s  %11s  %12s  %9s  %6s  %9s\n", "tick", "RSS MB", "cpu us/step", "wall us/step",
                "objects", "games", "best wave");
    auto shown = [&](long t) {
        if (t == options.memFrom || t == options.ticks) return true;
        while (t % 10 == 0) t /= 10;
        return t == 1 || t == 2 || t == 5;
    };
    for (const Window& w : windows) {
        if (shown(w.endTick))
            std::printf("%10ld  %9.2f  %11.2f  %12.2f  %9.1f  %6d  %9d\n", w.endTick, w.rssKb / 1024.0,
                        w.cpuUs, w.wallUs, w.objects, w.games, w.bestWave);
        csv.row(w.endTick, w.rssKb, w.cpuUs, w.wallUs, w.objects, w.games, w.bestWave);
    }
}

struct Verdict {
    double rssGrowthKb = 0;
    bool rssMet = false, timeMet = false;
};

Verdict printGoals(const Played& played, const Growth& g, const Options& options) {
    Verdict v;
    v.rssGrowthKb = static_cast<double>(played.rssEnd - played.rssBaseline);
    v.rssMet = played.rssBaseline > 0 && v.rssGrowthKb <= options.rssToleranceKb;
    v.timeMet = g.ratio - 1 <= options.timeTolerance && g.rise <= options.timeTolerance;
    std::printf("\n%d games, %.1f s in all (%.2f us per tick including checks and drawing)\n", played.games,
                played.seconds, played.seconds * 1e6 / options.ticks);
    std::printf("%-44s  %12s  %12s  %s\n", "goal", "measured", "limit", "");
    std::printf("%-44s  %12s  %12s  %s\n", "no NaN or infinity in any object, every tick", "none", "none",
                "met");
    std::printf("%-44s  %12.2f  %12s\n", ("RSS at tick " + std::to_string(options.memFrom) + ", MB").c_str(),
                played.rssBaseline / 1024.0, "");
    std::printf("%-44s  %12.2f  %12s\n", ("RSS at tick " + std::to_string(options.ticks) + ", MB").c_str(),
                played.rssEnd / 1024.0, "");
    std::printf("%-44s  %12.0f  %12.0f  %s\n", "RSS growth between them, KB", v.rssGrowthKb,
                options.rssToleranceKb, v.rssMet ? "met" : "MISSED");
    std::printf("%-44s  %12.2f  %12s\n", "cpu us/step, median of first tenth windows", g.earlyUs, "");
    std::printf("%-44s  %12.2f  %12s\n", "cpu us/step, median of last tenth windows", g.lateUs, "");
    const char* timeVerdict = !options.timeGoal ? "(not a goal here)" : v.timeMet ? "met" : "MISSED";
    std::printf("%-44s  %+11.1f%%  %+11.0f%%  %s\n", "per-step growth, last vs first tenth",
                (g.ratio - 1) * 100, options.timeTolerance * 100, timeVerdict);
    std::printf("%-44s  %+11.1f%%  %+11.0f%%  %s\n", "per-step growth, fitted line over the run",
                g.rise * 100, options.timeTolerance * 100, timeVerdict);
    std::printf("%-44s  %11.1f%%\n", "window-to-window noise (MAD of medians)", g.noise * 100);
    if (kAddressSanitizer)
        std::printf(
            "(AddressSanitizer build: its allocator and quarantine change RSS and times; "
            "figures for the README come from Release)\n");
    return v;
}

bool writePlot(const Played& played, const Options& options) {
    polar::bench::SoakPlot plot;
    plot.title = "soak: " + std::to_string(options.ticks) + " ticks of demo play";
    plot.baselineTick = static_cast<double>(options.memFrom);
    plot.baselineRssMb = played.rssBaseline / 1024.0;
    plot.rssToleranceMb = options.rssToleranceKb / 1024.0;
    for (const Window& w : played.windows)
        plot.points.push_back({static_cast<double>(w.endTick), w.rssKb / 1024.0, w.cpuUs, w.wallUs});
    if (auto error = plot.save(options.plot)) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        return false;
    }
    std::printf("wrote %s\n", options.plot.c_str());
    return true;
}

int run(const Options& options) {
    if (options.memFrom >= options.ticks || options.memFrom < options.window) {
        std::fprintf(stderr,
                     "soak: --mem-from %ld: expected a tick between --window (%d) and --ticks (%ld)\n",
                     options.memFrom, options.window, options.ticks);
        return polar::cli::kBadInput;
    }
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "soak: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const AssetFs assets(*root);
    std::printf(
        "soak: %ld ticks of the demo game, seed %llu, window %d ticks, a frame drawn every %d ticks%s\n",
        options.ticks, static_cast<unsigned long long>(options.seed), options.window, options.drawEvery,
        kAddressSanitizer ? " (AddressSanitizer build)" : "");
    std::fflush(stdout);
    const std::optional<Played> played = play(assets, options);
    if (!played) return 1;

    polar::bench::Csv csv("tick,rss_kb,cpu_us_median,wall_us_median,objects_mean,games,best_wave");
    printWindows(played->windows, options, csv);
    const Growth growth = growthOf(played->windows);
    const Verdict verdict = printGoals(*played, growth, options);
    if (!options.csv.empty() && !csv.write(options.csv)) return 2;
    if (!options.plot.empty() && !writePlot(*played, options)) return 2;
    if (!verdict.rssMet) {
        std::fprintf(stderr,
                     "soak: resident memory grew by %.0f KB between tick %ld and tick %ld (limit %.0f KB)\n",
                     verdict.rssGrowthKb, options.memFrom, options.ticks, options.rssToleranceKb);
        return 1;
    }
    if (options.timeGoal && !verdict.timeMet) {
        std::fprintf(stderr,
                     "soak: per-step time grew beyond %.0f%% (last/first tenth %+.1f%%, fitted %+.1f%%)\n",
                     options.timeTolerance * 100, (growth.ratio - 1) * 100, growth.rise * 100);
        return 1;
    }
    return 0;
}

const polar::bench::Registrar registrar{{
    "soak",
    "The demo game played headless for 10^6 ticks: no NaN, no memory growth, no per-step time growth",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--ticks", options->ticks, "Ticks to play (60 per second of game time)", {1000, 100000000})
            .showDefault();
        sub.option("--mem-from", options->memFrom,
                   "The tick whose resident memory is the baseline for the memory goal", {1, 100000000})
            .showDefault();
        sub.option("--window", options->window, "Ticks per timing window (the median of each is kept)",
                   {100, 1000000})
            .showDefault();
        sub.option("--seed", options->seed, "Seed of the first game and of the pilot's noise").showDefault();
        sub.option("--noise", options->noise,
                   "Share of stretches flown with random buttons instead of the pilot", {0.0, 1.0})
            .showDefault();
        sub.option("--draw-every", options->drawEvery, "Draw a frame every this many ticks (0: never)",
                   {0, 1000000})
            .showDefault();
        sub.option("--rss-tolerance-kb", options->rssToleranceKb,
                   "Largest allowed growth of resident memory after --mem-from, KB", {0.0, 1e9})
            .showDefault();
        sub.option("--time-tolerance", options->timeTolerance,
                   "Largest allowed relative growth of the per-step median (0.2 = 20%)", {0.0, 100.0})
            .showDefault();
        sub.flag("!--no-time-goal", options->timeGoal,
                 "Report per-step time but do not fail on it (for tests on a busy machine)");
        sub.option("--csv", options->csv, "Also write every window (tick,rss_kb,cpu_us_median,...) as CSV")
            .outputFile();
        sub.option("--plot", options->plot, "Also draw RSS and per-step time against ticks into this PNG")
            .outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
