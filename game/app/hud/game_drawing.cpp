#include "app/hud/game_drawing.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "app/hud/backdrop.h"
#include "app/hud/lettering.h"
#include "polar/bound_outline.h"
#include "polar/render/sprite.h"
#include "polar/render/text.h"

namespace polar::game {

using render::Color;

namespace {

std::string formatScore(long long v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%07lld", v);
    return buffer;
}

// Rules 3: the score multiplier beside the score, with a bar of the time before it drops a step, and
// under the lives each power-up under way with its seconds left and a bar that empties.
void drawArcadeHud(render::DrawList& list, const Game& game) {
    if (game.multiplier() > 1) {
        const std::string times = "X" + std::to_string(game.multiplier());
        list.drawText(times, 96, 5, 2, Color{255, 220, 90, 255});
        const int width = static_cast<int>(render::measureText(times, 2).width);
        const double left = std::clamp(game.chainLeft() / 2.5, 0.0, 1.0);
        list.drawLine(Vec2(96, 21), Vec2(96 + width * left, 21), Color{255, 220, 90, 200});
    }
    struct Shown {
        PickupKind kind;
        const char* name;
        double most;  // seconds it lasts, for the bar
        Color color;
    };
    constexpr Shown kShown[] = {{PickupKind::Spread, "SPREAD", 10, Color{255, 210, 74, 255}},
                                {PickupKind::Rapid, "RAPID", 8, Color{92, 255, 116, 255}},
                                {PickupKind::Barrier, "BARRIER", 7, Color{208, 112, 255, 255}}};
    int y = 40;
    for (const Shown& shown : kShown) {
        const double left = game.powerUpLeft(shown.kind);
        if (left <= 0) continue;
        char line[32];
        std::snprintf(line, sizeof line, "%s %.1f", shown.name, left);
        list.drawText(line, 6, y, 1, shown.color);
        const double part = std::clamp(left / shown.most, 0.0, 1.0);
        list.drawLine(Vec2(6, y + 9), Vec2(6 + 60 * part, y + 9), shown.color);
        y += 13;
    }
}

}  // namespace

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
    // The world is drawn through a view the shake moves; the HUD through one that keeps still.
    const render::View screen(canvas.width(), canvas.height());
    render::View view = screen;
    const Vec2 shake = particles.shake(options.effects);  // canvas pixels, y down
    view.setCentre(screen.centre() + Vec2(-shake.x(), shake.y()));
    // One list per thread (replays are verified on several at once), reset each frame, so a warm
    // frame allocates nothing for its commands.
    thread_local render::DrawList list;
    list.reset();
    // The backdrop keeps still under the shake: it is far away.
    SceneLook look = lookFor(options.backdrop ? backdropOf(game) : Backdrop::Plain);
    if (options.backdrop && game.rules().accent) {
        const auto& rgb = *game.rules().accent;
        look.accent = Color{rgb[0], rgb[1], rgb[2], 255};
    }
    drawBackdrop(list, canvas.width(), canvas.height(), look.backdrop, game.seed(), game.tickCount(), alpha,
                 options.effects);
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
        if (kind == Kind::Bullet) {
            // A trail behind the bullet, along its motion, brightest at the bullet.
            const Vec2 at = interpolation.at(object, alpha).position();
            const double speed = object.velocity.norm();
            if (speed > 1) {
                const Vec2 back = object.velocity * (-std::min(16.0, speed * 0.035) / speed);
                list.drawLine(view.toCanvas(at + back), view.toCanvas(at + back * 0.45),
                              Color{255, 200, 110, 70});
                list.drawLine(view.toCanvas(at + back * 0.45), view.toCanvas(at), Color{255, 236, 170, 150});
            }
        }
        list.drawSprite(sprites.get(sprite), view, interpolation.at(object, alpha), style);
        if (kind == Kind::Ship && game.powerUpLeft(PickupKind::Barrier) > 0) {
            // The barrier: a double violet ring that flickers in its last two seconds.
            Vec2 c = view.toCanvas(interpolation.at(object, alpha).position());
            double r = object.boundsOrEmpty().empty() ? 13 : object.boundsOrEmpty().front().maxRadius() + 6;
            std::uint8_t a =
                game.powerUpLeft(PickupKind::Barrier) < 2 && (game.tickCount() / 4) % 2 ? 70 : 200;
            list.drawCircle(c, r, Color{210, 120, 255, a});
            list.drawCircle(c, r + 2, Color{240, 200, 255, static_cast<std::uint8_t>(a / 2)});
        }
        if (kind == Kind::Ship && game.shieldLeft() > 0) {
            Vec2 c = view.toCanvas(interpolation.at(object, alpha).position());
            double r = object.boundsOrEmpty().empty() ? 12 : object.boundsOrEmpty().front().maxRadius() + 4;
            std::uint8_t a = game.shieldLeft() < 1.5 && (game.tickCount() / 5) % 2 ? 60 : 150;
            list.drawCircle(c, r, Color{120, 220, 255, a});
        }
    }
    particles.draw(list, view, alpha, game, sprites, options.effects);

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
        list.drawText(formatScore(game.score()), 6, 5, 2, look.accent);
        list.drawText("HI " + formatScore(static_cast<long long>(
                                  std::max<std::uint64_t>(options.highScore, game.score()))),
                      canvas.width() / 2 - 48, 5, 1, kHudDim);
        char wave[32];
        std::snprintf(wave, sizeof wave, "WAVE %d", game.wave());
        render::TextSize size = render::measureText(wave, 1);
        list.drawText(wave, canvas.width() - size.width - 6, 5, 1, look.accent);
        if (game.speed() != kMaxGameSpeed) {  // the speed assist, said where the wave is
            const std::string speed = "SPEED " + std::to_string(game.speed()) + "%";
            list.drawText(speed, canvas.width() - size.width - render::measureText(speed, 1).width - 18, 5, 1,
                          kHudDim);
        }
        const render::Image& ship = sprites.get(game.shipSprite());
        for (int i = 0; i < std::min(game.lives(), 8); ++i) {
            Transform icon(screen.toWorld(Vec2(14 + 14.0 * i, 30)), kHalfPi, Vec2(0.6, 0.6));
            list.drawSprite(ship, screen, icon);
        }
        if (game.arcade()) drawArcadeHud(list, game);
        particles.drawWords(list, view, alpha);
    }
    list.draw(canvas, options.tasks);
}

}  // namespace polar::game
