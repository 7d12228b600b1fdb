#include "app/screens/games.h"

#include <chrono>

namespace polar::game {

Games::Games(Parts parts, std::string scene)
    : scenePath(std::move(scene)),
      context_(parts.context),
      scores_(parts.scores),
      recorder_(parts.recorder),
      notice_(parts.notice),
      scripted_(parts.scripted) {}

Result<Game> Games::make(std::uint64_t seed, const std::string& scene, int gameSpeed) const {
    Game::Config config;
    config.scene = scene.empty() ? scenePath : scene;
    config.speed = gameSpeed;
    config.reader = context_.hotReload.reader();
    config.seed = seed;
    config.threads.tasks = &context_.pool;
    if (context_.options.lives) config.tuning.startLives = *context_.options.lives;
    Result<Game> made = Game::create(config);
    // Timing reads the clock only to report (the debug overlay); the simulation never sees it.
    if (made) made->world().setTiming(true);
    return made;
}

std::uint64_t Games::freshSeed() const {
    if (context_.options.seed) return *context_.options.seed;
    if (scripted_) return 1;
    // The seed is the only thing the wall clock ever decides; it is recorded with the game.
    return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) %
           1000000007ull;
}

bool Games::startGame() {
    Result<Game> fresh = make(freshSeed(), {}, speed);
    if (!fresh) {  // a modder's file broke since the start: say so, stay where the player is
        notice_.tell(context_.assets.onDisk(fresh.error()).message());
        return false;
    }
    endGame("restart");
    // A table per scene, set of mods and game speed.
    scores_.select(scenePath, modSetOf(context_.options.mods), speed);
    player.emplace(std::move(*fresh));
    recorder_.start(*player, context_.assets);
    interpolation.capture(player->world());
    return true;
}

void Games::endGame(std::string_view reason) {
    if (!player) return;
    recorder_.finish(*player, reason);
    player.reset();
}

void Games::renewAttract() {
    if (attract && !attract->over()) return;
    Result<Game> again = make(freshSeed());
    if (again) attract = std::move(*again);
}

void Games::tickAttract() {
    if (!attract) return;
    advance(*attract, bot.decide(*attract));
    renewAttract();
}

void Games::advance(Game& stepped, Actions actions) {
    interpolation.capture(stepped.world());
    stepped.tick(actions);
    context_.tallyStep(stepped);
    particles.spawnFor(stepped.events(), stepped.tickCount());
    particles.tick(1.0 / 60.0);
}

}  // namespace polar::game
