#include "app/screens/session.h"

namespace polar::game {

Session::Session(Parts parts, std::string scene)
    : context(parts.context),
      scores(parts.scores),
      recorder(parts.recorder),
      audio(parts.audio),
      input(parts.input),
      window(parts.window),
      games({context, scores, recorder, notice, window == nullptr}, std::move(scene)) {
    debug = context.options.showBounds;
}

void Session::follow(const Settings& settings) {
    preferences = settings;
    showFrameTime = settings.showFrameTime;
    effects = EffectLevels{settings.screenShake, settings.flashes};
    holdFire = settings.holdFire;
    games.speed = settings.gameSpeed;
}

void Session::drawWorld(render::Canvas& canvas, const Game& drawn, double alpha, bool hud) {
    DrawOptions draw;
    draw.tasks = &context.pool;
    draw.hud = hud;
    draw.debugOverlay = debug;
    draw.effects = effects;
    draw.highScore =
        scores.entries().empty() ? 0 : static_cast<std::uint64_t>(scores.entries().front().score);
    drawGame(canvas, drawn, context.sprites, games.interpolation, games.particles, alpha, draw);
}

}  // namespace polar::game
