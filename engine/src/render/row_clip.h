#pragma once
// Drawing restricted to a band of rows. Every drawing call decides each pixel from the call's own
// arguments alone, never from which rows are being drawn, so drawing a frame band by band (one
// band per thread) writes the same bytes as drawing it whole. These are the banded forms of the
// public calls; the public ones draw the rows [0, height).
#include <span>
#include <string_view>
#include <vector>

#include "polar/math.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"
#include "polar/render/image.h"
#include "polar/render/sprite.h"

namespace polar::render::detail {

// The rows begin ≤ y < end of a canvas that a call may write; 0 ≤ begin ≤ end ≤ height.
struct RowClip {
    int begin = 0;
    int end = 0;
};

inline RowClip allRows(const Canvas& canvas) {
    return {0, canvas.height()};
}

// The rows [top, bottom) a sprite under `toCanvas` may touch before clipping to the canvas: the
// canvas bounding box of the image's corners, a row wider each side for rounding. NaN for a
// non-finite matrix (then nothing is drawn).
struct SpriteRows {
    double top, bottom;
};
SpriteRows spriteRows(const Image& image, const Mat3& toCanvas);

void drawSprite(Canvas& canvas, RowClip rows, const Image& image, const Mat3& toCanvas,
                const SpriteStyle& style);
void clear(Canvas& canvas, RowClip rows, Color color);
void setPixel(Canvas& canvas, RowClip rows, int x, int y, Color color);
void blendPixel(Canvas& canvas, RowClip rows, int x, int y, Color color);
void fillRect(Canvas& canvas, RowClip rows, int x0, int y0, int w, int h, Color color);
void drawRect(Canvas& canvas, RowClip rows, int x0, int y0, int w, int h, Color color);
void drawLine(Canvas& canvas, RowClip rows, const Vec2& a, const Vec2& b, Color color);
void drawPolyline(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color);
void drawPolygon(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color);
void fillPolygon(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color);
// The same with the caller's scratch memory for the edge crossings (at most one per point), so that
// nothing is allocated once it holds points.size() values.
void fillPolygon(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color,
                 std::vector<double>& crossings);
void fillCircle(Canvas& canvas, RowClip rows, const Vec2& centre, double radius, Color color);
void drawCircle(Canvas& canvas, RowClip rows, const Vec2& centre, double radius, Color color);
void drawText(Canvas& canvas, RowClip rows, std::string_view text, int x, int y, int scale, Color color);

}  // namespace polar::render::detail
