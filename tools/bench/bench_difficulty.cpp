// polarcade-bench difficulty: how hard the game is, as the demo pilot finds it. The pilot (Bot)
// plays --seeds games of each scene, headless, under the newest rules and the default tuning, each
// game to its end or to --max-minutes of game time. Per scene: the median survival, final score and
// wave; per wave: the share of games that reached it, and the median game time and score on
// reaching it. Game time is ticks / 60, never the wall clock.
//
// The games are independent, so they are shared among --threads workers (the engine's ThreadPool);
// each game's figures are stored by its index and summed in that order, so the tables, the CSV and
// the picture are the same at any thread count (a test holds the CSV byte for byte).
#include <atomic>
#include <cmath>
#include <cstdio>
#include <memory>

#include "bench.h"
#include "cli.h"
#include "difficulty_curve.h"
#include "difficulty_plot.h"
#include "files/assets.h"
#include "files/scene_list.h"
#include "polar/tasks.h"
#include "rules/bot.h"

namespace {

using namespace polar;
using namespace polar::game;
using polar::bench::DifficultyCurve;
using polar::bench::GamePlayed;
using polar::bench::WaveFigures;

constexpr double kTicksPerMinute = 60.0 * 60.0;

struct Options {
    int seeds = 50;
    std::uint64_t firstSeed = 1;
    std::vector<std::string> scenes;  // empty: every built-in scene
    double maxMinutes = 15;
    int threads = static_cast<int>(hardwareThreads());
    std::string csv;
    std::string plot;
};

struct Scene {
    std::string name;     // as the tables show it
    std::string logical;  // what Game::Config::scene takes
};

// The scenes to play: --scenes resolved as the game resolves --scene, else every scene in assets/
// (a mod's are left out). An error naming the scenes there are for a name that is none of them.
Result<std::vector<Scene>> chooseScenes(const AssetFs& assets, const Options& options) {
    std::vector<Scene> scenes;
    if (options.scenes.empty()) {
        for (const SceneEntry& entry : listScenes(assets))
            if (entry.mod.empty()) scenes.push_back({entry.name, entry.logical});
        return scenes;
    }
    for (const std::string& name : options.scenes) {
        Result<std::string> logical = resolveScene(assets, name);
        if (!logical) return logical.error();
        scenes.push_back({name, *logical});
    }
    return scenes;
}

Result<Game> startGame(const AssetFs& assets, const Scene& scene, std::uint64_t seed) {
    Game::Config config;  // the newest rules, the default tuning, one thread
    config.scene = scene.logical;
    config.reader = assets.reader();
    config.seed = seed;
    return Game::create(config);
}

// One game of the demo pilot, to its end or to `capTicks`; nothing when the game cannot start (run()
// starts each scene once before the workers begin, so a broken scene file is reported there).
std::optional<GamePlayed> playGame(const AssetFs& assets, const Scene& scene, std::uint64_t seed,
                                   std::uint64_t capTicks) {
    Result<Game> game = startGame(assets, scene, seed);
    if (!game) return std::nullopt;
    Bot bot(seed);
    GamePlayed played;
    auto noteWave = [&] {
        for (int wave = played.wave + 1; wave <= game->wave(); ++wave)
            played.waves.push_back(
                {wave, static_cast<double>(game->tickCount()) / kTicksPerMinute, game->score()});
        played.wave = std::max(played.wave, game->wave());
    };
    noteWave();
    while (!game->over() && game->tickCount() < capTicks) {
        game->tick(bot.decide(*game));
        noteWave();
    }
    played.minutes = static_cast<double>(game->tickCount()) / kTicksPerMinute;
    played.score = game->score();
    played.capped = !game->over();
    return played;
}

// The games to play, seed-major (every scene's first seed, then every scene's second, …), so that
// the long games of a hard scene and the short ones of an easy one are mixed in every worker's share.
struct Job {
    std::size_t scene = 0;
    std::uint64_t seed = 0;
};

struct Work {
    const AssetFs* assets = nullptr;
    const std::vector<Scene>* scenes = nullptr;
    const std::vector<Job>* jobs = nullptr;
    std::uint64_t capTicks = 0;
    std::vector<std::optional<GamePlayed>> results;  // by job
    std::atomic<std::size_t> done{0};
    std::size_t progressEvery = 1;
    polar::bench::Stopwatch clock{polar::bench::CpuClock::None};
};

void playRange(std::uint32_t begin, std::uint32_t end, std::uint32_t, void* context) {
    Work& work = *static_cast<Work*>(context);
    for (std::uint32_t k = begin; k < end; ++k) {
        const Job& job = (*work.jobs)[k];
        work.results[k] = playGame(*work.assets, (*work.scenes)[job.scene], job.seed, work.capTicks);
        const std::size_t done = work.done.fetch_add(1) + 1;
        if (done % work.progressEvery == 0 || done == work.jobs->size())
            std::fprintf(stderr, "difficulty: %zu/%zu games (%.0f%%), %.1f s\n", done, work.jobs->size(),
                         100.0 * done / work.jobs->size(), work.clock.wallMs() / 1e3);
    }
}

void printScenes(const std::vector<Scene>& scenes, const std::vector<DifficultyCurve>& curves) {
    std::printf("\n%-10s %6s %7s %15s %13s %12s %14s\n", "scene", "games", "capped", "median minutes",
                "median score", "median wave", "reach wave 10");
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const DifficultyCurve& c = curves[s];
        const double wave10 = c.waves.size() >= 10 ? c.waves[9].fraction : 0.0;
        std::printf("%-10s %6d %7d %15.2f %13.0f %12.1f %13.0f%%\n", scenes[s].name.c_str(), c.games,
                    c.capped, c.medianMinutes, c.medianScore, c.medianWave, 100 * wave10);
    }
}

void printWaves(const std::vector<Scene>& scenes, const std::vector<DifficultyCurve>& curves,
                polar::bench::Csv& csv) {
    std::printf("\n%-10s %5s %8s %7s %15s %13s\n", "scene", "wave", "reached", "share", "median minutes",
                "median score");
    for (std::size_t s = 0; s < scenes.size(); ++s) {
        const DifficultyCurve& c = curves[s];
        for (const WaveFigures& w : c.waves) {
            std::printf("%-10s %5d %8d %6.0f%% %15.2f %13.0f\n", scenes[s].name.c_str(), w.wave, w.reached,
                        100 * w.fraction, w.medianMinutes, w.medianScore);
            csv.row(scenes[s].name, c.games, c.capped, polar::bench::Fixed{c.medianMinutes, 4}, c.medianScore,
                    c.medianWave, w.wave, w.reached, polar::bench::Fixed{w.fraction, 4},
                    polar::bench::Fixed{w.medianMinutes, 4}, w.medianScore);
        }
    }
}

int run(const Options& options) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "difficulty: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const AssetFs assets(*root);
    Result<std::vector<Scene>> scenes = chooseScenes(assets, options);
    if (!scenes) {
        std::fprintf(stderr, "difficulty: --scenes: %s\n", scenes.error().message().c_str());
        return polar::cli::kBadInput;
    }
    for (const Scene& scene : *scenes)
        if (Result<Game> game = startGame(assets, scene, options.firstSeed); !game) {
            std::fprintf(stderr, "difficulty: %s\n", game.error().message().c_str());
            return 1;
        }

    std::vector<Job> jobs;
    for (int k = 0; k < options.seeds; ++k)
        for (std::size_t s = 0; s < scenes->size(); ++s)
            jobs.push_back({s, options.firstSeed + static_cast<std::uint64_t>(k)});
    std::printf(
        "the demo pilot, %d games per scene (seeds %llu to %llu), newest rules (%d), default tuning, each "
        "game\n"
        "to its end or %.4g minutes of game time; %d thread%s\n",
        options.seeds, static_cast<unsigned long long>(options.firstSeed),
        static_cast<unsigned long long>(options.firstSeed + options.seeds - 1), kRulesVersion,
        options.maxMinutes, options.threads, options.threads == 1 ? "" : "s");
    std::fflush(stdout);

    Work work;
    work.assets = &assets;
    work.scenes = &*scenes;
    work.jobs = &jobs;
    work.capTicks = static_cast<std::uint64_t>(std::llround(options.maxMinutes * kTicksPerMinute));
    work.results.resize(jobs.size());
    work.progressEvery = std::max<std::size_t>(1, jobs.size() / 20);
    const polar::bench::Stopwatch whole(polar::bench::CpuClock::Process);
    {
        ThreadPool pool(static_cast<std::uint32_t>(options.threads));
        runTask(pool, playRange, static_cast<std::uint32_t>(jobs.size()), 1, &work);
    }
    const polar::bench::Lap lap = whole.lap();

    std::vector<std::vector<GamePlayed>> games(scenes->size());
    std::uint64_t ticks = 0;
    for (std::size_t k = 0; k < jobs.size(); ++k) {
        if (!work.results[k]) {
            std::fprintf(stderr, "difficulty: %s, seed %llu: the game did not start\n",
                         (*scenes)[jobs[k].scene].name.c_str(),
                         static_cast<unsigned long long>(jobs[k].seed));
            return 1;
        }
        ticks += static_cast<std::uint64_t>(std::llround(work.results[k]->minutes * kTicksPerMinute));
        games[jobs[k].scene].push_back(std::move(*work.results[k]));
    }
    std::vector<DifficultyCurve> curves;
    for (const std::vector<GamePlayed>& scene : games) curves.push_back(polar::bench::summarizeGames(scene));

    polar::bench::Csv csv(
        "scene,games,capped,median_survival_minutes,median_score,median_wave,wave,reached,fraction_reached,"
        "median_minutes_at_wave,median_score_at_wave");
    printScenes(*scenes, curves);
    printWaves(*scenes, curves, csv);
    std::printf(
        "\nminutes are game time (ticks / 3600); a capped game counts at the cap; the medians at a wave are\n"
        "over the games that reached it. %zu games, %.2f million ticks in %.1f s (%.1f s of CPU)\n",
        jobs.size(), ticks / 1e6, lap.wallMs / 1e3, lap.cpuMs / 1e3);
    if (!options.csv.empty() && !csv.write(options.csv)) return 2;
    if (!options.plot.empty()) {
        polar::bench::DifficultyPlot plot;
        plot.title = "difficulty: the demo pilot, " + std::to_string(options.seeds) + " games per scene";
        plot.capMinutes = options.maxMinutes;
        for (std::size_t s = 0; s < scenes->size(); ++s)
            plot.scenes.push_back({(*scenes)[s].name, std::move(games[s]), curves[s]});
        if (auto error = plot.save(options.plot)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 2;
        }
        std::printf("wrote %s\n", options.plot.c_str());
    }
    return 0;
}

const polar::bench::Registrar registrar{{
    "difficulty",
    "The demo pilot over many seeds per scene: survival, score and waves reached (the difficulty curve)",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--seeds", options->seeds, "Games per scene (seeds --first-seed, --first-seed + 1, ...)",
                   {1, 100000})
            .showDefault();
        sub.option("--first-seed", options->firstSeed, "The first game's seed (the game's and the pilot's)")
            .showDefault();
        sub.option("--scenes", options->scenes,
                   "Scenes to play, by name (\"cave,field\") or file; default: every scene in assets/scenes")
            .delimiter(',');
        sub.option("--max-minutes", options->maxMinutes,
                   "Stop a game still going after this many minutes of game time (it counts at the cap)",
                   {0.05, 1000.0})
            .showDefault();
        sub.option("--threads", options->threads, "Games played at once (the results do not depend on it)",
                   {1, 256})
            .showDefault();
        sub.option("--csv", options->csv,
                   "Also write one row per scene and wave (scene,games,capped,median_survival_minutes,...) "
                   "to this CSV file")
            .outputFile();
        sub.option("--plot", options->plot,
                   "Also draw the survival curve and the share reaching each wave, per scene, into this PNG")
            .outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
