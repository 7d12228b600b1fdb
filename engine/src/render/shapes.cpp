#include "polar/render/shapes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "polar/render/image.h"
#include "render/blend.h"
#include "render/row_clip.h"

namespace polar::render {

namespace detail {

namespace {

// Coordinates further out than this are pulled in before rounding to integers (far beyond any
// canvas, so no visible pixel changes), which keeps every product below 2⁶³.
constexpr double kFar = 536870912.0;  // 2²⁹

// Paints pixels x0 ≤ x < x1 of row y (already clipped) with the premultiplied colour p.
void paintSpan(Canvas& canvas, int y, int x0, int x1, std::uint32_t p) {
    std::uint32_t* row = canvas.row(y);
    if ((p >> 24) == 255) {
        std::fill(row + x0, row + x1, p);
    } else {
        for (int x = x0; x < x1; ++x) blendInto(row + x, p);
    }
}

// Paints the pixels of row y whose indices lie in [first, last], clipped to the canvas and rows.
void paintClipped(Canvas& canvas, RowClip rows, int y, double first, double last, std::uint32_t p) {
    if (y < rows.begin || y >= rows.end) return;
    first = std::max(first, 0.0);
    last = std::min(last, double(canvas.width() - 1));
    if (first <= last) paintSpan(canvas, y, int(first), int(last) + 1, p);
}

std::int64_t floorDiv(std::int64_t a, std::int64_t b) {
    std::int64_t q = a / b;
    if (a % b != 0 && ((a < 0) != (b < 0))) --q;
    return q;
}

// The integer pixel containing a coordinate, with far coordinates clamped.
std::int64_t pixelOf(double v) {
    return std::int64_t(std::floor(std::clamp(v, -kFar, kFar)));
}

// A line between the pixels containing a and b. Along the major axis every pixel is visited once;
// the minor coordinate is round(t·minor/major) (halves rounded up), computed exactly per pixel,
// so a clipped line shows the same pixels as the whole one. skipA/skipB leave out an end pixel.
void line(Canvas& canvas, RowClip rows, const Vec2& a, const Vec2& b, std::uint32_t p, bool skipA,
          bool skipB) {
    if (!std::isfinite(a.x()) || !std::isfinite(a.y()) || !std::isfinite(b.x()) || !std::isfinite(b.y()))
        return;
    std::int64_t x0 = pixelOf(a.x()), y0 = pixelOf(a.y()), x1 = pixelOf(b.x()), y1 = pixelOf(b.y());
    const bool xMajor = std::abs(x1 - x0) >= std::abs(y1 - y0);
    // Walk from the end with the smaller major coordinate, so a→b and b→a draw the same pixels.
    if ((xMajor ? x1 < x0 : y1 < y0)) {
        std::swap(x0, x1);
        std::swap(y0, y1);
        std::swap(skipA, skipB);
    }
    const std::int64_t major0 = xMajor ? x0 : y0, major1 = xMajor ? x1 : y1;
    const std::int64_t minor0 = xMajor ? y0 : x0, minorSpan = xMajor ? y1 - y0 : x1 - x0;
    const std::int64_t majorSpan = major1 - major0;  // ≥ 0
    // Each pixel's minor coordinate depends on m alone, so the walk may start and stop anywhere.
    const std::int64_t majorLow = xMajor ? 0 : rows.begin;
    const std::int64_t majorLimit = (xMajor ? canvas.width() : rows.end) - 1;
    const std::int64_t first = std::max(major0 + (skipA ? 1 : 0), majorLow);
    const std::int64_t last = std::min(major1 - (skipB ? 1 : 0), majorLimit);
    for (std::int64_t m = first; m <= last; ++m) {
        // minor = minor0 + round((m − major0)·minorSpan / majorSpan) = ⌊(2·t·minorSpan + majorSpan) /
        // (2·majorSpan)⌋
        std::int64_t minor = minor0;
        if (majorSpan != 0) minor += floorDiv(2 * (m - major0) * minorSpan + majorSpan, 2 * majorSpan);
        const std::int64_t x = xMajor ? m : minor, y = xMajor ? minor : m;
        if (x >= 0 && y >= rows.begin && x < canvas.width() && y < rows.end)
            blendInto(canvas.row(int(y)) + x, p);
    }
}

void outline(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color, bool closed) {
    const std::uint32_t p = premultiply(color);
    const std::size_t n = points.size();
    if (n == 0) return;
    if (n == 1) {
        line(canvas, rows, points[0], points[0], p, false, false);
        return;
    }
    // Each segment after the first leaves out its start pixel (the previous segment drew it); the
    // closing segment leaves out both ends.
    for (std::size_t i = 0; i + 1 < n; ++i) line(canvas, rows, points[i], points[i + 1], p, i > 0, false);
    if (closed && n > 2) line(canvas, rows, points[n - 1], points[0], p, true, true);
}

}  // namespace

void fillRect(Canvas& canvas, RowClip rows, int x0, int y0, int w, int h, Color color) {
    const std::int64_t left = std::max<std::int64_t>(x0, 0), top = std::max<std::int64_t>(y0, rows.begin);
    const std::int64_t right = std::min<std::int64_t>(std::int64_t{x0} + w, canvas.width());
    const std::int64_t bottom = std::min<std::int64_t>(std::int64_t{y0} + h, rows.end);
    if (left >= right || top >= bottom) return;
    const std::uint32_t p = premultiply(color);
    for (std::int64_t y = top; y < bottom; ++y) paintSpan(canvas, int(y), int(left), int(right), p);
}

void drawRect(Canvas& canvas, RowClip rows, int x0, int y0, int w, int h, Color color) {
    if (w <= 0 || h <= 0) return;
    if (w <= 2 || h <= 2) return fillRect(canvas, rows, x0, y0, w, h, color);
    fillRect(canvas, rows, x0, y0, w, 1, color);
    fillRect(canvas, rows, x0, y0 + h - 1, w, 1, color);
    fillRect(canvas, rows, x0, y0 + 1, 1, h - 2, color);
    fillRect(canvas, rows, x0 + w - 1, y0 + 1, 1, h - 2, color);
}

void drawLine(Canvas& canvas, RowClip rows, const Vec2& a, const Vec2& b, Color color) {
    line(canvas, rows, a, b, premultiply(color), false, false);
}

void drawPolyline(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color) {
    outline(canvas, rows, points, color, false);
}

void drawPolygon(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color) {
    outline(canvas, rows, points, color, true);
}

void fillPolygon(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color) {
    // Kept between calls (one per thread), so that warm immediate calls allocate nothing.
    thread_local std::vector<double> crossings;
    fillPolygon(canvas, rows, points, color, crossings);
}

void fillPolygon(Canvas& canvas, RowClip rows, std::span<const Vec2> points, Color color,
                 std::vector<double>& crossings) {
    const std::size_t n = points.size();
    if (n < 3) return;
    double yMin = points[0].y(), yMax = points[0].y();
    for (const Vec2& q : points) {
        if (!std::isfinite(q.x()) || !std::isfinite(q.y())) return;
        yMin = std::min(yMin, q.y());
        yMax = std::max(yMax, q.y());
    }
    const std::uint32_t p = premultiply(color);
    const int rowBegin = int(std::clamp(std::floor(yMin - 0.5), double(rows.begin), double(rows.end)));
    const int rowEnd = int(std::clamp(std::ceil(yMax - 0.5) + 1.0, double(rows.begin), double(rows.end)));
    for (int y = rowBegin; y < rowEnd; ++y) {
        const double yc = y + 0.5;
        crossings.clear();
        for (std::size_t i = 0; i < n; ++i) {
            Vec2 a = points[i], b = points[(i + 1) % n];
            if (a.y() == b.y()) continue;
            if (a.y() > b.y()) std::swap(a, b);  // same arithmetic whichever way the edge runs
            // An edge covers a ≤ y < b, so a vertex shared by two edges counts once.
            if (yc < a.y() || yc >= b.y()) continue;
            crossings.push_back(a.x() + (yc - a.y()) * (b.x() - a.x()) / (b.y() - a.y()));
        }
        std::sort(crossings.begin(), crossings.end());
        // Pixels whose centres x + ½ lie in [left, right): ⌈left − ½⌉ ≤ x ≤ ⌈right − ½⌉ − 1.
        for (std::size_t i = 0; i + 1 < crossings.size(); i += 2)
            paintClipped(canvas, rows, y, std::ceil(crossings[i] - 0.5),
                         std::ceil(crossings[i + 1] - 0.5) - 1.0, p);
    }
}

void fillCircle(Canvas& canvas, RowClip rows, const Vec2& centre, double radius, Color color) {
    if (!(radius >= 0.0) || !std::isfinite(radius) || !std::isfinite(centre.x()) ||
        !std::isfinite(centre.y()))
        return;
    const std::uint32_t p = premultiply(color);
    const int rowBegin =
        int(std::clamp(std::floor(centre.y() - radius - 0.5), double(rows.begin), double(rows.end)));
    const int rowEnd =
        int(std::clamp(std::ceil(centre.y() + radius - 0.5) + 1.0, double(rows.begin), double(rows.end)));
    for (int y = rowBegin; y < rowEnd; ++y) {
        const double dy = y + 0.5 - centre.y(), h2 = radius * radius - dy * dy;
        if (h2 < 0.0) continue;
        // |x + ½ − cx| ≤ h  ⇔  ⌈cx − h − ½⌉ ≤ x ≤ ⌊cx + h − ½⌋
        const double h = std::sqrt(h2);
        paintClipped(canvas, rows, y, std::ceil(centre.x() - h - 0.5), std::floor(centre.x() + h - 0.5), p);
    }
}

void drawCircle(Canvas& canvas, RowClip rows, const Vec2& centre, double radius, Color color) {
    if (!(radius >= 0.0) || !std::isfinite(radius) || !std::isfinite(centre.x()) ||
        !std::isfinite(centre.y()))
        return;
    const std::uint32_t p = premultiply(color);
    const double outer = radius + 0.5, inner = radius - 0.5;
    const int rowBegin =
        int(std::clamp(std::floor(centre.y() - outer - 0.5), double(rows.begin), double(rows.end)));
    const int rowEnd =
        int(std::clamp(std::ceil(centre.y() + outer - 0.5) + 1.0, double(rows.begin), double(rows.end)));
    for (int y = rowBegin; y < rowEnd; ++y) {
        const double dy = y + 0.5 - centre.y();
        const double ho2 = outer * outer - dy * dy;
        if (ho2 < 0.0) continue;
        const double ho = std::sqrt(ho2);
        const double o0 = std::ceil(centre.x() - ho - 0.5), o1 = std::floor(centre.x() + ho - 0.5);
        const double hi2 = inner > 0.0 ? inner * inner - dy * dy : -1.0;
        if (hi2 <= 0.0) {
            paintClipped(canvas, rows, y, o0, o1, p);
            continue;
        }
        // The hole: |x + ½ − cx| < hi  ⇔  ⌊cx − hi − ½⌋ + 1 ≤ x ≤ ⌈cx + hi − ½⌉ − 1
        const double hi = std::sqrt(hi2);
        const double i0 = std::floor(centre.x() - hi - 0.5) + 1.0,
                     i1 = std::ceil(centre.x() + hi - 0.5) - 1.0;
        paintClipped(canvas, rows, y, o0, std::min(o1, i0 - 1.0), p);
        paintClipped(canvas, rows, y, std::max(o0, i1 + 1.0), o1, p);
    }
}

}  // namespace detail

void fillRect(Canvas& canvas, int x0, int y0, int w, int h, Color color) {
    detail::fillRect(canvas, detail::allRows(canvas), x0, y0, w, h, color);
}

void drawRect(Canvas& canvas, int x0, int y0, int w, int h, Color color) {
    detail::drawRect(canvas, detail::allRows(canvas), x0, y0, w, h, color);
}

void drawLine(Canvas& canvas, const Vec2& a, const Vec2& b, Color color) {
    detail::drawLine(canvas, detail::allRows(canvas), a, b, color);
}

void drawPolyline(Canvas& canvas, std::span<const Vec2> points, Color color) {
    detail::drawPolyline(canvas, detail::allRows(canvas), points, color);
}

void drawPolygon(Canvas& canvas, std::span<const Vec2> points, Color color) {
    detail::drawPolygon(canvas, detail::allRows(canvas), points, color);
}

void fillPolygon(Canvas& canvas, std::span<const Vec2> points, Color color) {
    detail::fillPolygon(canvas, detail::allRows(canvas), points, color);
}

void fillCircle(Canvas& canvas, const Vec2& centre, double radius, Color color) {
    detail::fillCircle(canvas, detail::allRows(canvas), centre, radius, color);
}

void drawCircle(Canvas& canvas, const Vec2& centre, double radius, Color color) {
    detail::drawCircle(canvas, detail::allRows(canvas), centre, radius, color);
}

}  // namespace polar::render
