// Rules 3 (game_foes.cpp, game_power_ups.cpp): each foe's behaviour, each power-up's effect and
// time, the multiplier, the waves that bring foes in their order, and that a scene calling for none
// plays exactly as under rules 2.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "files/assets.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::game {
namespace {

Game::Config configFor(const std::string& scene, const AssetFs& assets, int rules = kRulesVersion,
                       std::uint64_t seed = 5) {
    Game::Config config;
    config.scene = scene;
    config.reader = assets.reader();
    config.seed = seed;
    config.rules = rules;
    config.tuning.startLives = 99;
    return config;
}

double angleBetween(double a, double b) {
    return std::fabs(std::remainder(a - b, kTwoPi));
}

bool happened(const Game& game, GameEvent::Type type, int size = -1) {
    for (const GameEvent& e : game.events())
        if (e.type == type && (size < 0 || e.size == size)) return true;
    return false;
}

int count(const Game& game, Kind kind) {
    int n = 0;
    for (const GameObject& o : game.world().objects()) n += game.kindOf(o.id) == kind;
    return n;
}

int countFoes(const Game& game, FoeKind foe) {
    int n = 0;
    for (const GameObject& o : game.world().objects())
        n += game.kindOf(o.id) == Kind::Foe && game.foeKind(o.id) == foe;
    return n;
}

// Turns the ship toward `target` (where it will be when a shot gets there) and fires when on it.
Actions aimAt(const Game& game, ObjectId target) {
    const GameObject* ship = game.world().find(game.shipId());
    const GameObject* foe = game.world().find(target);
    if (!ship || !foe) return 0;
    const Vec2 to = foe->transform.position() - ship->transform.position();
    const Vec2 lead = to + foe->velocity * (to.norm() / game.bulletSpeed());
    const double diff = std::remainder(trig::atan2(lead.y(), lead.x()) - ship->transform.rotation(), kTwoPi);
    Actions a = 0;
    if (diff > 0.03) a |= kTurnLeft;
    if (diff < -0.03) a |= kTurnRight;
    if (std::fabs(diff) < 0.08) a |= kFire;
    return a;
}

// The arena's wall radius toward `dir` from its centre (the cave's first bounds).
double wallRadius(const Game& game, const Vec2& dir) {
    for (const GameObject& o : game.world().objects())
        if (game.kindOf(o.id) == Kind::Arena)
            return o.boundsOrEmpty().front().worldRadius(o.transform.linear(), dir);
    return 0;
}

Vec2 arenaCentre(const Game& game) {
    for (const GameObject& o : game.world().objects())
        if (game.kindOf(o.id) == Kind::Arena) return o.transform.position();
    return Vec2::Zero();
}

class Foes : public ::testing::Test {
  protected:
    Game newGame(const std::string& scene = "scenes/minefield.json", int rules = kRulesVersion,
                 std::uint64_t seed = 5) {
        Result<Game> game = Game::create(configFor(scene, assets_, rules, seed));
        EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
        return std::move(*game);
    }
    AssetFs assets_{POLAR_ASSET_DIR};
};

// A small saucer's every shot goes at the ship, within its aim's ±0.12 radians; a large one's go
// every which way.
TEST_F(Foes, ASmallSaucerAimsAtTheShipALargeOneShootsAnywhere) {
    Game game = newGame();
    game.bringFoe(FoeKind::SmallSaucer);
    game.bringFoe(FoeKind::Saucer);
    std::map<int, std::vector<double>> misses;  // by FoeKind: how far off the ship each shot went
    for (int t = 0; t < 6000 && (misses[1].size() < 8 || misses[0].size() < 8); ++t) {
        // Where the ship and each saucer are before the tick: a shot leaves from its saucer's place.
        const GameObject* ship = game.world().find(game.shipId());
        const Vec2 shipAt = ship ? ship->transform.position() : Vec2::Zero();
        std::map<int, Vec2> saucerAt;
        for (const GameObject& o : game.world().objects())
            if (game.kindOf(o.id) == Kind::Foe)
                saucerAt[static_cast<int>(game.foeKind(o.id))] = o.transform.position();
        game.tick(0);
        if (countFoes(game, FoeKind::SmallSaucer) == 0) game.bringFoe(FoeKind::SmallSaucer);
        if (countFoes(game, FoeKind::Saucer) == 0) game.bringFoe(FoeKind::Saucer);
        for (const GameEvent& e : game.events()) {
            if (e.type != GameEvent::FoeFired || !ship) continue;
            const Vec2 to = shipAt - saucerAt[e.size];
            misses[e.size].push_back(angleBetween(e.angle, trig::atan2(to.y(), to.x())));
        }
    }
    ASSERT_GE(misses[1].size(), 8u);
    ASSERT_GE(misses[0].size(), 8u);
    for (double miss : misses[1]) EXPECT_LE(miss, 0.12 + 1e-9) << "a small saucer's shot misses the ship";
    EXPECT_GT(*std::max_element(misses[0].begin(), misses[0].end()), 0.6) << "a large saucer aims";
}

// A saucer comes in at the edge and wanders: its course turns now and then, at a steady speed.
TEST_F(Foes, ASaucerEntersAtTheEdgeAndWanders) {
    Game game = newGame();
    const ObjectId id = game.bringFoe(FoeKind::Saucer);
    const GameObject* saucer = game.world().find(id);
    const Vec2 out = saucer->transform.position() - arenaCentre(game);
    EXPECT_GT(out.norm(), wallRadius(game, out.normalized()) - 40) << "it enters near the wall";
    std::set<long> courses;
    for (int t = 0; t < 240 && game.world().find(id); ++t) {
        game.tick(0);
        const GameObject* s = game.world().find(id);
        if (!s) break;
        EXPECT_NEAR(s->velocity.norm(), 70, 1e-9);
        courses.insert(std::lround(trig::atan2(s->velocity.y(), s->velocity.x()) * 100));
    }
    EXPECT_GE(courses.size(), 2u) << "it never turned";
}

// Shot, a mine bursts into three shards that turn toward the ship.
TEST_F(Foes, AMineBurstsIntoThreeShardsThatHomeOnTheShip) {
    Game game = newGame();
    const ObjectId mine = game.bringFoe(FoeKind::Mine);
    int t = 0;
    for (; t < 1200 && !happened(game, GameEvent::FoeDestroyed, static_cast<int>(FoeKind::Mine)); ++t)
        game.tick(aimAt(game, mine));
    ASSERT_TRUE(happened(game, GameEvent::FoeDestroyed, static_cast<int>(FoeKind::Mine))) << "never hit";
    EXPECT_EQ(countFoes(game, FoeKind::Shard), 3);
    for (int k = 0; k < 45; ++k) game.tick(0);
    const GameObject* ship = game.world().find(game.shipId());
    ASSERT_NE(ship, nullptr);
    int shards = 0;
    for (const GameObject& o : game.world().objects()) {
        if (game.kindOf(o.id) != Kind::Foe || game.foeKind(o.id) != FoeKind::Shard) continue;
        ++shards;
        const Vec2 to = (ship->transform.position() - o.transform.position()).normalized();
        EXPECT_GT(o.velocity.normalized().dot(to), 0.7) << o.name << " does not head for the ship";
    }
    EXPECT_GT(shards, 0);
}

// A hunter crawls round the cave just inside its wall, and takes three hits.
TEST_F(Foes, AHunterCrawlsJustInsideTheWallAndTakesThreeHits) {
    Game game = newGame();
    const ObjectId hunter = game.bringFoe(FoeKind::Hunter);
    const Vec2 centre = arenaCentre(game);
    double moved = 0;
    Vec2 last = game.world().find(hunter)->transform.position();
    int hits = 0;
    bool destroyed = false;
    for (int t = 0; t < 3000 && !destroyed; ++t) {
        game.tick(t < 200 ? 0 : aimAt(game, hunter));
        for (const GameEvent& e : game.events()) {
            if (e.size != static_cast<int>(FoeKind::Hunter)) continue;
            hits += e.type == GameEvent::FoeHit;
            destroyed = destroyed || e.type == GameEvent::FoeDestroyed;
        }
        const GameObject* h = game.world().find(hunter);
        if (!h) break;
        const Vec2 out = h->transform.position() - centre;
        EXPECT_NEAR(out.norm(), wallRadius(game, out.normalized()) - 16, 1e-6) << "tick " << t;
        moved += (h->transform.position() - last).norm();
        last = h->transform.position();
    }
    EXPECT_GT(moved, 50) << "it sat still";
    ASSERT_TRUE(destroyed);
    EXPECT_EQ(hits, 2) << "two hits it lives through, the third destroys it";
}

// Spread: a shot is three bullets, 0.2 radians apart; it lasts 10 s, then a shot is one again.
TEST_F(Foes, SpreadFiresThreeBulletsForTenSeconds) {
    Game game = newGame();
    for (int t = 0; t < 30; ++t) game.tick(0);
    game.give(PickupKind::Spread);
    EXPECT_EQ(game.powerUpLeft(PickupKind::Spread), 10.0);
    game.tick(kFire);
    ASSERT_TRUE(happened(game, GameEvent::Shot));
    EXPECT_EQ(count(game, Kind::Bullet), 3);
    int ticks = 1;
    while (!happened(game, GameEvent::PowerUpEnd, static_cast<int>(PickupKind::Spread)) && ticks < 1000)
        game.tick(0), ++ticks;
    EXPECT_EQ(ticks, 600) << "ten seconds";
    for (int t = 0; t < 60; ++t) game.tick(0);  // the bullets fly out
    game.tick(kFire);
    EXPECT_EQ(count(game, Kind::Bullet), 1);
}

// Rapid: holding fire shoots every 4 ticks instead of every 9, for 8 seconds.
TEST_F(Foes, RapidFireShootsMoreThanTwiceAsOften) {
    auto gaps = [&](bool rapid) {
        Game game = newGame();
        if (rapid) game.give(PickupKind::Rapid);
        std::vector<int> shots;
        for (int t = 0; t < 120; ++t) {
            game.tick(kFire);
            if (happened(game, GameEvent::Shot)) shots.push_back(t);
        }
        return shots.size() > 1 ? shots[1] - shots[0] : 0;
    };
    EXPECT_EQ(gaps(false), 9);
    EXPECT_EQ(gaps(true), 4);
}

// Barrier: the ship is guarded and breaks the rocks it touches; no life is lost.
TEST_F(Foes, TheBarrierBreaksWhatItTouches) {
    Game game = newGame("scenes/minefield.json", kRulesVersion, 9);
    const int lives = game.lives();
    int broken = 0;
    for (int t = 0; t < 900; ++t) {
        if (t % 60 == 0) game.give(PickupKind::Barrier);
        // Rams the nearest rock.
        ObjectId nearest = 0;
        double best = 1e9;
        const Vec2 at = game.world().find(game.shipId())->transform.position();
        for (const GameObject& o : game.world().objects())
            if (game.kindOf(o.id) == Kind::Rock && (o.transform.position() - at).norm() < best)
                best = (o.transform.position() - at).norm(), nearest = o.id;
        game.tick((aimAt(game, nearest) & ~kFire) | kThrust);
        ASSERT_GT(game.powerUpLeft(PickupKind::Barrier), 0);
        for (const GameEvent& e : game.events())
            broken += (e.type == GameEvent::RockSplit || e.type == GameEvent::RockDestroyed);
        EXPECT_FALSE(happened(game, GameEvent::ShipHit));
    }
    EXPECT_GE(game.lives(), lives);  // a life picked up on the way counts too
    EXPECT_GT(broken, 0) << "the ship never broke a rock by touching it";
}

// The multiplier: each rock's points are its worth times the multiplier at the kill; the
// multiplier rises with quick kills, falls a step at a time without them, and a life lost ends it.
TEST_F(Foes, KillsInQuickSuccessionRaiseTheMultiplierALifeLostEndsIt) {
    Game game = newGame("scenes/minefield.json", kRulesVersion, 3);
    Bot bot(11);
    constexpr int kWorth[] = {0, 100, 50, 20};  // by size: small rocks are worth most
    int highest = 1, lifeLost = 0, falls = 0;
    for (int t = 0; t < 20000; ++t) {
        const int before = game.multiplier();
        game.tick(bot.decide(game));
        highest = std::max(highest, game.multiplier());
        falls += game.multiplier() < before;
        const bool died = happened(game, GameEvent::ShipHit);  // later in the tick than a kill
        for (const GameEvent& e : game.events()) {
            if (e.type == GameEvent::RockSplit || e.type == GameEvent::RockDestroyed) {
                const int times = e.points / kWorth[e.size];
                EXPECT_EQ(e.points % kWorth[e.size], 0);
                EXPECT_GE(times, before);
                if (!died) {
                    EXPECT_LE(times, game.multiplier());
                }
            }
            if (e.type == GameEvent::ShipHit) {
                ++lifeLost;
                EXPECT_EQ(game.multiplier(), 1);
            }
        }
    }
    EXPECT_GE(highest, 3);
    EXPECT_GT(lifeLost, 0);
    EXPECT_GT(falls, lifeLost) << "the multiplier also falls when kills stop coming";
}

// Waves build in kind: the minefield's mines come from wave 1, its hunters not before wave 3, its
// saucers not before wave 5 and small saucers not before wave 4.
TEST_F(Foes, WavesBringTheScenesFoesInTheirOrder) {
    Game game = newGame("scenes/minefield.json", kRulesVersion, 7);
    Bot bot(5);
    std::map<int, int> firstWave;
    for (int t = 0; t < 100000 && game.wave() < 7; ++t) {
        game.tick(bot.decide(game));
        for (const GameEvent& e : game.events())
            if (e.type == GameEvent::FoeIn && !firstWave.count(e.size)) firstWave[e.size] = game.wave();
    }
    ASSERT_GE(game.wave(), 6) << "the pilot got no further";
    ASSERT_TRUE(firstWave.count(static_cast<int>(FoeKind::Mine)));
    ASSERT_TRUE(firstWave.count(static_cast<int>(FoeKind::Hunter)));
    ASSERT_TRUE(firstWave.count(static_cast<int>(FoeKind::Saucer)));
    EXPECT_LE(firstWave[static_cast<int>(FoeKind::Mine)], 2);
    EXPECT_GE(firstWave[static_cast<int>(FoeKind::Hunter)], 3);
    EXPECT_GE(firstWave[static_cast<int>(FoeKind::Saucer)], 5);
    if (firstWave.count(static_cast<int>(FoeKind::SmallSaucer))) {
        EXPECT_GE(firstWave[static_cast<int>(FoeKind::SmallSaucer)], 5);
    }
}

// A scene that calls for none: under rules 3 it loads nothing more and plays, tick for tick, the
// game rules 2 played. A scene that calls for foes brings none under rules 2.
TEST_F(Foes, ASceneThatCallsForNoneCostsNothingAndPlaysAsRules2) {
    for (const char* scene : {"scenes/cave.json", "scenes/field.json", "scenes/storm.json"}) {
        Game now = newGame(scene, 3), before = newGame(scene, 2);
        EXPECT_FALSE(now.arcade());
        EXPECT_EQ(now.boundsPaths(), before.boundsPaths()) << scene;
        Bot a(4), b(4);
        for (int t = 0; t < 3000; ++t) {
            now.tick(a.decide(now));
            before.tick(b.decide(before));
            ASSERT_EQ(now.hash(), before.hash()) << scene << " tick " << t;
        }
    }
    Game old = newGame("scenes/minefield.json", 2);
    EXPECT_FALSE(old.arcade());
    Bot bot(4);
    for (int t = 0; t < 3000; ++t) {
        old.tick(bot.decide(old));
        ASSERT_EQ(count(old, Kind::Foe), 0);
    }
}

// The demo pilot plays each new scene long, and nothing becomes NaN.
TEST_F(Foes, ThePilotPlaysTheFoesScenesLongWithNoNaN) {
    for (const char* scene : {"scenes/minefield.json", "scenes/saucers.json"}) {
        Game game = newGame(scene);
        Bot bot(8);
        std::set<int> foesSeen;
        for (int t = 0; t < 12000 && !game.over(); ++t) {
            game.tick(bot.decide(game));
            for (const GameEvent& e : game.events())
                if (e.type == GameEvent::FoeIn) foesSeen.insert(e.size);
            for (const GameObject& o : game.world().objects())
                ASSERT_TRUE(o.transform.position().allFinite() && o.velocity.allFinite() &&
                            std::isfinite(o.transform.rotation()))
                    << scene << " tick " << t << ": " << o.name;
        }
        EXPECT_GE(foesSeen.size(), 2u) << scene;
        EXPECT_GT(game.score(), 0) << scene;
    }
}

}  // namespace
}  // namespace polar::game
