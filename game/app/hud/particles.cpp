#include "app/hud/particles.h"

#include <algorithm>
#include <cmath>

#include "app/hud/lettering.h"
#include "polar/render/text.h"
#include "rules/rng.h"

namespace polar::game {

using render::Color;

namespace {

constexpr double kTickSeconds = 1.0 / 60.0;
constexpr double kMostShake = 7.0;   // pixels, at full trauma and level
constexpr double kTraumaFade = 1.5;  // trauma lost per second
constexpr double kScreenFlashFade = 7.0;

Vec2 direction(double angle) {
    double s, c;
    trig::sincos(angle, s, c);
    return Vec2(c, s);
}

std::uint8_t alphaOf(double share, double most = 255) {
    return static_cast<std::uint8_t>(std::clamp(share, 0.0, 1.0) * most);
}

// The flame's colour as it cools: white-yellow, orange, red, gone.
Color flameColor(double share) {
    if (share > 0.7) return Color{255, 240, 170, alphaOf(share)};
    if (share > 0.4) return Color{255, 160, 60, alphaOf(share)};
    return Color{200, 70, 40, alphaOf(share * 1.6)};
}

}  // namespace

void Particles::addTrauma(double amount) {
    trauma_ = std::min(1.0, trauma_ + amount);
}

void Particles::debris(Rng& rng, const GameEvent& e, int count, double speed) {
    for (int i = 0; i < count; ++i) {
        const double angle = rng.range(0, kTwoPi);
        const double pace = rng.range(0.3, 1.0) * speed;
        Particle p;
        p.position = e.where + direction(angle) * rng.range(0, 6 + 3 * e.size);
        p.velocity = e.motion * 0.6 + direction(angle) * pace;
        p.life = p.maxLife = rng.range(0.6, 1.3);
        p.angle = rng.range(0, kTwoPi);
        p.spin = rng.range(-9, 9);
        p.size = rng.range(1.4, 2.2 + 0.8 * e.size);
        p.keep = 0.955;
        p.look = e.look;
        p.shade = static_cast<std::uint8_t>(rng.below(8));
        p.color = 0xffc8b898;
        p.shape = Shape::Shard;
        particles_.push_back(p);
    }
}

void Particles::dust(Rng& rng, const GameEvent& e, int count) {
    for (int i = 0; i < count; ++i) {
        const double angle = rng.range(0, kTwoPi);
        Particle p;
        p.position = e.where + direction(angle) * rng.range(0, 4 + 4 * e.size);
        p.velocity = e.motion * 0.3 + direction(angle) * rng.range(6, 30);
        p.life = p.maxLife = rng.range(1.5, 3.2);
        p.keep = 0.985;
        p.look = e.look;
        p.shade = static_cast<std::uint8_t>(rng.below(4));  // the darker half
        p.color = 0xff908070;
        p.shape = Shape::Dust;
        particles_.push_back(p);
    }
}

void Particles::sparks(Rng& rng, const Vec2& where, double towards, double spread, int count, double speed,
                       std::uint32_t color) {
    for (int i = 0; i < count; ++i) {
        const double angle = towards + rng.range(-spread, spread);
        Particle p;
        p.position = where;
        p.velocity = direction(angle) * rng.range(0.4, 1.0) * speed;
        p.life = p.maxLife = rng.range(0.12, 0.35);
        p.size = 0.035;
        p.keep = 0.9;
        p.color = color;
        p.shape = Shape::Spark;
        particles_.push_back(p);
    }
}

void Particles::spawnFor(const std::vector<GameEvent>& events, std::uint64_t tick) {
    tick_ = tick;
    Rng rng(tick * 0x9E3779B97F4A7C15ull + 17);
    for (const GameEvent& e : events) {
        switch (e.type) {
            case GameEvent::Shot:
                bursts_.push_back({e.where, 3.5, -20, 0.05, 0.05, 0xfffff4c0, false});
                sparks(rng, e.where, e.angle, 0.35, 2, 160, 0xffffe8a0);
                break;
            case GameEvent::RockSplit:
            case GameEvent::RockDestroyed: {
                const int size = std::clamp(e.size, 1, 3);
                flashes_.push_back({e.where, e.angle, e.look, 0.12, 0.12});
                bursts_.push_back({e.where, 2.0 + 2 * size, 60, 0.08, 0.08, 0xffffffff, false});
                debris(rng, e, 4 + 4 * size, 45 + 20 * size);
                dust(rng, e, 6 + 8 * size);
                sparks(rng, e.where, 0, kPi, 3 + 2 * size, 140, 0xffffe8b0);
                if (e.points > 0) popUps_.push_back({e.where, "+" + std::to_string(e.points), 0.8, 0.8});
                addTrauma(size == 3 ? 0.38 : size == 2 ? 0.18 : 0.07);
                break;
            }
            case GameEvent::ShipHit:
                flashes_.push_back({e.where, e.angle, e.look, 0.2, 0.2});
                bursts_.push_back({e.where, 8, 70, 0.16, 0.16, 0xffffd090, false});
                debris(rng, e, 22, 110);
                dust(rng, e, 24);
                sparks(rng, e.where, 0, kPi, 26, 200, 0xffffb040);
                addTrauma(0.8);
                screenFlash_ = 1.0;
                break;
            case GameEvent::CometShot:
                flashes_.push_back({e.where, e.angle, e.look, 0.14, 0.14});
                bursts_.push_back({e.where, 8, 140, 0.16, 0.16, 0xffc8f0ff, false});
                debris(rng, e, 12, 100);
                sparks(rng, e.where, 0, kPi, 24, 190, 0xff80d0ff);
                if (e.points > 0) popUps_.push_back({e.where, "+" + std::to_string(e.points), 1.0, 1.0});
                addTrauma(0.45);
                break;
            case GameEvent::WallHit:
                // Back the way the bullet came, fanned out.
                sparks(rng, e.where, e.angle + kPi, 1.1, 6, 120, 0xffffe080);
                bursts_.push_back({e.where, 2, 0, 0.04, 0.04, 0xfffff0c0, false});
                break;
            case GameEvent::Bounce:
                if (e.motion.norm() > 40) sparks(rng, e.where, 0, kPi, 3, 70, 0xffc0d0ff);
                break;
            case GameEvent::PickupTaken:
                bursts_.push_back({e.where, 6, 90, 0.35, 0.35, 0xff80ff90, true});
                for (int i = 0; i < 16; ++i) {
                    const double angle = rng.range(0, kTwoPi);
                    Particle p;
                    p.position = e.where;
                    p.velocity = direction(angle) * rng.range(14, 70);
                    p.life = p.maxLife = rng.range(0.3, 0.9);
                    p.color = 0xff80ff90;
                    particles_.push_back(p);
                }
                break;
            case GameEvent::ShipRespawn:
                bursts_.push_back({e.where, 26, -70, 0.35, 0.35, 0xff80e0ff, true});
                break;
            case GameEvent::ExtraLife:
                popUps_.push_back({e.where + Vec2(0, 30), "1UP", 1.2, 1.2});
                break;
            case GameEvent::WaveCleared:
                banner_ = "WAVE " + std::to_string(e.size) + " CLEARED";
                bannerLife_ = bannerMaxLife_ = 1.8;
                bursts_.push_back({e.where, 10, 520, 0.6, 0.6, 0xffffd678, true});
                addTrauma(0.12);
                break;
            case GameEvent::WaveStart:
                if (e.size > 1) {
                    banner_ = "WAVE " + std::to_string(e.size);
                    bannerLife_ = bannerMaxLife_ = 1.3;
                }
                break;
            case GameEvent::GameOver:
                addTrauma(1.0);
                break;
            case GameEvent::Thrust:
                for (int i = 0; i < 2; ++i) {
                    const double angle = e.angle + kPi + rng.range(-0.35, 0.35);
                    Particle p;
                    p.position = e.where;
                    p.velocity = e.motion * 0.5 + direction(angle) * rng.range(50, 110);
                    p.life = p.maxLife = rng.range(0.18, 0.4);
                    p.keep = 0.92;
                    p.shape = Shape::Flame;
                    particles_.push_back(p);
                }
                break;
            case GameEvent::CometIn:
                break;
            // Rules 3's foes.
            case GameEvent::FoeDestroyed:
                flashes_.push_back({e.where, e.angle, e.look, 0.14, 0.14});
                bursts_.push_back({e.where, 6, 120, 0.14, 0.14, 0xffff9ce0, false});
                debris(rng, e, 10, 90);
                sparks(rng, e.where, 0, kPi, 18, 170, 0xffff80d0);
                if (e.points > 0) popUps_.push_back({e.where, "+" + std::to_string(e.points), 1.0, 1.0});
                addTrauma(e.size == static_cast<int>(FoeKind::Shard) ? 0.1 : 0.35);
                break;
            case GameEvent::FoeHit:
                flashes_.push_back({e.where, e.angle, e.look, 0.08, 0.08});
                sparks(rng, e.where, 0, kPi, 6, 120, 0xffffe0a0);
                break;
            case GameEvent::FoeFired:
                bursts_.push_back({e.where, 3, -10, 0.05, 0.05, 0xffff90c0, false});
                break;
            case GameEvent::ChainUp:
                popUps_.push_back({e.where + Vec2(0, 14), "X" + std::to_string(e.points), 0.9, 0.9});
                break;
            case GameEvent::FoeIn:
            case GameEvent::PowerUpEnd:
                break;
        }
    }
}

void Particles::tick(double dt) {
    for (Particle& p : particles_) {
        p.position += p.velocity * dt;
        p.velocity *= p.keep;
        p.angle += p.spin * dt;
        p.life -= dt;
    }
    std::erase_if(particles_, [](const Particle& p) { return p.life <= 0; });
    for (Flash& f : flashes_) f.life -= dt;
    std::erase_if(flashes_, [](const Flash& f) { return f.life <= 0; });
    for (Burst& b : bursts_) {
        b.life -= dt;
        b.radius = std::max(0.0, b.radius + b.grow * dt);
    }
    std::erase_if(bursts_, [](const Burst& b) { return b.life <= 0; });
    for (PopUp& p : popUps_) p.life -= dt;
    std::erase_if(popUps_, [](const PopUp& p) { return p.life <= 0; });
    bannerLife_ = std::max(0.0, bannerLife_ - dt);
    screenFlash_ = std::max(0.0, screenFlash_ - kScreenFlashFade * dt);
    trauma_ = std::max(0.0, trauma_ - kTraumaFade * dt);
    // A new direction every tick, from the tick: the same shake on every run and after a seek.
    Rng rng(tick_ * 0xD1B54A32D192ED03ull + 5);
    const double strength = kMostShake * trauma_ * trauma_;
    const double x = rng.range(-1, 1), y = rng.range(-1, 1);
    shake_ = Vec2(x, y) * strength;
}

Vec2 Particles::shake(const EffectLevels& levels) const {
    const double level = std::clamp(levels.shake, 0, 100) / 100.0;
    return Vec2(std::round(shake_.x() * level), std::round(shake_.y() * level));
}

std::size_t Particles::heldBytes() const {
    return particles_.capacity() * sizeof(Particle) + flashes_.capacity() * sizeof(Flash) +
           bursts_.capacity() * sizeof(Burst) + popUps_.capacity() * sizeof(PopUp) + banner_.capacity();
}

void Particles::draw(render::DrawList& list, const render::View& view, double alpha, const Game& game,
                     SpriteCache& sprites, const EffectLevels& levels) const {
    const double flashLevel = std::clamp(levels.flashes, 0, 100) / 100.0;
    const double ahead = alpha * kTickSeconds;
    auto colorOf = [&](const Particle& p) {
        const std::string& sprite = game.look(p.look).sprite;
        return p.look && !sprite.empty() ? sprites.palette(sprite)[p.shade] : Color::fromArgb(p.color);
    };
    for (const Particle& p : particles_) {
        const double share = p.life / p.maxLife;
        const Vec2 c = view.toCanvas(p.position + p.velocity * ahead);
        switch (p.shape) {
            case Shape::Dot:
                list.blendPixel(static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())),
                                Color::fromArgb(p.color).withAlpha(alphaOf(share)));
                break;
            case Shape::Dust:
                // Faint, and fading in as the debris thins out: it lingers after the pieces are gone.
                list.blendPixel(static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())),
                                colorOf(p).withAlpha(alphaOf(std::min(share * 1.5, 1.0), 130)));
                break;
            case Shape::Shard: {
                const double angle = p.angle + p.spin * ahead;
                const Vec2 points[3] = {c + direction(angle) * p.size,
                                        c + direction(angle + 2.3) * (p.size * 0.8),
                                        c + direction(angle + 4.0) * (p.size * 0.9)};
                list.fillPolygon(points, colorOf(p).withAlpha(alphaOf(share * 3)));
                break;
            }
            case Shape::Spark: {
                const Vec2 tail = view.toCanvas(p.position + p.velocity * (ahead - p.size));
                list.drawLine(c, tail, Color::fromArgb(p.color).withAlpha(alphaOf(share * 1.5)));
                break;
            }
            case Shape::Flame: {
                const Color color = flameColor(share);
                const int x = static_cast<int>(std::floor(c.x())), y = static_cast<int>(std::floor(c.y()));
                if (share > 0.5)
                    list.fillRect(x, y, 2, 2, color);
                else
                    list.blendPixel(x, y, color);
                break;
            }
        }
    }
    if (flashLevel <= 0) return;
    for (const Burst& b : bursts_) {
        // Bright at once and gone fast: the share squared.
        const double share = b.life / b.maxLife;
        const Color color = Color::fromArgb(b.color).withAlpha(alphaOf(share * share * flashLevel, 230));
        const Vec2 c = view.toCanvas(b.where);
        const double radius = b.radius + b.grow * ahead;
        if (b.ring)
            list.drawCircle(c, radius, color);
        else
            list.fillCircle(c, radius, color);
    }
    for (const Flash& f : flashes_) {
        const std::string& sprite = game.look(f.look).sprite;
        if (sprite.empty()) continue;
        const double share = f.life / f.maxLife;
        render::SpriteStyle style;
        style.opacity = alphaOf(share * flashLevel, 235);
        const double grow = 1.0 + 0.25 * (1.0 - share);
        list.drawSprite(sprites.silhouette(sprite), view, Transform(f.where, f.angle, Vec2(grow, grow)),
                        style);
    }
    if (screenFlash_ > 0)
        list.fillRect(0, 0, view.canvasWidth(), view.canvasHeight(),
                      Color{255, 235, 220, alphaOf(screenFlash_ * flashLevel, 40)});
}

void Particles::drawWords(render::DrawList& list, const render::View& view, double alpha) const {
    for (const PopUp& p : popUps_) {
        const double share = std::max(0.0, p.life - alpha * kTickSeconds) / p.maxLife;
        const Vec2 c = view.toCanvas(p.where);
        const render::TextSize size = render::measureText(p.text, 1);
        const int rise = static_cast<int>(std::round(16 * (1.0 - share)));
        list.drawText(p.text, static_cast<int>(std::round(c.x())) - size.width / 2,
                      static_cast<int>(std::round(c.y())) - 12 - rise, 1,
                      kGold.withAlpha(alphaOf(share * 2.5)));
    }
    if (bannerLife_ > 0) {
        // Fades in over its first fifth and out over its last third.
        const double age = bannerMaxLife_ - bannerLife_;
        const double share =
            std::min({1.0, age / (bannerMaxLife_ * 0.2), bannerLife_ / (bannerMaxLife_ * 0.33)});
        const render::TextSize size = render::measureText(banner_, 2);
        list.drawText(banner_, (view.canvasWidth() - size.width) / 2, 118, 2,
                      kGold.withAlpha(alphaOf(share)));
    }
}

}  // namespace polar::game
