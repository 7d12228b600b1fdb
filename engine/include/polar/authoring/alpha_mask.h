#pragma once
#include <cstdint>
#include <vector>

#include "polar/math.h"
#include "polar/rgba_image.h"

namespace polar {

// The alpha channel of a sprite, and the map between its pixels and bound space.
//
// Why its own type? Bounds generation, bounds checks and the pixel-truth of the accuracy benchmark
// all ask the same two questions of a sprite: which pixels are opaque, and where is a pixel in
// bound space. Bound space has one unit per pixel, its origin at the sprite's centre and y up, while
// image rows run down; pixel (x, y) covers bound-space [x − w/2, x + 1 − w/2] × [h/2 − y − 1, h/2 − y].
struct AlphaMask {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> alpha;  // row-major, top row first

    std::uint8_t at(int x, int y) const { return alpha[static_cast<std::size_t>(y) * width + x]; }
    // Opaque: alpha above the threshold. Outside the image nothing is opaque.
    bool opaque(int x, int y, std::uint8_t threshold = kDefaultThreshold) const {
        return x >= 0 && y >= 0 && x < width && y < height && at(x, y) > threshold;
    }
    // The centre of pixel (x, y) in bound space.
    Vec2 pixelCentre(int x, int y) const { return Vec2(x + 0.5 - width * 0.5, height * 0.5 - y - 0.5); }
    // The pixel holding bound-space point p (may lie outside the image).
    void pixelAt(const Vec2& p, int& x, int& y) const;

    static constexpr std::uint8_t kDefaultThreshold = 127;
};

// The alpha channel of an image (the top byte of each 0xAARRGGBB pixel).
AlphaMask alphaMaskOf(const RgbaImage& image);

}  // namespace polar
