#include "polar/authoring/alpha_mask.h"

#include <cmath>
#include <cstdint>

namespace polar {

AlphaMask alphaMaskOf(const RgbaImage& image) {
    AlphaMask mask{image.width, image.height, {}};
    mask.alpha.reserve(image.pixels.size());
    for (std::uint32_t p : image.pixels) mask.alpha.push_back(static_cast<std::uint8_t>(p >> 24));
    return mask;
}

void AlphaMask::pixelAt(const Vec2& p, int& x, int& y) const {
    x = static_cast<int>(std::floor(p.x() + width * 0.5));
    y = static_cast<int>(std::floor(height * 0.5 - p.y()));
}

}  // namespace polar
