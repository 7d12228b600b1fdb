#pragma once
#include <cstdint>
#include <vector>

namespace polar {

// An 8-bit RGBA image with straight (not premultiplied) alpha, as PNG files store it. A plain value:
// the PNG codec (polar/platform/png_io.h) reads and writes it, authoring reads its alpha channel.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> pixels;  // row-major, top row first, 0xAARRGGBB

    std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
};

}  // namespace polar
