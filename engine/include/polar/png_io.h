#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "polar/alpha_mask.h"
#include "polar/error.h"

namespace polar {

// An 8-bit RGBA image with straight (not premultiplied) alpha, as PNG files store it.
struct RgbaImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint32_t> pixels;  // row-major, top row first, 0xAARRGGBB

    std::uint32_t at(int x, int y) const { return pixels[static_cast<std::size_t>(y) * width + x]; }
    AlphaMask alphaMask() const;
};

// Reads a PNG (through SDL2_image). A missing or corrupt file is an Error naming it.
Result<RgbaImage> loadPng(const std::string& path);
// Writes a PNG atomically: to a temporary file in the same folder, then renamed over `path`, so a
// crash leaves the old file or the new one, never a torn one.
std::optional<Error> savePng(const std::string& path, const RgbaImage& image);

}  // namespace polar
