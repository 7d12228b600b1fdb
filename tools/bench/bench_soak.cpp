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
#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "app/draw.h"
#include "bench.h"
#include "cli.h"
#include "files/assets.h"
#include "polar/atomic_file.h"
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

// Resident memory in KiB, from /proc/self/statm (second field, in pages). Reads into a stack
// buffer, so measuring allocates nothing.
long residentKb() {
    int fd = ::open("/proc/self/statm", O_RDONLY);
    if (fd < 0) return -1;
    char buffer[128];
    ssize_t n = ::read(fd, buffer, sizeof buffer - 1);
    ::close(fd);
    if (n <= 0) return -1;
    buffer[n] = '\0';
    long size = 0, resident = 0;
    if (std::sscanf(buffer, "%ld %ld", &size, &resident) != 2) return -1;
    return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

double threadCpuNs() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec * 1e9 + t.tv_nsec;
}

double median(std::vector<double>& v, std::size_t n) {
    std::nth_element(v.begin(), v.begin() + n / 2, v.begin() + n);
    return v[n / 2];
}

double medianOf(std::vector<double> v) {
    return v.empty() ? 0.0 : median(v, v.size());
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
    AssetFs assets(*root);
    int games = 1;
    std::optional<Game> game = newGame(assets, options.seed);
    if (!game) return 1;
    NoisyPilot pilot(options.seed, options.noise);
    Particles particles;
    SpriteCache sprites(assets);
    render::Canvas canvas(kScreenWidth, kScreenHeight);

    const std::size_t windowCount = static_cast<std::size_t>(options.ticks / options.window);
    std::vector<Window> windows;
    windows.reserve(windowCount + 1);
    std::vector<double> cpu(options.window), wall(options.window);
    double objectSum = 0;
    long rssBaseline = -1;
    int bestWave = 0;
    const int drawEvery = options.drawEvery;
    std::printf(
        "soak: %ld ticks of the demo game, seed %llu, window %d ticks, a frame drawn every %d ticks%s\n",
        options.ticks, static_cast<unsigned long long>(options.seed), options.window, drawEvery,
        kAddressSanitizer ? " (AddressSanitizer build)" : "");
    std::fflush(stdout);
    const auto start = std::chrono::steady_clock::now();
    const long progressEvery = std::max<long>(options.window, options.ticks / 10);

    for (long tick = 1; tick <= options.ticks; ++tick) {
        Actions actions = pilot.decide(*game);
        const auto wallStart = std::chrono::steady_clock::now();
        const double cpuStart = threadCpuNs();
        game->tick(actions);
        particles.spawnFor(game->events(), game->tickCount());
        particles.tick(1.0 / 60);
        const double cpuNs = threadCpuNs() - cpuStart;
        const double wallNs =
            std::chrono::duration<double, std::nano>(std::chrono::steady_clock::now() - wallStart).count();
        const std::size_t slot = static_cast<std::size_t>((tick - 1) % options.window);
        cpu[slot] = cpuNs / 1e3;
        wall[slot] = wallNs / 1e3;
        objectSum += static_cast<double>(game->world().objects().size());

        for (const GameObject& o : game->world().objects()) {
            if (const char* field = nonFiniteField(o)) {
                std::fprintf(
                    stderr, "soak: tick %ld (game %d, its tick %llu): object %u \"%s\" has a non-finite %s\n",
                    tick, games, static_cast<unsigned long long>(game->tickCount()), o.id, o.name.c_str(),
                    field);
                return 1;
            }
        }
        if (drawEvery > 0 && tick % drawEvery == 0)
            drawGame(canvas, *game, sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        bestWave = std::max(bestWave, game->wave());
        if (game->over()) {
            ++games;
            game = newGame(assets, options.seed + static_cast<std::uint64_t>(games - 1));
            if (!game) return 1;
        }
        if (tick % options.window == 0) {
            Window w;
            w.endTick = tick;
            w.rssKb = residentKb();
            w.cpuUs = median(cpu, cpu.size());
            w.wallUs = median(wall, wall.size());
            w.objects = objectSum / options.window;
            w.games = games;
            w.bestWave = bestWave;
            windows.push_back(w);
            objectSum = 0;
            if (tick == options.memFrom) rssBaseline = w.rssKb;
        }
        if (tick == options.memFrom && rssBaseline < 0) rssBaseline = residentKb();
        if (tick % progressEvery == 0) {
            double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            std::fprintf(stderr, "soak: %ld/%ld ticks (%.0f%%), %.1f s, RSS %.2f MB, %d games\n", tick,
                         options.ticks, 100.0 * tick / options.ticks, seconds, residentKb() / 1024.0, games);
        }
    }
    const long rssEnd = residentKb();
    const double totalSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // The table: windows at 1, 2, 5 × 10^k ticks, the baseline and the end.
    std::printf("\n%10s  %9s  %11s  %12s  %9s  %6s  %9s\n", "tick", "RSS MB", "cpu us/step", "wall us/step",
                "objects", "games", "best wave");
    auto shown = [&](long t) {
        if (t == options.memFrom || t == options.ticks) return true;
        while (t % 10 == 0) t /= 10;
        return t == 1 || t == 2 || t == 5;
    };
    std::ostringstream csv;
    csv << "tick,rss_kb,cpu_us_median,wall_us_median,objects_mean,games,best_wave\n";
    for (const Window& w : windows) {
        if (shown(w.endTick))
            std::printf("%10ld  %9.2f  %11.2f  %12.2f  %9.1f  %6d  %9d\n", w.endTick, w.rssKb / 1024.0,
                        w.cpuUs, w.wallUs, w.objects, w.games, w.bestWave);
        csv << w.endTick << ',' << w.rssKb << ',' << w.cpuUs << ',' << w.wallUs << ',' << w.objects << ','
            << w.games << ',' << w.bestWave << '\n';
    }

    // Per-step time: first tenth of the windows against the last tenth, and the fitted line.
    const std::size_t n = windows.size(), k = std::max<std::size_t>(1, n / 10);
    std::vector<double> early, late, all;
    for (std::size_t i = 0; i < n; ++i) {
        all.push_back(windows[i].cpuUs);
        if (i < k) early.push_back(windows[i].cpuUs);
        if (i >= n - k) late.push_back(windows[i].cpuUs);
    }
    const double earlyUs = medianOf(early), lateUs = medianOf(late), allUs = medianOf(all);
    // Least squares y = a + b·t over the window medians; rise = b·(t_last − t_first) / mean(y).
    double tMean = 0, yMean = 0;
    for (const Window& w : windows) tMean += w.endTick, yMean += w.cpuUs;
    tMean /= std::max<std::size_t>(1, n), yMean /= std::max<std::size_t>(1, n);
    double stt = 0, sty = 0;
    for (const Window& w : windows)
        stt += (w.endTick - tMean) * (w.endTick - tMean), sty += (w.endTick - tMean) * (w.cpuUs - yMean);
    const double slope = stt > 0 ? sty / stt : 0;  // µs per tick
    const double rise = n > 1 ? slope * (windows.back().endTick - windows.front().endTick) / yMean : 0;
    // Window-to-window noise: the median absolute deviation of the window medians, relative.
    std::vector<double> deviations;
    for (double y : all) deviations.push_back(std::fabs(y - allUs));
    const double noise = allUs > 0 ? medianOf(deviations) / allUs : 0;

    const double rssGrowthKb = static_cast<double>(rssEnd - rssBaseline);
    const bool rssMet = rssBaseline > 0 && rssGrowthKb <= options.rssToleranceKb;
    const double ratio = earlyUs > 0 ? lateUs / earlyUs : 0;
    const bool timeMet = ratio - 1 <= options.timeTolerance && rise <= options.timeTolerance;

    std::printf("\n%d games, %.1f s in all (%.2f us per tick including checks and drawing)\n", games,
                totalSeconds, totalSeconds * 1e6 / options.ticks);
    std::printf("%-44s  %12s  %12s  %s\n", "goal", "measured", "limit", "");
    std::printf("%-44s  %12s  %12s  %s\n", "no NaN or infinity in any object, every tick", "none", "none",
                "met");
    std::printf("%-44s  %12.2f  %12s\n", ("RSS at tick " + std::to_string(options.memFrom) + ", MB").c_str(),
                rssBaseline / 1024.0, "");
    std::printf("%-44s  %12.2f  %12s\n", ("RSS at tick " + std::to_string(options.ticks) + ", MB").c_str(),
                rssEnd / 1024.0, "");
    std::printf("%-44s  %12.0f  %12.0f  %s\n", "RSS growth between them, KB", rssGrowthKb,
                options.rssToleranceKb, rssMet ? "met" : "MISSED");
    std::printf("%-44s  %12.2f  %12s\n", "cpu us/step, median of first tenth windows", earlyUs, "");
    std::printf("%-44s  %12.2f  %12s\n", "cpu us/step, median of last tenth windows", lateUs, "");
    const char* timeVerdict = !options.timeGoal ? "(not a goal here)" : timeMet ? "met" : "MISSED";
    std::printf("%-44s  %+11.1f%%  %+11.0f%%  %s\n", "per-step growth, last vs first tenth",
                (ratio - 1) * 100, options.timeTolerance * 100, timeVerdict);
    std::printf("%-44s  %+11.1f%%  %+11.0f%%  %s\n", "per-step growth, fitted line over the run", rise * 100,
                options.timeTolerance * 100, timeVerdict);
    std::printf("%-44s  %11.1f%%\n", "window-to-window noise (MAD of medians)", noise * 100);
    if (kAddressSanitizer)
        std::printf(
            "(AddressSanitizer build: its allocator and quarantine change RSS and times; "
            "figures for the README come from Release)\n");

    if (!options.csv.empty()) {
        if (auto error = writeFileAtomically(options.csv, csv.str())) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 2;
        }
        std::printf("wrote %s\n", options.csv.c_str());
    }
    if (!options.plot.empty()) {
        polar::bench::SoakPlot plot;
        plot.title = "soak: " + std::to_string(options.ticks) + " ticks of demo play";
        plot.baselineTick = static_cast<double>(options.memFrom);
        plot.baselineRssMb = rssBaseline / 1024.0;
        plot.rssToleranceMb = options.rssToleranceKb / 1024.0;
        for (const Window& w : windows)
            plot.points.push_back({static_cast<double>(w.endTick), w.rssKb / 1024.0, w.cpuUs, w.wallUs});
        if (auto error = plot.save(options.plot)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 2;
        }
        std::printf("wrote %s\n", options.plot.c_str());
    }
    if (!rssMet) {
        std::fprintf(stderr,
                     "soak: resident memory grew by %.0f KB between tick %ld and tick %ld (limit %.0f KB)\n",
                     rssGrowthKb, options.memFrom, options.ticks, options.rssToleranceKb);
        return 1;
    }
    if (options.timeGoal && !timeMet) {
        std::fprintf(stderr,
                     "soak: per-step time grew beyond %.0f%% (last/first tenth %+.1f%%, fitted %+.1f%%)\n",
                     options.timeTolerance * 100, (ratio - 1) * 100, rise * 100);
        return 1;
    }
    return 0;
}

const polar::bench::Registrar registrar{{
    "soak",
    "The demo game played headless for 10^6 ticks: no NaN, no memory growth, no per-step time growth",
    [](CLI::App& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.add_option("--ticks", options->ticks, "Ticks to play (60 per second of game time)")
            ->check(CLI::Range(1000L, 100000000L))
            ->capture_default_str();
        sub.add_option("--mem-from", options->memFrom,
                       "The tick whose resident memory is the baseline for the memory goal")
            ->check(CLI::Range(1L, 100000000L))
            ->capture_default_str();
        sub.add_option("--window", options->window, "Ticks per timing window (the median of each is kept)")
            ->check(CLI::Range(100, 1000000))
            ->capture_default_str();
        sub.add_option("--seed", options->seed, "Seed of the first game and of the pilot's noise")
            ->capture_default_str();
        sub.add_option("--noise", options->noise,
                       "Share of stretches flown with random buttons instead of the pilot")
            ->check(CLI::Range(0.0, 1.0))
            ->capture_default_str();
        sub.add_option("--draw-every", options->drawEvery, "Draw a frame every this many ticks (0: never)")
            ->check(CLI::Range(0, 1000000))
            ->capture_default_str();
        sub.add_option("--rss-tolerance-kb", options->rssToleranceKb,
                       "Largest allowed growth of resident memory after --mem-from, KB")
            ->check(CLI::Range(0.0, 1e9))
            ->capture_default_str();
        sub.add_option("--time-tolerance", options->timeTolerance,
                       "Largest allowed relative growth of the per-step median (0.2 = 20%)")
            ->check(CLI::Range(0.0, 100.0))
            ->capture_default_str();
        sub.add_flag("!--no-time-goal", options->timeGoal,
                     "Report per-step time but do not fail on it (for tests on a busy machine)");
        sub.add_option("--csv", options->csv,
                       "Also write every window (tick,rss_kb,cpu_us_median,...) as CSV");
        sub.add_option("--plot", options->plot,
                       "Also draw RSS and per-step time against ticks into this PNG");
        return [options] { return run(*options); };
    },
}};

}  // namespace
