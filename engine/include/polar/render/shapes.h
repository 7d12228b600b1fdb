#pragma once
#include <span>

#include "polar/math.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"

namespace polar::render {

// Shapes are given in canvas coordinates (y down; pixel (x, y) has its centre at (x + ½, y + ½)).
// Map world points first with View::toCanvas or transformPoint. A translucent colour is blended
// "over" the canvas, each pixel once per call. Everything is clipped exactly at the canvas edges.

// Fills the pixels x0 ≤ x < x0 + w, y0 ≤ y < y0 + h.
void fillRect(Canvas& canvas, int x0, int y0, int w, int h, Color color);
// Outlines that rectangle one pixel thick, inside its edges.
void drawRect(Canvas& canvas, int x0, int y0, int w, int h, Color color);

// A one-pixel line from the pixel containing a to the pixel containing b, both ends included
// (Bresenham's stepping on integers, so every compiler draws the same pixels).
void drawLine(Canvas& canvas, const Vec2& a, const Vec2& b, Color color);
// Lines through consecutive points, open at the ends; shared points are drawn once.
void drawPolyline(Canvas& canvas, std::span<const Vec2> points, Color color);
// The closed outline through the points (the last joined back to the first).
void drawPolygon(Canvas& canvas, std::span<const Vec2> points, Color color);
// Fills the pixels whose centres lie inside the polygon (even-odd rule; a centre exactly on a left
// edge is inside, on a right edge outside, so polygons sharing an edge never overlap).
void fillPolygon(Canvas& canvas, std::span<const Vec2> points, Color color);

// Fills the pixels whose centres c satisfy |c − centre| ≤ radius.
void fillCircle(Canvas& canvas, const Vec2& centre, double radius, Color color);
// Outlines the circle about one pixel thick: the centres with radius − ½ < |c − centre| ≤ radius + ½.
void drawCircle(Canvas& canvas, const Vec2& centre, double radius, Color color);

}  // namespace polar::render
