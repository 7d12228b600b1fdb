// Rules 3: what a broken rock or foe drops in a scene that calls for foes or power-ups, what each
// pickup gives, and the power-ups' timers (game.h).
#include <algorithm>

#include "rules/game.h"

namespace polar::game {
namespace {

// Seconds each power-up lasts, by PickupKind (Shield and Life are not timed here).
constexpr double kPowerUpTime[5] = {0, 0, 10.0, 8.0, 7.0};
// How often each kind is drawn: a shield 2, a life 1, each power-up the scene calls for 3.
constexpr std::uint32_t kShieldWeight = 2, kLifeWeight = 1, kPowerUpWeight = 3;

}  // namespace

void Game::dropPickup(const Vec2& at, double chance) {
    if (!rng_.chance(chance)) return;
    PickupKind kinds[5] = {PickupKind::Shield, PickupKind::Life};
    std::uint32_t weights[5] = {kShieldWeight, kLifeWeight};
    int count = 2;
    std::uint32_t total = kShieldWeight + kLifeWeight;
    for (int p = 0; p < kPowerUpCount; ++p) {
        if (!rules_.callsFor(static_cast<PowerUp>(p))) continue;
        kinds[count] = static_cast<PickupKind>(static_cast<int>(PickupKind::Spread) + p);
        weights[count++] = kPowerUpWeight;
        total += kPowerUpWeight;
    }
    std::uint32_t draw = rng_.below(total);
    int pick = 0;
    while (draw >= weights[pick]) draw -= weights[pick++];
    const PickupKind kind = kinds[pick];
    Entity pickup;
    pickup.kind = Kind::Pickup;
    pickup.pickup = kind;
    pickup.life = tuning_.pickupLife;
    spawn("pickup", pickups_[static_cast<int>(kind)], at, 0, Vec2::Zero(), 1.2, kGhost | kPhysics, pickup);
}

void Game::takePickup(PickupKind kind) {
    switch (kind) {
        case PickupKind::Life:
            ++lives_;
            break;
        case PickupKind::Shield:
            shield_ = tuning_.shieldTime;
            break;
        case PickupKind::Spread:
            spread_ = kPowerUpTime[static_cast<int>(kind)];
            break;
        case PickupKind::Rapid:
            rapid_ = kPowerUpTime[static_cast<int>(kind)];
            break;
        case PickupKind::Barrier:
            barrier_ = kPowerUpTime[static_cast<int>(kind)];
            break;
    }
}

double Game::powerUpLeft(PickupKind kind) const {
    switch (kind) {
        case PickupKind::Spread:
            return spread_;
        case PickupKind::Rapid:
            return rapid_;
        case PickupKind::Barrier:
            return barrier_;
        case PickupKind::Shield:
        case PickupKind::Life:
            break;
    }
    return 0;
}

void Game::agePowerUps(double dt) {
    double* timers[3] = {&spread_, &rapid_, &barrier_};
    for (int p = 0; p < 3; ++p) {
        double& left = *timers[p];
        if (left <= 0) continue;
        left = std::max(0.0, left - dt);
        if (left == 0)
            events_.push_back(
                {GameEvent::PowerUpEnd, arenaCentre_, static_cast<int>(PickupKind::Spread) + p});
    }
}

}  // namespace polar::game
