#include "polar/render/image.h"

#include <algorithm>
#include <cassert>

#include "polar/render/canvas.h"
#include "render/blend.h"

namespace polar::render {

using detail::mul255;

std::uint32_t premultiply(Color c) {
    return (std::uint32_t{c.a} << 24) | (mul255(c.r, c.a) << 16) | (mul255(c.g, c.a) << 8) | mul255(c.b, c.a);
}

Color unpremultiply(std::uint32_t p) {
    std::uint32_t a = p >> 24;
    if (a == 0) return kTransparent;
    // c = round(p·255 / a), capped at 255 (a premultiplied channel never exceeds a).
    auto channel = [a](std::uint32_t v) {
        std::uint32_t c = (v * 255 + a / 2) / a;
        return std::uint8_t(c > 255 ? 255 : c);
    };
    return {channel((p >> 16) & 0xFF), channel((p >> 8) & 0xFF), channel(p & 0xFF), std::uint8_t(a)};
}

Image::Image(int width, int height)
    : width_(width), height_(height), pixels_(std::size_t(width) * height, 0) {
    assert(width > 0 && height > 0);
}

Image Image::fromCanvas(const Canvas& canvas) {
    Image image(canvas.width(), canvas.height());
    for (int y = 0; y < canvas.height(); ++y) {
        const std::uint32_t* row = canvas.row(y);
        for (int x = 0; x < canvas.width(); ++x) image.setPixel(x, y, Color::fromArgb(row[x]));
    }
    return image;
}

void Image::setPixel(int x, int y, Color c) {
    assert(x >= 0 && y >= 0 && x < width_ && y < height_);
    const std::uint32_t p = premultiply(c);
    pixels_[std::size_t(y) * width_ + x] = p;
    if (p != 0) markVisible(x, y);
}

void Image::markVisible(int x, int y) {
    // Texel (x, y) is the square [x, x+1] × [y, y+1]: x + y spans [x+y, x+y+2], x − y [x−y−1, x−y+1].
    VisibleRegion& r = visible_;
    if (r.empty) {
        r = {x, x + 1, y, y + 1, x + y, x + y + 2, x - y - 1, x - y + 1, false};
        return;
    }
    r.minX = std::min(r.minX, x);
    r.maxX = std::max(r.maxX, x + 1);
    r.minY = std::min(r.minY, y);
    r.maxY = std::max(r.maxY, y + 1);
    r.minSum = std::min(r.minSum, x + y);
    r.maxSum = std::max(r.maxSum, x + y + 2);
    r.minDiff = std::min(r.minDiff, x - y - 1);
    r.maxDiff = std::max(r.maxDiff, x - y + 1);
}

Color Image::pixel(int x, int y) const {
    assert(x >= 0 && y >= 0 && x < width_ && y < height_);
    return unpremultiply(pixels_[std::size_t(y) * width_ + x]);
}

}  // namespace polar::render
