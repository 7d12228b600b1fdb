#include "app/run/headless_run.h"

#include <csignal>
#include <cstdio>
#include <map>

#include "app/hud/game_drawing.h"
#include "app/hud/overlays.h"
#include "polar/platform/image_file.h"
#include "replay/replay.h"
#include "rules/bot.h"

namespace polar::game {
namespace {

constexpr double kTickSeconds = 1.0 / 60.0;

// Set by SIGINT or SIGTERM during a headless run; the loop looks at it between ticks. A signal
// handler may only touch a volatile sig_atomic_t, so that is all it does.
volatile std::sig_atomic_t interruptRequested = 0;

void requestInterrupt(int) {
    interruptRequested = 1;
}

// Catches SIGINT and SIGTERM for its lifetime, then puts the previous handlers back.
class InterruptCatcher {
  public:
    InterruptCatcher() {
        interruptRequested = 0;
        previousInt_ = std::signal(SIGINT, requestInterrupt);
        previousTerm_ = std::signal(SIGTERM, requestInterrupt);
    }
    ~InterruptCatcher() {
        std::signal(SIGINT, previousInt_ == SIG_ERR ? SIG_DFL : previousInt_);
        std::signal(SIGTERM, previousTerm_ == SIG_ERR ? SIG_DFL : previousTerm_);
    }
    InterruptCatcher(const InterruptCatcher&) = delete;
    InterruptCatcher& operator=(const InterruptCatcher&) = delete;
    bool interrupted() const { return interruptRequested != 0; }

  private:
    void (*previousInt_)(int) = SIG_DFL;
    void (*previousTerm_)(int) = SIG_DFL;
};

}  // namespace

std::optional<Error> screenshotNotReached(const AppOptions& options, std::uint64_t first, std::uint64_t last,
                                          const std::string& limit) {
    for (const auto& [tick, file] : options.screenshots) {
        if (tick >= first && tick <= last) continue;
        const std::string range = std::to_string(first) + " to " + std::to_string(last);
        return Error{"", 0, 0,
                     "polarcade: --screenshot " + std::to_string(tick) + ":" + file + ": tick " +
                         std::to_string(tick) + " is never played (" + limit + ")",
                     "a tick from " + range};
    }
    return std::nullopt;
}

int runHeadless(AppContext& context, const std::string& scenePath, std::int64_t ticks, bool announce,
                bool recordIntoData) {
    const AppOptions& options = context.options;
    Game::Config config;
    config.scene = scenePath;
    config.reader = context.hotReload.reader();
    config.seed = options.seed.value_or(1);
    config.threads.tasks = &context.pool;
    if (options.lives) config.tuning.startLives = *options.lives;
    Result<Game> game = Game::create(config);
    if (!game) return context.fail(game.error());
    // Timing reads the clock only to report; the simulation never sees it.
    game->world().setTiming(options.stats || options.showBounds);
    Bot bot(game->seed());
    // With --data DIR the game is also kept in DIR/replays/, as a windowed game would be.
    std::string replays;
    if (recordIntoData && context.dataFolder().writable()) replays = context.dataFolder().path + "replays";
    GameRecorder recorder({options.record, replays, 20, options.mods, {}});
    recorder.start(*game, context.assets);
    // Every picture is read now, so a missing or corrupt one is reported even when no frame is
    // drawn (it would be drawn as a magenta box).
    for (const std::string& sprite : game->spritePaths()) context.sprites.get(sprite);
    context.reportSpriteProblems();
    // SIGINT or SIGTERM ends the run between two ticks, with the recordings finished.
    InterruptCatcher interrupt;
    Interpolation interpolation;
    Particles particles;
    std::map<std::uint64_t, std::vector<std::string>> shots;
    for (auto& [tick, file] : options.screenshots) shots[tick].push_back(file);
    for (std::int64_t t = 1; t <= ticks; ++t) {
        if (interrupt.interrupted()) {
            std::fflush(stdout);
            std::fprintf(stderr, "polarcade: interrupted after tick %lld\n", static_cast<long long>(t - 1));
            recorder.finish(*game, "interrupted");
            context.printStats();
            std::fflush(stdout);
            return kInterruptedExitCode;
        }
        context.reloadBetweenTicks({&*game}, false);
        Actions actions = bot.decide(*game);
        game->tick(actions);
        context.tallyStep(*game);
        recorder.record(actions, *game);
        particles.spawnFor(game->events(), game->tickCount());
        particles.tick(kTickSeconds);
        auto due = shots.find(static_cast<std::uint64_t>(t));
        if (due == shots.end()) continue;
        DrawOptions draw;
        draw.tasks = &context.pool;
        draw.debugOverlay = options.showBounds;
        drawGame(context.canvas, *game, context.sprites, interpolation, particles, 1.0, draw);
        OverlayContent overlays;
        if (options.showBounds) overlays.debugWorld = &game->world();
        overlays.effectMs = &context.effectMs;
        overlays.reload = &context.hotReload;
        drawOverlays(context.canvas, overlays);
        context.reportSpriteProblems();
        for (const std::string& file : due->second) {
            if (auto error = render::savePng(context.canvas, file)) return context.fail(*error);
            if (announce) std::printf("saved tick %lld to %s\n", static_cast<long long>(t), file.c_str());
        }
    }
    recorder.finish(*game, "ticks");
    context.printStats();
    return 0;
}

}  // namespace polar::game
