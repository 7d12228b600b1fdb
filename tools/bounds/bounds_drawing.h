#pragma once
// What `view` and `edit` draw alike: the colours of bounds drawings and the angle convention's compass.
#include "polar/render/render.h"

namespace polar::bounds_tool {

using render::Color;

inline constexpr Color kBackground{22, 24, 34, 255};
inline constexpr Color kImageArea{40, 44, 60, 255};
inline constexpr Color kPixelGrid{52, 57, 78, 255};
inline constexpr Color kAxes{110, 118, 160, 255};
inline constexpr Color kText{225, 230, 250, 255};
inline constexpr Color kDimText{150, 158, 190, 255};
// One colour per Bound of the file, in file order.
inline constexpr Color kRadiiColors[] = {
    {255, 214, 80, 255}, {90, 220, 255, 255}, {255, 120, 220, 255}, {150, 255, 120, 255}};

// An arrow from `from` to `to`, its head at `to`.
void drawArrow(render::Canvas& canvas, const Vec2& from, const Vec2& to, Color color);
// The angle convention around canvas point c: 0° toward +x (right), 90° toward +y (up), angles
// growing counter-clockwise.
void drawCompass(render::Canvas& canvas, const Vec2& c);

}  // namespace polar::bounds_tool
