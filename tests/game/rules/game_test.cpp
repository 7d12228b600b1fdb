#include "rules/game.h"

#include <gtest/gtest.h>

#include <cmath>

#include "app/hud/game_drawing.h"
#include "files/assets.h"
#include "polar/tasks.h"
#include "rules/bot.h"

namespace polar::game {
namespace {

Game newGame(std::uint64_t seed, const AssetFs& assets) {
    Game::Config config;
    config.reader = assets.reader();
    config.seed = seed;
    Result<Game> game = Game::create(config);
    EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
    return std::move(*game);
}

// Scripted input: sweep round slowly while firing, with a short burst of thrust now and then.
Actions script(std::uint64_t tick) {
    Actions a = kFire;
    if (tick % 90 < 50) a |= kTurnLeft;
    if (tick % 240 < 12) a |= kThrust;
    return a;
}

bool finiteState(const World& world) {
    for (const GameObject& o : world.objects()) {
        const Transform& t = o.transform;
        for (double v :
             {t.position().x(), t.position().y(), t.rotation(), o.velocity.x(), o.velocity.y(), o.spin})
            if (!std::isfinite(v)) return false;
    }
    return true;
}

class GameTest : public ::testing::Test {
  protected:
    AssetFs assets_{POLAR_ASSET_DIR};
};

TEST_F(GameTest, SixHundredScriptedTicksScoreAndSplitRocks) {
    Game game = newGame(1, assets_);
    int splits = 0, shots = 0;
    std::size_t largeRocksAtStart = 0;
    for (const GameObject& o : game.world().objects()) largeRocksAtStart += game.rockSize(o.id) == 3;
    EXPECT_EQ(largeRocksAtStart, 3u) << "wave 1 starts with three large rocks";
    for (std::uint64_t t = 1; t <= 600; ++t) {
        game.tick(script(t));
        for (const GameEvent& e : game.events()) {
            splits += e.type == GameEvent::RockSplit;
            shots += e.type == GameEvent::Shot;
        }
        ASSERT_TRUE(finiteState(game.world())) << "tick " << t;
    }
    EXPECT_EQ(game.tickCount(), 600u);
    EXPECT_GT(shots, 20);
    EXPECT_GT(splits, 0) << "a rock split";
    EXPECT_GT(game.score(), 0) << "the score changed";
    int smaller = 0;
    for (const GameObject& o : game.world().objects())
        smaller += game.rockSize(o.id) == 2 || game.rockSize(o.id) == 1;
    EXPECT_GT(smaller + splits, 0);
}

TEST_F(GameTest, SameSeedAndInputsGiveTheSameGame) {
    Game a = newGame(42, assets_), b = newGame(42, assets_);
    Bot botA(3), botB(3);
    for (int t = 0; t < 900; ++t) {
        a.tick(botA.decide(a));
        b.tick(botB.decide(b));
        ASSERT_EQ(a.hash(), b.hash()) << "tick " << t;
    }
    Game c = newGame(43, assets_);
    EXPECT_NE(c.hash(), newGame(42, assets_).hash()) << "the seed decides where the rocks start";
}

TEST_F(GameTest, OneChangedInputChangesTheFuture) {
    Game a = newGame(5, assets_), b = newGame(5, assets_);
    for (std::uint64_t t = 1; t <= 300; ++t) {
        a.tick(script(t));
        b.tick(t == 100 ? Actions(script(t) | kThrust) : script(t));
    }
    EXPECT_NE(a.hash(), b.hash());
}

TEST_F(GameTest, ShipStaysInsideTheCave) {
    Game game = newGame(9, assets_);
    const GameObject* cave = game.world().findByName("cave");
    ASSERT_NE(cave, nullptr);
    for (std::uint64_t t = 1; t <= 900; ++t) {
        game.tick(kThrust | (t % 200 < 30 ? kTurnLeft : 0));
        const GameObject* ship = game.world().find(game.shipId());
        if (!ship) continue;
        // The container rule keeps the ship's outline inside the wall, measured from the cave's
        // centre toward the ship's radii centre: the penetration never exceeds the response's slop.
        PairTest wall = testObjects(*cave, *ship);
        EXPECT_LE(wall.penetration, 1e-4 * (wall.ra + wall.rb) + 1e-9) << "tick " << t;
    }
}

TEST_F(GameTest, LosingEveryLifeEndsTheGame) {
    Tuning hard;
    hard.startLives = 1;
    hard.invulnerableAfterRespawn = 0;
    Game::Config config;
    config.reader = assets_.reader();
    config.tuning = hard;
    Result<Game> game = Game::create(config);
    ASSERT_TRUE(game.ok());
    // Sit still: a rock finds the ship sooner or later.
    int t = 0;
    for (; t < 60 * 120 && !game->over(); ++t) game->tick(0);
    EXPECT_TRUE(game->over());
    EXPECT_EQ(game->lives(), 0);
    EXPECT_EQ(game->shipId(), 0u);
}

TEST_F(GameTest, AMissingBoundsFileIsOneClearError) {
    Game::Config config;
    config.reader = [&](const std::string& path) -> std::optional<SourceFile> {
        if (path == "sprites/comet.bounds.json") return std::nullopt;
        return assets_.reader()(path);
    };
    Result<Game> game = Game::create(config);
    ASSERT_FALSE(game.ok());
    EXPECT_EQ(game.error().message(),
              "sprites/comet.bounds.json: cannot read the bounds file; expected an existing, readable "
              ".bounds.json file");
}

TEST_F(GameTest, HeadlessFrameShowsTheGame) {
    Game game = newGame(1, assets_);
    for (std::uint64_t t = 1; t <= 120; ++t) game.tick(script(t));
    SpriteCache sprites(assets_);
    Interpolation interpolation;
    Particles particles;
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    drawGame(canvas, game, sprites, interpolation, particles, 1.0, DrawOptions{});
    EXPECT_TRUE(sprites.problems().empty());
    // The cave wall fills the corners; its middle is the dark background with things in it.
    std::map<std::uint32_t, int> colours;
    for (int y = 0; y < canvas.height(); y += 3)
        for (int x = 0; x < canvas.width(); x += 3) ++colours[canvas.pixel(x, y).argb()];
    EXPECT_GT(colours.size(), 50u) << "a real frame, not a blank one";
}

TEST_F(GameTest, AFrameIsTheSameBytesAtEveryThreadCount) {
    Game game = newGame(1, assets_);
    Particles particles;
    Interpolation interpolation;
    for (std::uint64_t t = 1; t <= 240; ++t) {
        interpolation.capture(game.world());
        game.tick(script(t));
        particles.spawnFor(game.events(), game.tickCount());
        particles.tick(1.0 / 60.0);
    }
    SpriteCache sprites(assets_);
    // Everything a frame can hold: sprites between two ticks, particles, the HUD and the overlay.
    DrawOptions options;
    options.debugOverlay = true;
    render::Canvas alone(kScreenWidth, kScreenHeight);
    drawGame(alone, game, sprites, interpolation, particles, 0.4, options);
    for (std::uint32_t workers : {1u, 2u, 3u, 8u}) {
        ThreadPool pool(workers);
        options.tasks = &pool;
        render::Canvas canvas(kScreenWidth, kScreenHeight);
        drawGame(canvas, game, sprites, interpolation, particles, 0.4, options);
        int differing = 0;
        for (int y = 0; y < canvas.height(); ++y)
            for (int x = 0; x < canvas.width(); ++x) differing += canvas.row(y)[x] != alone.row(y)[x];
        EXPECT_EQ(differing, 0) << workers << " threads";
    }
}

}  // namespace
}  // namespace polar::game
