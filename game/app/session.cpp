#include "app/session.h"

#include <chrono>
#include <cstdio>

namespace polar::game {

Session::Session(Parts parts, std::string scene)
    : context(parts.context),
      options(context.options),
      assets(context.assets),
      sprites(context.sprites),
      tasks(context.pool),
      hotReload(context.hotReload),
      data(parts.data),
      scores(parts.scores),
      recorder(parts.recorder),
      audio(parts.audio),
      input(parts.input),
      window(parts.window),
      scenePath(std::move(scene)) {
    debug = options.showBounds;
}

Result<Game> Session::newGame(std::uint64_t seed, const std::string& scene) const {
    Game::Config config;
    config.scene = scene.empty() ? scenePath : scene;
    config.reader = hotReload.reader();
    config.seed = seed;
    config.threads.tasks = &tasks;
    if (options.lives) config.tuning.startLives = *options.lives;
    Result<Game> made = Game::create(config);
    // Timing reads the clock only to report (the debug overlay); the simulation never sees it.
    if (made) made->world().setTiming(true);
    return made;
}

std::uint64_t Session::freshSeed() const {
    if (options.seed) return *options.seed;
    if (!window) return 1;
    // The seed is the only thing the wall clock ever decides; it is recorded with the game.
    return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) %
           1000000007ull;
}

bool Session::startGame() {
    Result<Game> fresh = newGame(freshSeed());
    if (!fresh) {  // a modder's file broke since the start: say so, stay where the player is
        tell(assets.onDisk(fresh.error()).message());
        return false;
    }
    endGame("restart");
    scores.select(scenePath, modSetOf(options.mods));  // a table per scene and set of mods
    game.emplace(std::move(*fresh));
    recorder.start(*game, assets);
    interpolation.capture(game->world());
    return true;
}

void Session::endGame(std::string_view reason) {
    if (!game) return;
    recorder.finish(*game, reason);
    game.reset();
}

void Session::renewAttract() {
    if (attract && !attract->over()) return;
    Result<Game> again = newGame(freshSeed());
    if (again) attract = std::move(*again);
}

void Session::tickAttract() {
    if (!attract) return;
    advance(*attract, bot.decide(*attract));
    renewAttract();
}

void Session::advance(Game& stepped, Actions actions) {
    interpolation.capture(stepped.world());
    stepped.tick(actions);
    context.tallyStep(stepped);
    particles.spawnFor(stepped.events(), stepped.tickCount());
    particles.tick(1.0 / 60.0);
}

void Session::drawWorld(render::Canvas& canvas, const Game& drawn, double alpha, bool hud) {
    shown = &drawn;
    DrawOptions draw;
    draw.tasks = &tasks;
    draw.hud = hud;
    draw.debugOverlay = debug;
    draw.highScore =
        scores.entries().empty() ? 0 : static_cast<std::uint64_t>(scores.entries().front().score);
    drawGame(canvas, drawn, sprites, interpolation, particles, alpha, draw);
}

bool Session::noticeFresh() const {
    return !notice_.empty() && ticks_ - noticeAt_ < kNoticeTicks;
}

void Session::tell(std::string message) {
    std::fprintf(stderr, "polarcade: %s\n", message.c_str());
    notice_ = std::move(message);
    noticeAt_ = ticks_;
}

}  // namespace polar::game
