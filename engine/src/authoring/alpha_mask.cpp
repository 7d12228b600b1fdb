#include "polar/authoring/alpha_mask.h"

#include <cmath>

namespace polar {

void AlphaMask::pixelAt(const Vec2& p, int& x, int& y) const {
    x = static_cast<int>(std::floor(p.x() + width * 0.5));
    y = static_cast<int>(std::floor(height * 0.5 - p.y()));
}

}  // namespace polar
