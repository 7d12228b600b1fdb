#pragma once
#include "polar/math.h"

namespace polar::game {

// A rectangle of canvas pixels, x right and y down from the top-left corner: what a menu row or an
// overlay covers on screen.
struct PixelRect {
    int x = 0, y = 0, width = 0, height = 0;

    bool empty() const { return width <= 0 || height <= 0; }
    // True when the canvas point lies inside (pixel centres are at +0.5).
    bool contains(const Vec2& point) const {
        return point.x() >= x && point.x() < x + width && point.y() >= y && point.y() < y + height;
    }
    // True when the two share at least one pixel.
    bool overlaps(const PixelRect& other) const {
        return !empty() && !other.empty() && x < other.x + other.width && other.x < x + width &&
               y < other.y + other.height && other.y < y + height;
    }
    bool operator==(const PixelRect&) const = default;
};

}  // namespace polar::game
