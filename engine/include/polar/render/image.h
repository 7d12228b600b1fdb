#pragma once
#include <cstdint>
#include <vector>

#include "polar/render/color.h"

namespace polar::render {

class Canvas;

// A picture to draw as a sprite: pixels kept premultiplied (colour already multiplied by alpha),
// row-major, 0xAARRGGBB, row 0 at the top.
//
// Why premultiplied? Blending a premultiplied texel s over a destination d is one multiply per
// channel, d' = s + d·(255 − a)/255, with no division and no special case for a = 0; converting
// once at load time keeps that out of the per-pixel loop. An Image is a plain value: share a heavy
// one between objects through a std::shared_ptr<const Image> (see loadImage in image_file.h).
class Image {
  public:
    // A region that holds every visible (non-transparent) texel: the texel squares' bounds along
    // x, y, x + y and x − y (an octagon), in texel coordinates (y down, origin top-left). It only
    // grows, so it stays conservative when pixels are cleared; the renderer skips what lies outside.
    struct VisibleRegion {
        int minX = 0, maxX = 0;        // x ∈ [minX, maxX]
        int minY = 0, maxY = 0;        // y ∈ [minY, maxY]
        int minSum = 0, maxSum = 0;    // x + y ∈ [minSum, maxSum]
        int minDiff = 0, maxDiff = 0;  // x − y ∈ [minDiff, maxDiff]
        bool empty = true;             // no visible texel at all
    };

    Image() = default;
    // A width × height image, all transparent. Sizes must be positive; drawSprite draws images of
    // at most 32767 pixels a side.
    Image(int width, int height);
    // The pixels of a canvas (read as straight alpha), premultiplied.
    static Image fromCanvas(const Canvas& canvas);

    // Size in pixels; an empty (default-constructed) image is 0 × 0.
    int width() const { return width_; }
    int height() const { return height_; }
    bool empty() const { return width_ == 0; }

    // Sets (x, y) to the straight-alpha colour c (stored premultiplied); 0 ≤ x < width, 0 ≤ y < height.
    void setPixel(int x, int y, Color c);
    // The straight-alpha colour at (x, y), rounded back from premultiplied (exact when a is 0 or 255).
    Color pixel(int x, int y) const;
    // The premultiplied pixels, width·height of them, row-major.
    const std::uint32_t* premultiplied() const { return pixels_.data(); }
    // Where the visible texels are (see VisibleRegion).
    const VisibleRegion& visibleRegion() const { return visible_; }

  private:
    void markVisible(int x, int y);

    int width_ = 0;
    int height_ = 0;
    std::vector<std::uint32_t> pixels_;
    VisibleRegion visible_;
};

// The premultiplied form of a straight-alpha colour: each channel c becomes round(c·a/255).
std::uint32_t premultiply(Color c);
// The straight-alpha colour of a premultiplied value: each channel becomes round(c·255/a).
Color unpremultiply(std::uint32_t premultipliedArgb);

}  // namespace polar::render
