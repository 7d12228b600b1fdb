// polarcade-bench looks: how long a frame takes to draw in each scene with its backdrop, at its
// busiest. The demo pilot plays each built-in scene (99 lives, so it keeps flying); the busiest
// tick is the one with the most objects and particles. The game is then played again to a second
// before that tick, and the next two seconds are drawn as the game draws them (drawGame: backdrop,
// every effect at full, the HUD; 640×360, one thread, headless), each frame twice in turn: with its
// backdrop and with the plain one, so the backdrop's cost is measured side by side.
#include <cstdio>

#include "app/hud/backdrop.h"
#include "app/hud/game_drawing.h"
#include "bench.h"
#include "cli.h"
#include "files/assets.h"
#include "files/scene_list.h"
#include "rules/bot.h"

namespace {

using namespace polar;
using namespace polar::game;
using polar::bench::Summary;

struct Options {
    int ticks = 18000;
    std::uint64_t seed = 16;
    std::string csv;
};

Result<Game> startGame(const AssetFs& assets, const std::string& scene, const Options& options) {
    Game::Config config;
    config.scene = scene;
    config.reader = assets.reader();
    config.seed = options.seed;
    config.tuning.startLives = 99;
    return Game::create(config);
}

// One scene's figures.
struct SceneFigures {
    std::string name;
    std::uint64_t busiestTick = 0;
    int wave = 0;
    std::size_t objects = 0, particles = 0;
    polar::bench::Timings withBackdrop, plain;
};

std::optional<Error> measure(const AssetFs& assets, SpriteCache& sprites, const SceneEntry& scene,
                             const Options& options, SceneFigures& figures) {
    figures.name = scene.name;
    // The first play finds the busiest tick.
    {
        Result<Game> game = startGame(assets, scene.logical, options);
        if (!game) return game.error();
        Bot bot(options.seed);
        Particles particles;
        std::size_t most = 0;
        for (int t = 0; t < options.ticks && !game->over(); ++t) {
            game->tick(bot.decide(*game));
            particles.spawnFor(game->events(), game->tickCount());
            particles.tick(1.0 / 60.0);
            const std::size_t busy = game->world().objects().size() * 8 + particles.size();
            if (busy > most) {
                most = busy;
                figures.busiestTick = game->tickCount();
                figures.wave = game->wave();
                figures.objects = game->world().objects().size();
                figures.particles = particles.size();
            }
        }
    }
    // The second play draws the two seconds around it.
    Result<Game> game = startGame(assets, scene.logical, options);
    if (!game) return game.error();
    Bot bot(options.seed);
    Particles particles;
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    DrawOptions withBackdrop, plain;
    plain.backdrop = false;
    const std::uint64_t from = figures.busiestTick > 60 ? figures.busiestTick - 60 : 0;
    drawGame(canvas, *game, sprites, Interpolation{}, particles, 1.0,
             withBackdrop);  // warm: sprites, pictures
    while (game->tickCount() < from + 120 && !game->over()) {
        game->tick(bot.decide(*game));
        particles.spawnFor(game->events(), game->tickCount());
        particles.tick(1.0 / 60.0);
        if (game->tickCount() < from) continue;
        polar::bench::timeInto(figures.withBackdrop, polar::bench::CpuClock::Thread, [&] {
            drawGame(canvas, *game, sprites, Interpolation{}, particles, 1.0, withBackdrop);
        });
        polar::bench::timeInto(figures.plain, polar::bench::CpuClock::Thread, [&] {
            drawGame(canvas, *game, sprites, Interpolation{}, particles, 1.0, plain);
        });
    }
    return std::nullopt;
}

int run(const Options& options) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "looks: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const AssetFs assets(*root);
    SpriteCache sprites(assets);
    std::printf(
        "each scene's busiest two seconds in %d ticks of the demo pilot (seed %llu, 99 lives), drawn at\n"
        "640x360, 1 thread, headless, every effect at full; each frame with its backdrop and plain, in "
        "turn\n",
        options.ticks, static_cast<unsigned long long>(options.seed));
    std::printf("%-8s %-10s %6s %5s %8s %10s %9s %9s %9s %9s  %s\n", "scene", "backdrop", "tick", "wave",
                "objects", "particles", "median ms", "cpu ms", "worst ms", "plain ms", "goal 2 ms");
    polar::bench::Csv csv(
        "scene,backdrop,tick,wave,objects,particles,median_ms,cpu_median_ms,worst_ms,plain_median_ms");
    bool met = true;
    for (const SceneEntry& scene : listScenes(assets)) {
        if (!scene.mod.empty()) continue;
        SceneFigures f;
        if (std::optional<Error> error = measure(assets, sprites, scene, options, f)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 1;
        }
        Result<Game> game = startGame(assets, scene.logical, options);
        const char* backdrop = game ? backdropName(backdropOf(*game)) : "?";
        const Summary wall = f.withBackdrop.wall(), cpu = f.withBackdrop.cpu(), plain = f.plain.wall();
        met = met && wall.median <= 2.0;
        std::printf("%-8s %-10s %6llu %5d %8zu %10zu %9.3f %9.3f %9.3f %9.3f  %s\n", f.name.c_str(), backdrop,
                    static_cast<unsigned long long>(f.busiestTick), f.wave, f.objects, f.particles,
                    wall.median, cpu.median, wall.worst, plain.median, wall.median <= 2.0 ? "met" : "MISSED");
        csv.row(f.name, backdrop, f.busiestTick, f.wave, f.objects, f.particles, wall.median, cpu.median,
                wall.worst, plain.median);
    }
    std::printf("median and worst of the frames on the wall clock; cpu: the drawing thread's own time\n");
    // A strike may fall outside the storm's busiest two seconds: its cost on its own, the storm's
    // backdrop drawn alone on 120 ticks at a strike's brightest and 120 unlit ones, in turn.
    std::uint64_t lit = 0, dark = 0;
    for (std::uint64_t t = 0; lit == 0 || dark == 0; ++t) {
        if (lit == 0 && lightningAt(options.seed, t, 0) >= 0.99) lit = t;
        if (dark == 0 && t > 120 && lightningAt(options.seed, t, 0) == 0) dark = t;
    }
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    render::DrawList list;
    polar::bench::Timings litTimes, darkTimes;
    for (int k = 0; k < 120; ++k)
        for (auto [tick, times] : {std::pair{lit, &litTimes}, std::pair{dark, &darkTimes}})
            polar::bench::timeInto(*times, polar::bench::CpuClock::Thread, [&] {
                list.reset();
                drawBackdrop(list, canvas.width(), canvas.height(), Backdrop::Storm, options.seed, tick, 0,
                             EffectLevels{});
                list.draw(canvas);
            });
    std::printf("the storm's backdrop alone: %.3f ms at a strike's brightest, %.3f ms unlit (medians)\n",
                litTimes.wall().median, darkTimes.wall().median);
    if (!options.csv.empty() && !csv.write(options.csv)) return 1;
    return met ? 0 : 1;
}

const polar::bench::Registrar registrar{{
    "looks",
    "A frame of each scene at its busiest, with its backdrop and every effect, 1 thread (goal 2 ms)",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--ticks", options->ticks, "Ticks of demo play in which to find the busiest moment",
                   {120, 1000000})
            .showDefault();
        sub.option("--seed", options->seed, "The demo game's seed").showDefault();
        sub.option("--csv", options->csv,
                   "Also write scene,backdrop,tick,wave,objects,particles,median_ms,cpu_median_ms,worst_ms,"
                   "plain_median_ms to this CSV file")
            .outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
