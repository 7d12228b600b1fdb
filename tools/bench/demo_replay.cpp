#include "demo_replay.h"

#include "replay/replay.h"
#include "rules/bot.h"

namespace polar::bench {

std::optional<Error> recordDemo(const std::string& path, const game::AssetFs& assets, std::uint64_t seed,
                                int ticks, int lives) {
    using namespace polar::game;
    Game::Config config;
    config.reader = assets.reader();
    config.seed = seed;
    config.tuning.startLives = lives;
    std::vector<AssetStamp> stamps;
    Result<Game> game = createStampedGame(config, &assets, path, stamps);
    if (!game) return game.error();
    auto writer = ReplayWriter::open(path, headerFor(*game, path, {}, stamps));
    if (!writer) return writer.error();
    Bot bot(seed);
    for (int t = 0; t < ticks; ++t) {
        Actions actions = bot.decide(*game);
        game->tick(actions);
        if (auto error = (*writer)->record(actions, *game)) return error;
    }
    return (*writer)->finish(*game, "ticks");
}

}  // namespace polar::bench
