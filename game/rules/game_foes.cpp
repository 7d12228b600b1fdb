// Rules 3: the foes a scene calls for, their shots, and when a wave brings which (game.h). Nothing
// here runs in a game whose scene calls for none (Game::arcade()).
#include <algorithm>
#include <cassert>
#include <cmath>

#include "polar/bounds_file.h"
#include "rules/game.h"

namespace polar::game {
namespace {

// What each FoeKind is: hits it takes, speed (a hunter's: its crawl along the wall), seconds it
// stays, seconds between its shots (0: it never shoots), points, and the chance it drops a pickup.
struct FoeSpec {
    int hits;
    double speed;
    double life;
    double fireEvery;
    int score;
    double dropChance;
};
constexpr FoeSpec kFoeSpecs[kFoeKindCount] = {
    {1, 70, 16, 1.8, 200, 0.35},   // Saucer: wanders, shoots anywhere
    {1, 100, 14, 1.5, 1000, 0.6},  // SmallSaucer: faster, aims at the ship
    {1, 22, 30, 0, 150, 0.0},      // Mine: drifts, bursts into three shards
    {1, 100, 7, 0, 100, 0.1},      // Shard: homes on the ship
    {3, 45, 30, 2.4, 300, 0.6},    // Hunter: crawls along the arena's edge, fires at the ship
};
constexpr const char* kFoeSprites[kFoeKindCount] = {"saucer", "saucer-small", "mine", "mine-shard", "hunter"};
constexpr double kFoeShotSpeed = 190;
constexpr double kFoeShotLife = 1.8;
constexpr double kShardPull = 220;        // a shard's turn toward the ship, units per second²
constexpr double kSmallSaucerAim = 0.12;  // radians either side of dead on
constexpr double kHunterInset = 16;       // a hunter's distance inside the wall
constexpr int kShards = 3;
constexpr int kMaxFoes = 5;
constexpr int kHitStopFoe = 3;  // a small saucer or a hunter destroyed
// The score multiplier: a kill within kChainWindow seconds of the last raises it a step, a kill
// within kCloseKill of the ship a step more; each kChainWindow without a kill takes a step off.
constexpr double kChainWindow = 2.5;
constexpr double kCloseKill = 70;
constexpr int kMaxMultiplier = 5;

Vec2 unit(double angle) {
    double s, c;
    trig::sincos(angle, s, c);
    return Vec2(c, s);
}

double sizeOf(const Prototype& proto) {
    return proto.bounds && !proto.bounds->empty() ? proto.bounds->front().maxRadius() : 4;
}

}  // namespace

bool Game::loadArcadePrototypes(const FileReader& reader, Error& error) {
    auto load = [&](const std::string& name, Prototype& proto) {
        proto.look = lookFor(Look{"sprites/" + name + ".png", "sprites/" + name + ".bounds.json"});
        Result<BoundsPtr> bounds = loadBounds(looks_[proto.look].bounds, reader);
        if (!bounds) {
            error = bounds.error();
            return false;
        }
        proto.bounds = *bounds;
        return true;
    };
    for (int k = 0; k < kFoeKindCount; ++k)
        if (!load(kFoeSprites[k], foes_[k])) return false;
    return load("foe-shot", foeShot_) && load("pickup-spread", pickups_[2]) &&
           load("pickup-rapid", pickups_[3]) && load("pickup-barrier", pickups_[4]);
}

FoeKind Game::foeKind(ObjectId id) const {
    auto it = entities_.find(id);
    return it == entities_.end() ? FoeKind::Saucer : it->second.foe;
}

// Which foes wave `wave_` may bring: the scene's in the order its file lists them, the first
// from wave 1, the second from wave 3, the third from wave 5; saucers come small from wave 4 on,
// more often each wave. How many may be about at once grows by one every third wave. Foes come
// while the wave's rocks last, sooner the later the wave.
void Game::scheduleFoes(double dt, bool waveUnderWay) {
    if (!waveUnderWay || rules_.foes == 0) return;
    foeTimer_ -= dt;
    if (foeTimer_ > 0) return;
    foeTimer_ = rng_.range(std::max(3.0, 9.0 - 0.5 * wave_), std::max(6.0, 14.0 - 0.6 * wave_));
    Foe open[kFoeCount];
    int count = 0;
    for (Foe foe : rules_.foeOrder)
        if (wave_ >= 1 + 2 * count) open[count++] = foe;
    int about = 0;
    for (const auto& [id, entity] : entities_)
        about += entity.kind == Kind::Foe && entity.foe != FoeKind::Shard;
    if (count == 0 || about >= std::min(kMaxFoes, 1 + wave_ / 3)) return;
    switch (open[rng_.below(static_cast<std::uint32_t>(count))]) {
        case Foe::Saucer: {
            const bool small = wave_ >= 4 && rng_.chance(std::min(0.6, 0.15 * (wave_ - 3)));
            spawnFoe(small ? FoeKind::SmallSaucer : FoeKind::Saucer);
            break;
        }
        case Foe::Mine:
            spawnFoe(FoeKind::Mine);
            break;
        case Foe::Hunter:
            spawnFoe(FoeKind::Hunter);
            break;
    }
}

ObjectId Game::bringFoe(FoeKind kind) {
    assert(arcade_ && "bringFoe needs a scene that calls for foes or power-ups");
    spawnFoe(kind);
    return world_.objects().back().id;
}

void Game::spawnFoe(FoeKind kind) {
    const FoeSpec& spec = kFoeSpecs[static_cast<int>(kind)];
    const Prototype& proto = foes_[static_cast<int>(kind)];
    Entity entity;
    entity.kind = Kind::Foe;
    entity.foe = kind;
    entity.hits = spec.hits;
    entity.life = spec.life;
    entity.timer = spec.fireEvery * rng_.range(0.5, 1.0);
    Vec2 at, velocity = Vec2::Zero();
    double rotation = 0, spin = 0;
    const bool wrap = rules_.edges == SceneRules::Edges::Wrap;
    if (kind == FoeKind::Saucer || kind == FoeKind::SmallSaucer) {
        // In from the edge, heading roughly inward.
        const double angle = rng_.range(0, kTwoPi);
        const Vec2 dir = unit(angle);
        at = arenaCentre_ + dir * (arenaRadiusToward(dir) - (wrap ? 0 : 26));
        entity.heading = angle + kPi + rng_.range(-0.7, 0.7);
        entity.turn = rng_.range(0.8, 1.6);
        velocity = unit(entity.heading) * spec.speed;
    } else if (kind == FoeKind::Mine) {
        const GameObject* ship = world_.find(ship_);
        const Vec2 avoid = ship ? ship->transform.position() : shipStart_;
        at = randomPointInArena(40);
        for (int tries = 0; tries < 20 && (at - avoid).norm() < 150; ++tries) at = randomPointInArena(40);
        velocity = unit(rng_.range(0, kTwoPi)) * spec.speed;
        spin = 1.0;
    } else {  // Hunter
        entity.heading = rng_.range(0, kTwoPi);
        entity.turn = rng_.chance(0.5) ? 1.0 : -1.0;
        const Vec2 dir = unit(entity.heading);
        at = arenaCentre_ + dir * (arenaRadiusToward(dir) - kHunterInset);
        rotation = entity.heading + kPi;  // facing into the arena
    }
    spawn("foe", proto, at, rotation, velocity, spin, kPhysics | kCollisions | kGhost | kIgnoreContainers,
          entity);
    events_.push_back({GameEvent::FoeIn, at, static_cast<int>(kind), proto.look, rotation, velocity, 0});
}

void Game::foeFire(ObjectId foe, Entity& entity, const Vec2& from, double angle) {
    const Vec2 dir = unit(angle);
    const Vec2 muzzle = from + dir * (sizeOf(foes_[static_cast<int>(entity.foe)]) + sizeOf(foeShot_) + 2);
    Entity shot;
    shot.kind = Kind::FoeShot;
    shot.foe = entity.foe;
    shot.life = kFoeShotLife;
    spawn("foe-shot", foeShot_, muzzle, angle, dir * kFoeShotSpeed, 0, kPhysics | kCollisions | kGhost, shot);
    events_.push_back({GameEvent::FoeFired, muzzle, static_cast<int>(entity.foe), foeShot_.look, angle,
                       dir * kFoeShotSpeed, 0});
    (void)foe;
}

void Game::steerFoes(double dt) {
    // Foes in creation order; a shot fired adds an object, so each foe is looked up by its id.
    std::vector<ObjectId> foes;
    for (const auto& [id, entity] : entities_)
        if (entity.kind == Kind::Foe) foes.push_back(id);
    const bool wrap = rules_.edges == SceneRules::Edges::Wrap;
    for (ObjectId id : foes) {
        Entity& entity = entities_.at(id);
        GameObject* foe = world_.find(id);
        const GameObject* ship = world_.find(ship_);
        const Vec2 at = foe->transform.position();
        const FoeSpec& spec = kFoeSpecs[static_cast<int>(entity.foe)];
        std::optional<double> shot;  // the direction of a shot this tick
        switch (entity.foe) {
            case FoeKind::Saucer:
            case FoeKind::SmallSaucer: {
                entity.turn -= dt;
                if (entity.turn <= 0) {
                    entity.heading += rng_.range(-1.2, 1.2);
                    entity.turn = rng_.range(0.8, 1.6);
                }
                // Near the wall it turns back in.
                const Vec2 out = at - arenaCentre_;
                if (!wrap && out.norm() > 0 && out.norm() > arenaRadiusToward(out.normalized()) - 34 &&
                    unit(entity.heading).dot(out) > 0)
                    entity.heading = trig::atan2(-out.y(), -out.x());
                foe->velocity = unit(entity.heading) * spec.speed;
                entity.timer -= dt;
                if (entity.timer <= 0 && ship) {
                    entity.timer = spec.fireEvery;
                    if (entity.foe == FoeKind::SmallSaucer) {
                        const Vec2 to = ship->transform.position() - at;
                        shot = trig::atan2(to.y(), to.x()) + rng_.range(-kSmallSaucerAim, kSmallSaucerAim);
                    } else {
                        shot = rng_.range(0, kTwoPi);
                    }
                }
                break;
            }
            case FoeKind::Mine: {
                // Bounces off the wall: v' = v − 2 (v·n) n, n the outward radial direction.
                const Vec2 out = at - arenaCentre_;
                if (!wrap && out.norm() > 0 && out.norm() > arenaRadiusToward(out.normalized()) - 20) {
                    const Vec2 n = out.normalized();
                    const double along = foe->velocity.dot(n);
                    if (along > 0) foe->velocity -= n * (2 * along);
                }
                break;
            }
            case FoeKind::Shard:
                if (ship) {
                    // Pulled toward the ship, no faster than its speed.
                    const Vec2 to = ship->transform.position() - at;
                    if (to.norm() > 0) foe->velocity += to.normalized() * (kShardPull * dt);
                    const double speed = foe->velocity.norm();
                    if (speed > spec.speed) foe->velocity *= spec.speed / speed;
                }
                break;
            case FoeKind::Hunter: {
                // Crawls round the arena just inside its edge: the angle moves by speed / radius.
                const Vec2 dir = unit(entity.heading);
                const double reach = std::max(40.0, arenaRadiusToward(dir));
                entity.heading += entity.turn * spec.speed / reach * dt;
                const Vec2 next = unit(entity.heading);
                const Vec2 target = arenaCentre_ + next * (arenaRadiusToward(next) - kHunterInset);
                foe->velocity = (target - at) / dt;
                foe->transform.setRotation(reduceRadians(entity.heading + kPi));
                entity.timer -= dt;
                if (entity.timer <= 0 && ship) {
                    entity.timer = spec.fireEvery;
                    const Vec2 to = ship->transform.position() - at;
                    shot = trig::atan2(to.y(), to.x());
                    if (rng_.chance(0.3)) entity.turn = -entity.turn;
                }
                break;
            }
        }
        if (shot) foeFire(id, entity, at, *shot);
    }
}

bool Game::hitFoe(ObjectId id, const Vec2& hitVelocity, int damage) {
    auto it = entities_.find(id);
    const GameObject* foe = world_.find(id);
    if (it == entities_.end() || !foe) return false;
    Entity& entity = it->second;
    const Vec2 at = foe->transform.position();
    const auto look = static_cast<std::uint32_t>(foe->userData);
    const double angle = foe->transform.rotation();
    const Vec2 velocity = foe->velocity;
    entity.hits -= damage;
    if (entity.hits > 0) {
        events_.push_back({GameEvent::FoeHit, at, static_cast<int>(entity.foe), look, angle, hitVelocity, 0});
        return false;
    }
    const FoeKind kind = entity.foe;
    const FoeSpec& spec = kFoeSpecs[static_cast<int>(kind)];
    const int points = addScore(spec.score);
    despawn(id);
    events_.push_back({GameEvent::FoeDestroyed, at, static_cast<int>(kind), look, angle, velocity, points});
    if (kind == FoeKind::SmallSaucer || kind == FoeKind::Hunter) holdStill(kHitStopFoe);
    if (kind == FoeKind::Mine) {
        // Three shards fly apart, a third of a turn between them, and then home on the ship.
        const double first = rng_.range(0, kTwoPi);
        for (int k = 0; k < kShards; ++k) {
            const Vec2 dir = unit(first + k * kTwoPi / kShards);
            Entity shard;
            shard.kind = Kind::Foe;
            shard.foe = FoeKind::Shard;
            shard.hits = kFoeSpecs[static_cast<int>(FoeKind::Shard)].hits;
            shard.life = kFoeSpecs[static_cast<int>(FoeKind::Shard)].life;
            spawn("foe", foes_[static_cast<int>(FoeKind::Shard)], at + dir * 6, first, dir * 70, 3.0,
                  kPhysics | kCollisions | kGhost | kIgnoreContainers, shard);
        }
    }
    dropPickup(at, spec.dropChance);
    return true;
}

void Game::chainKill(const Vec2& at) {
    const GameObject* ship = world_.find(ship_);
    int steps = chainTimer_ > 0 ? 1 : 0;
    if (ship && (at - ship->transform.position()).norm() < kCloseKill) ++steps;
    chainTimer_ = kChainWindow;
    const int before = multiplier_;
    multiplier_ = std::min(kMaxMultiplier, multiplier_ + steps);
    if (multiplier_ > before) events_.push_back({GameEvent::ChainUp, at, 0, 0, 0, Vec2::Zero(), multiplier_});
}

void Game::ageChain(double dt) {
    if (chainTimer_ <= 0) return;
    chainTimer_ -= dt;
    if (chainTimer_ > 0) return;
    chainTimer_ = 0;
    if (multiplier_ > 1) --multiplier_;
    if (multiplier_ > 1) chainTimer_ = kChainWindow;
}

}  // namespace polar::game
