#include "app/draw.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "polar/bound_outline.h"
#include "polar/platform/image_file.h"
#include "polar/render/sprite.h"
#include "polar/render/text.h"
#include "rules/rng.h"

namespace polar::game {

using render::Color;

namespace {

constexpr Color kHudColor{230, 236, 255, 255};
constexpr Color kHudDim{140, 150, 190, 255};
constexpr Color kMagenta{255, 0, 255, 200};

std::string formatScore(long long v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%07lld", v);
    return buffer;
}

}  // namespace

const render::Image& SpriteCache::get(const std::string& logical) {
    if (auto it = images_.find(logical); it != images_.end()) return it->second;
    std::optional<std::string> path = assets_.resolve(logical);
    render::Image image;
    if (!path) {
        problems_.push_back(
            Error{logical, 0, 0, "sprite image not found in assets/ or any mod", "an image file there"});
    } else if (Result<render::Image> loaded = render::loadImage(*path)) {
        image = std::move(*loaded);
    } else {
        problems_.push_back(loaded.error());
    }
    if (image.empty()) {  // a magenta box marks the missing picture
        image = render::Image(12, 12);
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 12; ++x)
                if (x == 0 || y == 0 || x == 11 || y == 11 || x == y || x == 11 - y)
                    image.setPixel(x, y, kMagenta);
    }
    return images_.emplace(logical, std::move(image)).first->second;
}

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

void Interpolation::capture(const World& world) {
    previous_.clear();
    for (const GameObject& o : world.objects()) previous_.emplace(o.id, o.transform);
}

Transform Interpolation::at(const GameObject& object, double alpha) const {
    auto it = previous_.find(object.id);
    if (it == previous_.end() || alpha >= 1.0) return object.transform;
    const Transform& a = it->second;
    const Transform& b = object.transform;
    // A jump no motion makes in one tick is a wrap across the field: drawn where it landed, not
    // swept across the screen.
    constexpr double kJump = 200;
    if ((b.position() - a.position()).squaredNorm() > kJump * kJump) return b;
    double turn = std::remainder(b.rotation() - a.rotation(), kTwoPi);
    return Transform(a.position() + (b.position() - a.position()) * alpha, a.rotation() + turn * alpha,
                     a.scaleFactors() + (b.scaleFactors() - a.scaleFactors()) * alpha);
}

void drawBoundOutline(render::DrawList& list, const render::View& view, const Bound& bound,
                      const Transform& transform, Color color) {
    Mat3 toCanvas = view.matrix() * transform.matrix();
    list.drawPolygon(boundOutline(bound, toCanvas), color);
    Vec2 c = render::transformPoint(toCanvas, bound.centre());
    list.drawLine(c - Vec2(2, 0), c + Vec2(2, 0), color);
    list.drawLine(c - Vec2(0, 2), c + Vec2(0, 2), color);
}

void drawCentredText(render::Canvas& canvas, const std::string& text, int y, int scale, Color color) {
    render::TextSize size = render::measureText(text, scale);
    render::drawText(canvas, text, (canvas.width() - size.width) / 2, y, scale, color);
}

void drawGame(render::Canvas& canvas, const Game& game, SpriteCache& sprites,
              const Interpolation& interpolation, const Particles& particles, double alpha,
              const DrawOptions& options) {
    render::View view(canvas.width(), canvas.height());
    // One list per thread (replays are verified on several at once), reset each frame, so a warm
    // frame allocates nothing for its commands.
    thread_local render::DrawList list;
    list.reset();
    list.clear(Color{6, 6, 14, 255});
    const World& world = game.world();

    // Things in creation order, the arena first (it is the scene's first container), so later
    // objects draw over earlier ones exactly as they were made.
    for (const GameObject& object : world.objects()) {
        const std::string& sprite = game.lookOf(object).sprite;
        if (sprite.empty()) continue;
        Kind kind = game.kindOf(object.id);
        render::SpriteStyle style;
        if (kind == Kind::Ship && game.shipProtected()) {
            // Blink while invulnerable; a shield shows as a ring instead.
            if (game.shieldLeft() <= 0 && (game.tickCount() / 6) % 2 == 0) style.opacity = 90;
        }
        if (kind == Kind::Pickup)
            style.opacity = static_cast<std::uint8_t>(200 + 55 * ((game.tickCount() / 8) % 2));
        list.drawSprite(sprites.get(sprite), view, interpolation.at(object, alpha), style);
        if (kind == Kind::Ship && game.shieldLeft() > 0) {
            Vec2 c = view.toCanvas(interpolation.at(object, alpha).position());
            double r = object.boundsOrEmpty().empty() ? 12 : object.boundsOrEmpty().front().maxRadius() + 4;
            std::uint8_t a = game.shieldLeft() < 1.5 && (game.tickCount() / 5) % 2 ? 60 : 150;
            list.drawCircle(c, r, Color{120, 220, 255, a});
        }
    }
    particles.draw(list, view, alpha);

    if (options.debugOverlay) {
        for (const GameObject& object : world.objects()) {
            Color color = object.has(kContainer)                  ? Color{255, 200, 40, 255}
                          : world.collidedWith(object.id).empty() ? Color{80, 255, 120, 220}
                                                                  : Color{255, 70, 70, 255};
            for (const Bound& bound : object.boundsOrEmpty())
                drawBoundOutline(list, view, bound, interpolation.at(object, alpha), color);
        }
        for (const PairReport& hit : world.hits()) {
            const GameObject& a = world.objects()[hit.a];
            const GameObject& b = world.objects()[hit.b];
            list.drawLine(view.toCanvas(a.transform.position()), view.toCanvas(b.transform.position()),
                          Color{255, 80, 80, 200});
        }
    }

    if (options.hud) {
        list.drawText(formatScore(game.score()), 6, 5, 2, kHudColor);
        list.drawText("HI " + formatScore(static_cast<long long>(
                                  std::max<std::uint64_t>(options.highScore, game.score()))),
                      canvas.width() / 2 - 48, 5, 1, kHudDim);
        char wave[32];
        std::snprintf(wave, sizeof wave, "WAVE %d", game.wave());
        render::TextSize size = render::measureText(wave, 1);
        list.drawText(wave, canvas.width() - size.width - 6, 5, 1, kHudColor);
        const render::Image& ship = sprites.get(game.shipSprite());
        for (int i = 0; i < std::min(game.lives(), 8); ++i) {
            Transform icon(view.toWorld(Vec2(14 + 14.0 * i, 30)), kHalfPi, Vec2(0.6, 0.6));
            list.drawSprite(ship, view, icon);
        }
    }
    list.draw(canvas, options.tasks);
}

}  // namespace polar::game
