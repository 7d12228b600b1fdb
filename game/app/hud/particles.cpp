#include "app/hud/particles.h"

#include <algorithm>
#include <cmath>

#include "rules/rng.h"

namespace polar::game {

using render::Color;

void Particles::spawnFor(const std::vector<GameEvent>& events, std::uint64_t tick) {
    Rng rng(tick * 0x9E3779B97F4A7C15ull + 17);
    for (const GameEvent& e : events) {
        int count = 0;
        double speed = 60;
        std::uint32_t color = 0xffd8c8b0;
        switch (e.type) {
            case GameEvent::RockSplit:
            case GameEvent::RockDestroyed:
                count = 6 + 6 * e.size;
                break;
            case GameEvent::ShipHit:
                count = 40;
                speed = 110;
                color = 0xffffb040;
                break;
            case GameEvent::CometShot:
                count = 30;
                speed = 120;
                color = 0xff80d0ff;
                break;
            case GameEvent::WallHit:
                count = 4;
                speed = 40;
                color = 0xffffe080;
                break;
            case GameEvent::PickupTaken:
                count = 16;
                speed = 70;
                color = 0xff80ff90;
                break;
            default:
                break;
        }
        for (int i = 0; i < count; ++i) {
            double angle = rng.range(0, kTwoPi), v = rng.range(0.2, 1.0) * speed;
            double life = rng.range(0.3, 0.9);
            double s, c;
            trig::sincos(angle, s, c);
            particles_.push_back({e.where, Vec2(c, s) * v, life, life, color});
        }
    }
}

void Particles::tick(double dt) {
    for (Particle& p : particles_) {
        p.position += p.velocity * dt;
        p.velocity *= 0.97;
        p.life -= dt;
    }
    particles_.erase(
        std::remove_if(particles_.begin(), particles_.end(), [](const Particle& p) { return p.life <= 0; }),
        particles_.end());
}

void Particles::draw(render::DrawList& list, const render::View& view, double alpha) const {
    for (const Particle& p : particles_) {
        Vec2 c = view.toCanvas(p.position + p.velocity * (alpha / 60.0));
        Color color = Color::fromArgb(p.color);
        color.a = static_cast<std::uint8_t>(255 * std::clamp(p.life / p.maxLife, 0.0, 1.0));
        list.blendPixel(static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())), color);
    }
}

}  // namespace polar::game
