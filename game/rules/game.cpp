// The rules: one fixed tick from the player's Actions (steering, firing, waves, collisions, ageing,
// the score), and the spawning they do (game.h).
#include "rules/game.h"

#include <algorithm>
#include <cmath>

namespace polar::game {
namespace {

constexpr int kRockScore[] = {0, 100, 50, 20};
constexpr int kCometScore = 250;
// Hit-stop (rules 2), in ticks: long enough to feel, short enough never to cost the player a dodge.
constexpr int kHitStopLargeRock = 3;
constexpr int kHitStopComet = 4;
constexpr int kHitStopLifeLost = 10;
constexpr int kHitStopGameOver = 20;
// Rules 2: how far from the ship a wave's rocks start (rules 1: 110).
constexpr double kSafeStartDistance = 150;

Vec2 facingOf(const Transform& t) {
    double s, c;
    trig::sincos(t.rotation(), s, c);
    return Vec2(c, s);
}

// The radius of an object's first radii toward +x, a size good enough for placing things.
double sizeOf(const Prototype& proto) {
    return proto.bounds && !proto.bounds->empty() ? proto.bounds->front().maxRadius() : 4;
}

}  // namespace

ObjectId Game::spawn(const std::string& base, const Prototype& proto, const Vec2& position, double rotation,
                     const Vec2& velocity, double spin, ObjectFlags flags, Entity entity, double damping) {
    ObjectDef def;
    def.name = base + "-" + std::to_string(++serial_);
    def.userData = proto.look;
    def.bounds = proto.bounds;
    def.transform = Transform(position, rotation, Vec2::Ones());
    def.velocity = velocity;
    def.spin = spin;
    def.damping = damping;
    def.flags = flags;
    ObjectId id = world_.add(std::move(def));
    entities_.emplace(id, std::move(entity));
    return id;
}

void Game::despawn(ObjectId id) {
    world_.remove(id);
    entities_.erase(id);
    if (id == ship_) ship_ = 0;
}

Kind Game::kindOf(ObjectId id) const {
    auto it = entities_.find(id);
    return it == entities_.end() ? Kind::Scenery : it->second.kind;
}

int Game::rockSize(ObjectId id) const {
    auto it = entities_.find(id);
    return it != entities_.end() && it->second.kind == Kind::Rock ? it->second.size : 0;
}

PickupKind Game::pickupKind(ObjectId id) const {
    auto it = entities_.find(id);
    return it == entities_.end() ? PickupKind::Shield : it->second.pickup;
}

double Game::arenaRadiusToward(const Vec2& dir) const {
    if (rules_.edges == SceneRules::Edges::Wrap) {
        // From the field's centre to its rectangle's edge along dir.
        Vec2 half = rules_.field * 0.5;
        double reach = std::max(half.x(), half.y());
        if (std::abs(dir.x()) > 1e-12) reach = std::min(reach, half.x() / std::abs(dir.x()));
        if (std::abs(dir.y()) > 1e-12) reach = std::min(reach, half.y() / std::abs(dir.y()));
        return reach;
    }
    const GameObject* arena = world_.find(arena_);
    if (!arena || arena->boundsOrEmpty().empty()) return 0;
    return arena->boundsOrEmpty().front().worldRadius(arena->transform.linear(), dir);
}

Vec2 Game::randomPointInArena(double margin) {
    double angle = rng_.range(0, kTwoPi);
    double s, c;
    trig::sincos(angle, s, c);
    Vec2 dir(c, s);
    double reach = std::max(0.0, arenaRadiusToward(dir) - margin);
    return arenaCentre_ + dir * (std::sqrt(rng_.uniform()) * reach);
}

void Game::tick(Actions actions) {
    events_.clear();
    ++ticks_;
    // A hit-stop freezes the whole game, its timers and the player's controls with it: the tick
    // passes (and is recorded) and nothing moves.
    if (hitStop_ > 0) {
        --hitStop_;
        return;
    }
    double dt = stepSeconds();
    if (!over_ && ship_ != 0) steerShip(actions);
    if (arcade_) steerFoes(dt);
    world_.step(dt);
    handleCollisions();
    ageThings();
    if (rules_.edges == SceneRules::Edges::Wrap) wrapEdges();
}

void Game::wrapEdges() {
    // A thing wholly past one side of the field comes back wholly past the other, so it slides in
    // the way it left. Comets cross the field once and are not wrapped.
    for (GameObject& object : world_.objects()) {
        Kind kind = kindOf(object.id);
        if (kind != Kind::Ship && kind != Kind::Rock && kind != Kind::Bullet && kind != Kind::Pickup &&
            kind != Kind::Foe && kind != Kind::FoeShot)
            continue;
        double margin = object.boundsOrEmpty().empty() ? 4 : object.boundsOrEmpty().front().maxRadius();
        Vec2 at = object.transform.position();
        Vec2 moved = at;
        for (int axis = 0; axis < 2; ++axis) {
            double span = rules_.field[axis] + 2 * margin;
            if (moved[axis] < -margin)
                moved[axis] += span;
            else if (moved[axis] > rules_.field[axis] + margin)
                moved[axis] -= span;
        }
        if (moved != at) object.transform.setPosition(moved);
    }
}

void Game::steerShip(Actions actions) {
    GameObject* ship = world_.find(ship_);
    if (!ship) return;
    double turn = ((actions & kTurnLeft) ? 1.0 : 0.0) - ((actions & kTurnRight) ? 1.0 : 0.0);
    ship->spin = turn * tuning_.turnRate;
    if (actions & kThrust) {
        Vec2 facing = facingOf(ship->transform);
        ship->velocity += facing * (tuning_.thrust / tuning_.tickRate * speedScale_);
        double speed = ship->velocity.norm();
        if (speed > tuning_.maxShipSpeed) ship->velocity *= tuning_.maxShipSpeed / speed;
        events_.push_back({GameEvent::Thrust, ship->transform.position() - facing * sizeOf(ship_proto_), 0,
                           ship_proto_.look, ship->transform.rotation(), ship->velocity, 0});
    }
    // Pickups are ghosts the world does not collide (a touch must not nudge the ship): the game asks
    // the narrow phase itself whether the ship touches one.
    std::vector<ObjectId> taken;
    for (const GameObject& object : world_.objects()) {
        if (kindOf(object.id) != Kind::Pickup || object.boundsOrEmpty().empty() ||
            ship->boundsOrEmpty().empty())
            continue;
        if (testObjects(*ship, object).hit) taken.push_back(object.id);
    }
    for (ObjectId id : taken) {
        const GameObject* pickup = world_.find(id);
        events_.push_back({GameEvent::PickupTaken, pickup->transform.position(),
                           static_cast<int>(pickupKind(id)), static_cast<std::uint32_t>(pickup->userData)});
        takePickup(pickupKind(id));
        despawn(id);
    }

    // Last: a shot adds an object, which may move the world's objects (and `ship` with them).
    fireCooldown_ = std::max(0.0, fireCooldown_ - stepSeconds());
    if ((actions & kFire) && fireCooldown_ <= 0) fire();
}

void Game::fire() {
    // Rules 3's power-ups: spread fires three bullets a shot and may have three times as many out;
    // rapid cools the gun in under half the time and allows six more.
    int most = tuning_.maxBullets;
    double cooldown = tuning_.fireCooldown;
    if (spread_ > 0) most *= 3;
    if (rapid_ > 0) most += 6, cooldown *= 0.45;
    int bullets = 0;
    for (const auto& [id, entity] : entities_) bullets += entity.kind == Kind::Bullet;
    if (bullets >= most) return;
    const GameObject* ship = world_.find(ship_);
    Vec2 facing = facingOf(ship->transform);
    Vec2 muzzle = ship->transform.position() + facing * (sizeOf(ship_proto_) + sizeOf(bullet_) + 1);
    Entity bullet{Kind::Bullet, 0, PickupKind::Shield, rules_.bulletLife.value_or(tuning_.bulletLife)};
    ObjectFlags flags = kPhysics | kCollisions | kGhost;
    if (rules_.fastBullets) flags = flags | kFast;
    const double heading = ship->transform.rotation();
    const Vec2 velocity = ship->velocity + facing * bulletSpeed();
    if (spread_ > 0) {
        constexpr double kSpreadAngle = 0.2;  // radians between the three bullets
        const Vec2 shipVelocity = ship->velocity;
        for (double side : {-1.0, 1.0}) {
            double s, c;
            trig::sincos(heading + side * kSpreadAngle, s, c);
            spawn("bullet", bullet_, muzzle, heading + side * kSpreadAngle,
                  shipVelocity + Vec2(c, s) * bulletSpeed(), 0, flags, bullet);
        }
    }
    spawn("bullet", bullet_, muzzle, heading, velocity, 0, flags, bullet);
    fireCooldown_ = cooldown;
    events_.push_back({GameEvent::Shot, muzzle, 0, bullet_.look, heading, velocity, 0});
}

void Game::startWave() {
    ++wave_;
    int count = std::min(2 + wave_, 9);
    double speed = std::min(28.0 + 7.0 * wave_, 95.0);
    Vec2 avoid = ship_ ? world_.find(ship_)->transform.position() : shipStart_;
    // Rules 2: a rock starts farther off and never heads at the ship, so a player who sits still
    // is not hit the moment the wave's grace runs out.
    const double clearance = rulesVersion_ >= 2 ? kSafeStartDistance : 110;
    for (int i = 0; i < count; ++i) {
        Vec2 at = randomPointInArena(40);
        for (int tries = 0; tries < 20 && (at - avoid).norm() < clearance; ++tries)
            at = randomPointInArena(40);
        double heading = rng_.range(0, kTwoPi);
        double s, c;
        trig::sincos(heading, s, c);
        if (rulesVersion_ >= 2 && (avoid - at).norm() > 0) {
            // Within 60° of straight at the ship: turned a quarter away, to the nearer side.
            const Vec2 toShip = (avoid - at).normalized();
            const Vec2 dir(c, s);
            if (dir.dot(toShip) > 0.5) {
                const double side = dir.x() * toShip.y() - dir.y() * toShip.x() > 0 ? -1.0 : 1.0;
                trig::sincos(heading + side * kHalfPi, s, c);
            }
        }
        // One draw per statement: C++ leaves the order of function arguments and operands open, and
        // g++ and clang++ pick differently, which would make the same seed a different game.
        const Prototype& proto = rocks_[3][rng_.below(kRockVariants)];
        double spin = rng_.range(0.4, 1.6);
        if (!rng_.chance(0.5)) spin = -spin;
        double rotation = rng_.range(0, kTwoPi);
        double pace = speed * rng_.range(0.7, 1.3);
        Entity rock{Kind::Rock, 3, PickupKind::Shield, 0};
        spawn("rock", proto, at, rotation, Vec2(c, s) * pace, spin, kPhysics | kCollisions, rock);
    }
    cometTimer_ = rng_.range(9.0, 15.0);
    if (arcade_ && rules_.foes) foeTimer_ = rng_.range(5.0, 9.0);
    events_.push_back({GameEvent::WaveStart, arenaCentre_, wave_});
}

void Game::spawnShip() {
    Entity entity{Kind::Ship, 0, PickupKind::Shield, 0};
    ObjectDef def;
    def.name = "ship";
    def.userData = ship_proto_.look;
    def.bounds = ship_proto_.bounds;
    def.transform = Transform(shipStart_, kHalfPi, Vec2::Ones());
    def.damping = tuning_.shipDamping;
    def.flags = kPhysics | kCollisions;
    ship_ = world_.add(std::move(def));
    entities_.emplace(ship_, std::move(entity));
    invulnerable_ = tuning_.invulnerableAfterRespawn;
    events_.push_back({GameEvent::ShipRespawn, shipStart_, 0});
}

void Game::spawnComet() {
    double angle = rng_.range(0, kTwoPi);
    double s, c;
    trig::sincos(angle, s, c);
    Vec2 start = arenaCentre_ + Vec2(c, s) * 430.0;
    double targetX = rng_.range(-120, 120);
    double targetY = rng_.range(-70, 70);
    Vec2 target = arenaCentre_ + Vec2(targetX, targetY);
    Vec2 velocity = (target - start).normalized() * rng_.range(120, 170);
    Entity comet{Kind::Comet, 0, PickupKind::Shield, 860.0 / velocity.norm()};
    spawn("comet", comet_, start, trig::atan2(velocity.y(), velocity.x()), velocity, 0,
          kPhysics | kCollisions | kGhost | kIgnoreContainers, comet);
    events_.push_back({GameEvent::CometIn, start, 0});
}

void Game::splitRock(ObjectId id, const Vec2& hitVelocity, bool byPlayer) {
    auto it = entities_.find(id);
    GameObject* rock = world_.find(id);
    if (it == entities_.end() || !rock) return;
    int size = it->second.size;
    Vec2 at = rock->transform.position();
    Vec2 velocity = rock->velocity;
    const auto look = static_cast<std::uint32_t>(rock->userData);
    const double angle = rock->transform.rotation();
    // Rules 2: the pieces are the same variant as the rock (rock-large-2 → rock-medium-2), so they
    // keep its colours; rules 1 drew each piece's variant.
    std::uint32_t variant = 0;
    for (std::uint32_t v = 0; v < rocks_[size].size(); ++v)
        if (rocks_[size][v].look == look) variant = v;
    const int points = addScore(kRockScore[size]);
    despawn(id);
    if (arcade_ && byPlayer) chainKill(at);
    if (size == 3) holdStill(kHitStopLargeRock);
    if (size > 1) {
        // Two children fly apart across the shot, each nudged along it.
        Vec2 along = hitVelocity.norm() > 0 ? Vec2(hitVelocity.normalized()) : Vec2(Vec2::UnitX());
        Vec2 across(-along.y(), along.x());
        double childSize = sizeOf(rocks_[size - 1][0]);
        for (int side = -1; side <= 1; side += 2) {
            std::uint32_t drawn = rng_.below(kRockVariants);
            const Prototype& proto = rocks_[size - 1][rulesVersion_ >= 2 ? variant : drawn];
            double apart = side * rng_.range(30, 55);
            double forward = rng_.range(5, 25);
            Vec2 v = velocity + across * apart + along * forward;
            double spin = rng_.range(0.8, 2.6);
            if (!rng_.chance(0.5)) spin = -spin;
            Entity child{Kind::Rock, size - 1, PickupKind::Shield, 0};
            spawn("rock", proto, at + across * (side * childSize * 0.9), rng_.range(0, kTwoPi), v, spin,
                  kPhysics | kCollisions, child);
        }
        events_.push_back({GameEvent::RockSplit, at, size, look, angle, velocity, points});
    } else {
        events_.push_back({GameEvent::RockDestroyed, at, size, look, angle, velocity, points});
    }
    if (arcade_) {
        dropPickup(at, tuning_.pickupChance * 1.5);
    } else if (rng_.chance(tuning_.pickupChance)) {
        bool life = rng_.chance(0.3);
        Entity pickup{Kind::Pickup, 0, life ? PickupKind::Life : PickupKind::Shield, tuning_.pickupLife};
        spawn("pickup", pickups_[life ? 1 : 0], at, 0, Vec2::Zero(), 1.2, kGhost | kPhysics, pickup);
    }
}

void Game::handleCollisions() {
    // Visit in creation order; what a visit removes is skipped later.
    std::vector<ObjectId> ids;
    ids.reserve(world_.objects().size());
    for (const GameObject& object : world_.objects()) ids.push_back(object.id);
    for (ObjectId id : ids) {
        GameObject* object = world_.find(id);
        if (!object) continue;
        std::span<const ObjectId> partners = world_.collidedWith(id);
        if (partners.empty()) continue;
        std::vector<ObjectId> touched(partners.begin(), partners.end());  // visits may remove objects
        Vec2 velocity = object->velocity;
        switch (kindOf(id)) {
            case Kind::Bullet:
                for (ObjectId other : touched) {
                    Kind k = kindOf(other);
                    if (k == Kind::Rock && world_.find(other)) {
                        splitRock(other, velocity);
                    } else if (k == Kind::Foe && world_.find(other)) {
                        const Vec2 at = world_.find(other)->transform.position();
                        if (hitFoe(other, velocity, 1)) chainKill(at);
                    } else if (k == Kind::Comet && world_.find(other)) {
                        const GameObject* comet = world_.find(other);
                        events_.push_back({GameEvent::CometShot, comet->transform.position(), 0,
                                           static_cast<std::uint32_t>(comet->userData),
                                           comet->transform.rotation(), comet->velocity, kCometScore});
                        addScore(kCometScore);
                        despawn(other);
                        holdStill(kHitStopComet);
                    } else if (k == Kind::Arena) {
                        events_.push_back({GameEvent::WallHit, object->transform.position(), 0, 0,
                                           trig::atan2(velocity.y(), velocity.x()), velocity, 0});
                    } else {
                        continue;
                    }
                    despawn(id);
                    break;
                }
                break;
            case Kind::Comet:
                for (ObjectId other : touched)
                    if (kindOf(other) == Kind::Rock && world_.find(other)) splitRock(other, velocity, false);
                break;
            case Kind::FoeShot:
                for (ObjectId other : touched)
                    if (kindOf(other) == Kind::Arena) {
                        despawn(id);
                        break;
                    }
                break;
            case Kind::Ship:
                for (ObjectId other : touched) {
                    // A smash below may add objects, which may move the ship's.
                    object = world_.find(id);
                    if (!object) break;
                    Kind k = kindOf(other);
                    if (barrier_ > 0 && world_.find(other)) {
                        // Rules 3's barrier breaks what it touches (a comet passes it by).
                        if (k == Kind::Rock) {
                            splitRock(other, object->velocity);
                        } else if (k == Kind::Foe) {
                            const Vec2 at = world_.find(other)->transform.position();
                            if (hitFoe(other, object->velocity, 3)) chainKill(at);
                        } else if (k == Kind::FoeShot) {
                            despawn(other);
                        }
                    }
                    if (k == Kind::Arena)
                        events_.push_back(
                            {GameEvent::Bounce, object->transform.position(), 0, 0, 0, object->velocity, 0});
                    const bool deadly =
                        k == Kind::Rock || k == Kind::Comet || k == Kind::Foe || k == Kind::FoeShot;
                    if (!deadly || shipProtected()) continue;
                    events_.push_back({GameEvent::ShipHit, object->transform.position(), 0,
                                       static_cast<std::uint32_t>(object->userData),
                                       object->transform.rotation(), velocity, 0});
                    despawn(id);
                    --lives_;
                    multiplier_ = 1;  // rules 3: a life lost ends the chain
                    chainTimer_ = 0;
                    if (lives_ <= 0) {
                        over_ = true;
                        events_.push_back({GameEvent::GameOver, arenaCentre_, 0});
                        holdStill(kHitStopGameOver);
                    } else {
                        respawnTimer_ = tuning_.respawnDelay;
                        holdStill(kHitStopLifeLost);
                    }
                    break;
                }
                break;
            default:
                break;
        }
    }
}

void Game::ageThings() {
    double dt = stepSeconds();
    std::vector<ObjectId> expired;
    bool rocksLeft = false;
    for (auto& [id, entity] : entities_) {
        rocksLeft = rocksLeft || entity.kind == Kind::Rock;
        if (entity.kind != Kind::Bullet && entity.kind != Kind::Pickup && entity.kind != Kind::Comet &&
            entity.kind != Kind::Foe && entity.kind != Kind::FoeShot)
            continue;
        entity.life -= dt;
        if (entity.life <= 0) expired.push_back(id);
    }
    for (ObjectId id : expired) despawn(id);

    invulnerable_ = std::max(0.0, invulnerable_ - dt);
    shield_ = std::max(0.0, shield_ - dt);
    if (arcade_) {
        agePowerUps(dt);
        ageChain(dt);
    }
    if (over_) return;
    if (ship_ == 0 && lives_ > 0) {
        respawnTimer_ -= dt;
        if (respawnTimer_ <= 0) spawnShip();
    }
    if (arcade_) scheduleFoes(dt, rocksLeft);
    if (!rocksLeft) {
        if (waveTimer_ <= 0) {
            waveTimer_ = tuning_.waveDelay;
            if (wave_ > 0) events_.push_back({GameEvent::WaveCleared, arenaCentre_, wave_});
        }
        waveTimer_ -= dt;
        if (waveTimer_ <= 0) startWave();
    }
    if (wave_ >= 2) {
        cometTimer_ -= dt;
        if (cometTimer_ <= 0) {
            spawnComet();
            cometTimer_ = rng_.range(std::max(5.0, 14.0 - wave_), std::max(9.0, 22.0 - wave_));
        }
    }
}

void Game::holdStill(int ticks) {
    if (rulesVersion_ >= 2) hitStop_ = std::max(hitStop_, ticks);
}

int Game::addScore(int points) {
    if (arcade_) points *= multiplier_;
    score_ += points;
    while (score_ >= nextExtraLife_) {
        nextExtraLife_ += tuning_.extraLifeEvery;
        ++lives_;
        events_.push_back({GameEvent::ExtraLife, arenaCentre_, 0});
    }
    return points;
}

}  // namespace polar::game
