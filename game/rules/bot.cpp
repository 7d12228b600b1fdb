#include "rules/bot.h"

#include <cmath>

namespace polar::game {

Actions Bot::decide(const Game& game) {
    const GameObject* ship = game.world().find(game.shipId());
    if (!ship) return 0;
    Vec2 p = ship->transform.position();
    const GameObject* target = nullptr;
    const GameObject* threat = nullptr;
    double bestTarget = INFINITY, bestThreat = 70.0;
    for (const GameObject& o : game.world().objects()) {
        Kind kind = game.kindOf(o.id);
        // Foes and their shots (rules 3) are targets and threats too; shots only threats.
        if (kind != Kind::Rock && kind != Kind::Comet && kind != Kind::Foe && kind != Kind::FoeShot) continue;
        Vec2 to = o.transform.position() - p;
        double d = to.norm();
        if (kind != Kind::FoeShot && d < bestTarget) bestTarget = d, target = &o;
        if (d < bestThreat && to.dot(o.velocity - ship->velocity) < 0) bestThreat = d, threat = &o;
    }
    Actions actions = 0;
    double heading = ship->transform.rotation();
    auto turnToward = [&](const Vec2& dir) {
        double diff = std::remainder(trig::atan2(dir.y(), dir.x()) - heading, kTwoPi);
        if (diff > 0.05) actions |= kTurnLeft;
        if (diff < -0.05) actions |= kTurnRight;
        return std::fabs(diff);
    };
    if (threat && !game.shipProtected()) {
        turnToward(p - threat->transform.position());
        actions |= kThrust;
    } else if (target) {
        // Lead the target: aim where it will be when a bullet gets there.
        Vec2 to = target->transform.position() - p;
        double time = to.norm() / game.bulletSpeed();
        Vec2 aim = to + (target->velocity - ship->velocity) * time;
        if (turnToward(aim) < 0.12 && rng_.chance(0.6)) actions |= kFire;
        if (ship->velocity.norm() < 20 && rng_.chance(0.05)) actions |= kThrust;
    }
    return actions;
}

}  // namespace polar::game
