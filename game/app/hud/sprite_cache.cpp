#include "app/hud/sprite_cache.h"

#include <algorithm>

#include "polar/platform/image_file.h"

namespace polar::game {

using render::Color;

namespace {

constexpr Color kMagenta{255, 0, 255, 200};

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

const render::Image& SpriteCache::silhouette(const std::string& logical) {
    if (auto it = silhouettes_.find(logical); it != silhouettes_.end()) return it->second;
    const render::Image& image = get(logical);
    render::Image white(image.width(), image.height());
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (std::uint8_t a = image.pixel(x, y).a; a > 0) white.setPixel(x, y, Color{255, 255, 255, a});
    return silhouettes_.emplace(logical, std::move(white)).first->second;
}

const SpriteCache::Palette& SpriteCache::palette(const std::string& logical) {
    if (auto it = palettes_.find(logical); it != palettes_.end()) return it->second;
    const render::Image& image = get(logical);
    // Opaque texels by brightness (Rec. 601 weights, in whole numbers), ties by row-major order.
    std::vector<std::pair<int, Color>> opaque;
    for (int y = 0; y < image.height(); ++y)
        for (int x = 0; x < image.width(); ++x)
            if (Color c = image.pixel(x, y); c.a >= 192)
                opaque.push_back({299 * c.r + 587 * c.g + 114 * c.b, c});
    std::stable_sort(opaque.begin(), opaque.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    Palette palette;
    palette.fill(Color{200, 190, 170, 255});
    for (std::size_t i = 0; i < palette.size() && !opaque.empty(); ++i)
        palette[i] = opaque[(2 * i + 1) * opaque.size() / (2 * palette.size())].second.withAlpha(255);
    return palettes_.emplace(logical, palette).first->second;
}

}  // namespace polar::game
