// The game's rules as a player sees them (README.md, "Playing"; game/rules/game.h): the points for
// each kind of shot, the lives (lost, won back by pickups and every extraLifeEvery points), the
// protection after a respawn and under a shield, the waves, and a shot rock splitting in two one
// size down. Each tick of a long demo game is checked against its own events, and a few moments
// are set up by hand (a rock placed on a bullet's path).
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "files/assets.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::game {
namespace {

// The points a shot earns (README.md: a comet is worth 250); a rock's by its size.
constexpr int kPointsForComet = 250;
int pointsForRock(int size) {
    switch (size) {
        case 3:
            return 20;  // large
        case 2:
            return 50;  // medium
        case 1:
            return 100;  // small
        default:
            ADD_FAILURE() << "a rock of size " << size;
            return 0;
    }
}

Game rulesGame(const AssetFs& assets, std::uint64_t seed, const Tuning& tuning) {
    Game::Config config;
    config.reader = assets.reader();
    config.seed = seed;
    config.tuning = tuning;
    Result<Game> game = Game::create(config);
    EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
    return std::move(*game);
}

std::map<int, int> rocksBySize(const Game& game) {
    std::map<int, int> sizes;
    for (const GameObject& o : game.world().objects())
        if (game.kindOf(o.id) == Kind::Rock) ++sizes[game.rockSize(o.id)];
    return sizes;
}

// What a long game did, counted so that a test can say its rule was exercised.
struct Seen {
    int ticks = 0, rockShots[4] = {}, cometShots = 0, extraLives = 0, lifePickups = 0, shipHits = 0;
    int exactMultiples = 0;    // ticks whose score ended exactly on a multiple of extraLifeEvery
    int protectedTouches = 0;  // ticks a protected ship touched a rock or a comet
    int waves = 0;
    int comets = 0;  // comet-ticks
    bool over = false;

    std::string describe() const {
        return std::to_string(ticks) + " ticks: rocks shot (small, medium, large) " +
               std::to_string(rockShots[1]) + ", " + std::to_string(rockShots[2]) + ", " +
               std::to_string(rockShots[3]) + "; comets shot " + std::to_string(cometShots) +
               "; extra lives " + std::to_string(extraLives) + " (" + std::to_string(exactMultiples) +
               " at an exact multiple); life pickups " + std::to_string(lifePickups) + "; ship hits " +
               std::to_string(shipHits) + "; protected touches " + std::to_string(protectedTouches) +
               "; waves started " + std::to_string(waves);
    }
};

class GameRulesTest : public ::testing::Test {
  protected:
    // Plays the demo pilot for up to `ticks` ticks and checks every tick against the rules; counts
    // what happened into `seen`.
    void playAndCheck(std::uint64_t seed, const Tuning& tuning, int ticks, Seen& seen) {
        Game game = rulesGame(assets_, seed, tuning);
        Bot bot(seed);
        EXPECT_EQ(game.lives(), tuning.startLives);
        EXPECT_EQ(game.wave(), 1);
        EXPECT_EQ(rocksBySize(game), (std::map<int, int>{{3, 3}})) << "wave 1: 2 + 1 large rocks";
        for (; seen.ticks < ticks && !game.over(); ++seen.ticks) {
            const int score = game.score(), lives = game.lives(), wave = game.wave();
            const bool wasProtected = game.shipProtected();
            const ObjectId ship = game.shipId();
            const std::map<int, int> rocksBefore = rocksBySize(game);
            game.tick(bot.decide(game));

            int points = 0, livesGained = 0, hits = 0, waveStarts = 0, shotBySize[4] = {};
            for (const GameEvent& e : game.events()) {
                switch (e.type) {
                    case GameEvent::RockSplit:
                    case GameEvent::RockDestroyed:
                        EXPECT_EQ(e.type == GameEvent::RockDestroyed, e.size == 1)
                            << "tick " << game.tickCount() << ": only a small rock shatters";
                        points += pointsForRock(e.size);
                        ++seen.rockShots[e.size];
                        ++shotBySize[e.size];
                        break;
                    case GameEvent::CometShot:
                        points += kPointsForComet;
                        ++seen.cometShots;
                        break;
                    case GameEvent::ExtraLife:
                        ++livesGained;
                        ++seen.extraLives;
                        break;
                    case GameEvent::PickupTaken:
                        if (e.size == static_cast<int>(PickupKind::Life)) ++livesGained, ++seen.lifePickups;
                        break;
                    case GameEvent::ShipHit:
                        ++hits;
                        ++seen.shipHits;
                        break;
                    case GameEvent::WaveStart:
                        ++waveStarts;
                        EXPECT_EQ(e.size, wave + 1) << "waves count up by one";
                        break;
                    default:
                        break;
                }
            }
            const std::string at = "tick " + std::to_string(game.tickCount());
            ASSERT_EQ(game.score() - score, points) << at << ": the score moves by the points of its shots";
            ASSERT_EQ(game.lives() - lives, livesGained - hits) << at;
            // Every extraLifeEvery points give a life, at the multiple itself.
            ASSERT_EQ(game.score() / tuning.extraLifeEvery, seen.extraLives)
                << at << ": score " << game.score();
            if (points && game.score() % tuning.extraLifeEvery == 0) ++seen.exactMultiples;
            // A shot rock is gone; a large or medium one leaves two rocks one size smaller.
            std::map<int, int> rocksAfter = rocksBySize(game);
            for (int size = 1; size <= 3; ++size) {
                int expected = rocksBefore.count(size) ? rocksBefore.at(size) : 0;
                expected += (size < 3 ? 2 * shotBySize[size + 1] : 0) - shotBySize[size];
                if (size == 3 && waveStarts) expected += std::min(2 + game.wave(), 9);
                ASSERT_EQ(rocksAfter.count(size) ? rocksAfter.at(size) : 0, expected)
                    << at << ": size " << size;
            }
            if (wasProtected) {
                EXPECT_EQ(hits, 0) << at << ": a protected ship is not hit";
            }
            if (wasProtected && ship != 0 && game.world().find(ship)) {
                for (ObjectId other : game.world().collidedWith(ship)) {
                    Kind k = game.kindOf(other);
                    if (k == Kind::Rock || k == Kind::Comet) {
                        ++seen.protectedTouches;
                        break;
                    }
                }
            }
            if (hits) {
                EXPECT_EQ(game.shipId(), 0u) << at << ": the ship is gone until it respawns";
                EXPECT_EQ(game.over(), game.lives() == 0) << at << ": the game ends at 0 lives";
            }
            if (waveStarts) {
                ++seen.waves;
                EXPECT_EQ(game.wave(), wave + 1);
                EXPECT_EQ(rocksBySize(game), (std::map<int, int>{{3, std::min(2 + game.wave(), 9)}}))
                    << at << ": wave " << game.wave() << " starts with 2 + wave large rocks, at most 9";
                // Each wave faster: its rocks start at 0.7 to 1.3 times min(28 + 7·wave, 95).
                const double pace = std::min(28.0 + 7.0 * game.wave(), 95.0);
                for (const GameObject& o : game.world().objects())
                    if (game.kindOf(o.id) == Kind::Rock) {
                        EXPECT_GE(o.velocity.norm(), 0.7 * pace - 1e-9) << at;
                        EXPECT_LE(o.velocity.norm(), 1.3 * pace + 1e-9) << at;
                    }
            }
            // README.md: comets pass through the cave wall (they ignore containers); bullets,
            // pickups and comets are ghosts that nothing pushes; rocks and the ship are pushed.
            for (const GameObject& o : game.world().objects()) {
                switch (game.kindOf(o.id)) {
                    case Kind::Comet:
                        ++seen.comets;
                        EXPECT_TRUE(o.has(kIgnoreContainers) && o.has(kGhost)) << at << " " << o.name;
                        break;
                    case Kind::Bullet:
                    case Kind::Pickup:
                        EXPECT_TRUE(o.has(kGhost) && !o.has(kIgnoreContainers)) << at << " " << o.name;
                        break;
                    case Kind::Rock:
                    case Kind::Ship:
                        EXPECT_TRUE(!o.has(kGhost) && !o.has(kIgnoreContainers)) << at << " " << o.name;
                        break;
                    default:
                        break;
                }
            }
        }
        seen.over = game.over();
        if (game.over()) {
            EXPECT_EQ(game.lives(), 0);
            std::uint64_t endedAt = game.tickCount();
            for (int t = 0; t < 600; ++t) game.tick(kFire | kThrust);
            EXPECT_EQ(game.shipId(), 0u) << "no ship after the game is over";
            EXPECT_EQ(game.lives(), 0);
            EXPECT_EQ(game.tickCount(), endedAt + 600) << "the world runs on behind GAME OVER";
        }
    }

    AssetFs assets_{POLAR_ASSET_DIR};
};

// Tuning that makes the rules show often: a life every 500 points (some scores land on a multiple).
Tuning rulesTuning() {
    Tuning tuning;
    tuning.extraLifeEvery = 500;
    tuning.startLives = 4;
    return tuning;
}

TEST_F(GameRulesTest, EveryTickScoresItsShotsAndCountsItsLives) {
    Seen seen;
    playAndCheck(10, rulesTuning(), 60 * 300, seen);
    if (HasFatalFailure()) return;
    SCOPED_TRACE(seen.describe());
    // The rules above were exercised, not passed over (seed 10 plays five minutes without losing).
    EXPECT_GT(seen.rockShots[3], 0);
    EXPECT_GT(seen.rockShots[2], 0);
    EXPECT_GT(seen.rockShots[1], 0);
    EXPECT_GT(seen.cometShots, 0);
    EXPECT_GT(seen.comets, 0);
    EXPECT_GT(seen.extraLives, 2);
    EXPECT_GT(seen.exactMultiples, 0);
    EXPECT_GT(seen.lifePickups, 0);
    EXPECT_GT(seen.shipHits, 0);
    EXPECT_GT(seen.protectedTouches, 0);
    EXPECT_GE(seen.waves, 3);
}

TEST_F(GameRulesTest, TheLastLifeLostEndsTheGame) {
    Seen seen;
    playAndCheck(2, rulesTuning(), 60 * 300, seen);  // seed 2 loses its last life within a minute
    if (HasFatalFailure()) return;
    SCOPED_TRACE(seen.describe());
    EXPECT_TRUE(seen.over);
    EXPECT_EQ(seen.shipHits, 4 + seen.extraLives + seen.lifePickups) << "every life, each lost once";
}

// Each scene's bullets (assets/README.md, the "game" block): fired at the scene's bullet speed
// relative to the ship (the tuning's 430 units per second unless "bullet_speed" says otherwise),
// flagged "fast" exactly when "bullets" is "fast", and gone after the scene's bullet life.
TEST_F(GameRulesTest, BulletsHaveTheirScenesSpeedLifeAndFlag) {
    struct Case {
        const char* scene;
        double speed, life;  // life 0: not timed (the cave's wall ends a bullet sooner)
        bool fast;
    };
    const Tuning tuning;
    for (const Case& c : {Case{"scenes/cave.json", tuning.bulletSpeed, 0.0, false},
                          Case{"scenes/field.json", tuning.bulletSpeed, tuning.bulletLife, false},
                          Case{"scenes/storm.json", 1500.0, 0.3, true}}) {
        SCOPED_TRACE(c.scene);
        Game::Config config;
        config.scene = c.scene;
        config.reader = assets_.reader();
        config.seed = 5;
        Result<Game> game = Game::create(config);
        ASSERT_TRUE(game.ok()) << game.error().message();
        EXPECT_EQ(game->bulletSpeed(), c.speed);
        game->tick(kFire);
        std::vector<const GameObject*> bullets;
        for (const GameObject& o : game->world().objects())
            if (game->kindOf(o.id) == Kind::Bullet) bullets.push_back(&o);
        ASSERT_EQ(bullets.size(), 1u) << "one shot on the first tick";
        const GameObject& bullet = *bullets[0];
        const GameObject* ship = game->world().find(game->shipId());
        ASSERT_NE(ship, nullptr);
        EXPECT_NEAR((bullet.velocity - ship->velocity).norm(), c.speed, 1e-9);
        EXPECT_EQ(bullet.has(kFast), c.fast);
        if (c.life == 0.0) continue;
        // It lives its life (to within the tick it ends in), unless it hits something first.
        const ObjectId id = bullet.id;
        int alive = 1;
        bool hit = false;
        while (game->world().find(id) && alive < 1000) {
            game->tick(0);
            for (const GameEvent& e : game->events())
                hit = hit || e.type == GameEvent::RockSplit || e.type == GameEvent::RockDestroyed ||
                      e.type == GameEvent::CometShot || e.type == GameEvent::WallHit;
            if (game->world().find(id)) ++alive;
        }
        ASSERT_FALSE(hit) << "the bullet hit something after " << alive << " ticks; pick another seed";
        EXPECT_NEAR(alive, c.life * tuning.tickRate, 1.0);
    }
}

}  // namespace
}  // namespace polar::game
