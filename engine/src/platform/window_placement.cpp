#include "polar/platform/window.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

// Where a canvas lands in a window, and back: plain arithmetic, shared by every platform's Window.
namespace polar::platform {

Window::Placement Window::fit(int canvasWidth, int canvasHeight, int windowWidth, int windowHeight,
                              bool integerOnly) {
    if (canvasWidth <= 0 || canvasHeight <= 0 || windowWidth <= 0 || windowHeight <= 0) return {};
    const double f = std::min(double(windowWidth) / canvasWidth, double(windowHeight) / canvasHeight);
    const double k = std::floor(f);
    Placement p;
    if (k >= 1.0 && (integerOnly || k >= 0.8 * f)) {
        p.width = canvasWidth * int(k);
        p.height = canvasHeight * int(k);
    } else {
        p.width = std::clamp(int(std::floor(canvasWidth * f)), 1, windowWidth);
        p.height = std::clamp(int(std::floor(canvasHeight * f)), 1, windowHeight);
    }
    p.x = (windowWidth - p.width) / 2;
    p.y = (windowHeight - p.height) / 2;
    return p;
}

Vec2 Window::windowToCanvas(int x, int y) const {
    if (last_.width == 0 || last_.height == 0) return {0, 0};
    return {(x + 0.5 - last_.x) * lastCanvasWidth_ / last_.width,
            (y + 0.5 - last_.y) * lastCanvasHeight_ / last_.height};
}

}  // namespace polar::platform
