#include "app/hud/sprite_cache.h"

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

}  // namespace polar::game
