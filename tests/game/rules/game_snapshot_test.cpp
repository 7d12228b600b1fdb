// Game::restore(Game::save()) is the game: on every golden replay, saved at random ticks and
// restored (into a game that went on, and into a fresh one), Game::hash() is the one at the save and
// every tick after gives the straight play's hash, at 1 and 2 workers. The pilot's state rides beside.
// A cut or damaged game snapshot is refused and changes nothing.
#include <gtest/gtest.h>

#include "golden_replays.h"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "files/assets.h"
#include "replay/replay.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

using polar::testing::goldenReplays;

Game startGame(const Replay& replay, const AssetFs& assets, std::uint32_t workers) {
    Game::Config config = configFor(replay, assets);
    config.threads.workers = workers;
    config.threads.parallelMin = 1;
    Result<Game> game = Game::create(config);
    EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
    return std::move(*game);
}

TEST(GameSnapshot, EveryGoldenReplayResumesFromRandomTicksToTheBit) {
    AssetFs assets{POLAR_ASSET_DIR};
    std::vector<std::string> files = goldenReplays();
    ASSERT_GE(files.size(), 3u);  // the cave's three, and one for each newer scene
    Rng pick(27);
    for (const std::string& file : files) {
        Result<Replay> replay = readReplay(file);
        ASSERT_TRUE(replay.ok()) << replay.error().message();
        const std::size_t ticks = replay->actions.size();
        for (std::uint32_t workers : {1u, 2u}) {
            // Straight play: the hash after every tick, and snapshots at random ticks.
            std::vector<std::uint64_t> saveAt;
            for (int k = 0; k < 4; ++k) saveAt.push_back(pick.below(static_cast<std::uint32_t>(ticks)));
            saveAt.push_back(0);
            std::sort(saveAt.begin(), saveAt.end());
            Game game = startGame(*replay, assets, workers);
            std::vector<std::uint64_t> hashes{game.hash()};
            std::vector<GameSnapshot> snapshots;
            for (std::size_t t = 0; t < ticks; ++t) {
                for (std::uint64_t at : saveAt)
                    if (at == t) game.save(snapshots.emplace_back());
                game.tick(replay->actions[t]);
                hashes.push_back(game.hash());
            }
            Game fresh = startGame(*replay, assets, workers);
            for (std::size_t k = 0; k < snapshots.size(); ++k) {
                const std::uint64_t at = saveAt[k];
                // Into the game that played to the end, and into one that never ticked.
                for (Game* target : {&game, &fresh}) {
                    std::optional<Error> error = target->restore(snapshots[k]);
                    ASSERT_FALSE(error) << error->message();
                    ASSERT_EQ(target->hash(), hashes[at]) << file << " restored at tick " << at;
                    ASSERT_EQ(target->tickCount(), at);
                    std::size_t end = std::min<std::size_t>(ticks, at + 400);
                    for (std::size_t t = at; t < end; ++t) {
                        target->tick(replay->actions[t]);
                        ASSERT_EQ(target->hash(), hashes[t + 1])
                            << file << " at " << workers << " workers, restored at " << at << ", tick "
                            << t + 1;
                    }
                }
            }
        }
    }
}

TEST(GameSnapshot, ThePilotResumesWithTheGame) {
    AssetFs assets{POLAR_ASSET_DIR};
    Result<Replay> replay = readReplay(goldenReplays().front());
    ASSERT_TRUE(replay.ok());
    Game game = startGame(*replay, assets, 1);
    Bot bot(3);
    for (int t = 0; t < 200; ++t) game.tick(bot.decide(game));
    GameSnapshot snapshot;
    game.save(snapshot);
    std::uint64_t pilot = bot.state();
    std::vector<std::uint64_t> straight;
    for (int t = 0; t < 300; ++t) {
        game.tick(bot.decide(game));
        straight.push_back(game.hash());
    }
    ASSERT_FALSE(game.restore(snapshot));
    bot.restore(pilot);
    for (int t = 0; t < 300; ++t) {
        game.tick(bot.decide(game));
        ASSERT_EQ(game.hash(), straight[static_cast<std::size_t>(t)]) << "tick " << t;
    }
}

TEST(GameSnapshot, ACutOrDamagedSnapshotIsRefusedAndChangesNothing) {
    AssetFs assets{POLAR_ASSET_DIR};
    Result<Replay> replay = readReplay(goldenReplays().front());
    ASSERT_TRUE(replay.ok());
    Game game = startGame(*replay, assets, 1);
    for (int t = 0; t < 300; ++t) game.tick(replay->actions[static_cast<std::size_t>(t)]);
    GameSnapshot good;
    game.save(good);
    Game other = startGame(*replay, assets, 1);
    for (int t = 0; t < 50; ++t) other.tick(replay->actions[static_cast<std::size_t>(t)]);
    const std::uint64_t before = other.hash();
    for (std::size_t cut = 0; cut < good.bytes.size(); ++cut) {
        GameSnapshot bad = good;
        bad.bytes.resize(cut);
        bad.bytes.shrink_to_fit();
        ASSERT_TRUE(other.restore(bad)) << "game part cut to " << cut;
    }
    for (std::size_t cut = 0; cut < good.world.bytes.size(); cut += 5) {
        GameSnapshot bad = good;
        bad.world.bytes.resize(cut);
        bad.world.bytes.shrink_to_fit();
        ASSERT_TRUE(other.restore(bad)) << "world part cut to " << cut;
    }
    for (std::size_t at = 0; at < good.bytes.size(); ++at) {
        GameSnapshot bad = good;
        bad.bytes[at] ^= 0x10;
        ASSERT_TRUE(other.restore(bad)) << "byte " << at << " changed";
    }
    EXPECT_EQ(other.hash(), before);
    ASSERT_FALSE(other.restore(good));
    EXPECT_EQ(other.hash(), game.hash());
}

}  // namespace
}  // namespace polar::game
