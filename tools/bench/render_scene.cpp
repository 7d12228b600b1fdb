#include "render_scene.h"

#include <cmath>
#include <cstdint>

namespace polar::bench::render_scene {

render::Canvas makeSpriteArt() {
    render::Canvas art(kSpriteSide, kSpriteSide);
    art.clear(render::kTransparent);
    for (int y = 0; y < kSpriteSide; ++y)
        for (int x = 0; x < kSpriteSide; ++x) {
            const double dx = x + 0.5 - 32.0, dy = y + 0.5 - 32.0, r = std::sqrt(dx * dx + dy * dy);
            if (r < 22.0) {
                const bool stripe = ((x + y) / 6) % 2 == 0;
                art.setPixel(x, y,
                             stripe ? render::Color{230, 120, 40, 255} : render::Color{250, 210, 90, 255});
            } else if (r < 30.0) {
                const auto alpha = std::uint8_t(200.0 - (r - 22.0) * 20.0);
                const bool nose = dx > 0 && std::abs(dy) < 5.0;
                art.setPixel(x, y,
                             nose ? render::Color{255, 255, 255, alpha} : render::Color{80, 160, 255, alpha});
            }
        }
    return art;
}

std::vector<Placement> makePlacements(int count) {
    std::uint32_t state = 12345;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / 16777216.0;
    };
    std::vector<Placement> out;
    for (int i = 0; i < count; ++i) {
        Placement p;
        p.x = -32.0 + next() * (kWidth + 64.0);
        p.y = -32.0 + next() * (kHeight + 64.0);
        p.degrees = next() * 360.0;
        p.scale = 0.5 + next();
        out.push_back(p);
    }
    return out;
}

Transform placementTransform(const render::View& view, const Placement& p) {
    // Canvas y runs down, world y up: the view turns the canvas point back into a world one.
    return Transform(view.toWorld({p.x, p.y}), degToRad(p.degrees), Vec2(p.scale, p.scale));
}

void recordScene(render::DrawList& list, const render::Image& sprite, const render::View& view,
                 const std::vector<Placement>& placements, const render::SpriteStyle& style) {
    list.reset();
    list.clear(kBackground);
    for (const Placement& p : placements) list.drawSprite(sprite, view, placementTransform(view, p), style);
}

}  // namespace polar::bench::render_scene
