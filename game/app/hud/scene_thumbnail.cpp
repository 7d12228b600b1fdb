#include "app/hud/scene_thumbnail.h"

#include <cassert>

#include "rules/game.h"

namespace polar::game {

Result<render::Canvas> sceneThumbnail(const AssetFs& assets, SpriteCache& sprites, const std::string& scene,
                                      int factor) {
    assert(factor >= 1 && kScreenWidth % factor == 0 && kScreenHeight % factor == 0);
    Game::Config config;
    config.scene = scene;
    config.reader = assets.reader();
    Result<Game> game = Game::create(config);
    if (!game) return assets.onDisk(game.error());

    render::Canvas frame(kScreenWidth, kScreenHeight);
    DrawOptions options;
    options.hud = false;
    drawGame(frame, *game, sprites, Interpolation{}, Particles{}, 1.0, options);

    render::Canvas small(kScreenWidth / factor, kScreenHeight / factor);
    const int area = factor * factor;
    for (int y = 0; y < small.height(); ++y) {
        for (int x = 0; x < small.width(); ++x) {
            int r = 0, g = 0, b = 0;
            for (int dy = 0; dy < factor; ++dy) {
                for (int dx = 0; dx < factor; ++dx) {
                    render::Color c = frame.pixel(x * factor + dx, y * factor + dy);
                    r += c.r, g += c.g, b += c.b;
                }
            }
            // Rounded to nearest: (sum + area/2) / area.
            small.setPixel(x, y,
                           render::Color{static_cast<std::uint8_t>((r + area / 2) / area),
                                         static_cast<std::uint8_t>((g + area / 2) / area),
                                         static_cast<std::uint8_t>((b + area / 2) / area), 255});
        }
    }
    return small;
}

}  // namespace polar::game
