#include "polar/render/sprite.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "render/blend.h"
#include "render/row_clip.h"
#include "render/sprite_span.h"

namespace polar::render {

namespace {

// Texel coordinates are walked in 32.32 fixed point: value / 2³² texels.
constexpr double kFixedOne = 4294967296.0;
// Limits that keep every 64-bit product below 2⁶²: a sprite shrunk more than 2¹⁶ times (less than a
// pixel for any image) or centred more than 2⁴⁰ pixels away from the canvas is not drawn.
constexpr double kMaxTexelsPerPixel = 65536.0;
constexpr double kMaxCentre = 1099511627776.0;
// Images wider or taller than this are not drawn (loadImage refuses them).
constexpr int kMaxImageSide = 32767;

bool setUp(const Canvas& canvas, const Image& image, const Mat3& m, detail::PreparedSprite& s) {
    const double l00 = m(0, 0), l01 = m(0, 1), l10 = m(1, 0), l11 = m(1, 1);
    const double cx = m(0, 2), cy = m(1, 2);
    if (!std::isfinite(l00) || !std::isfinite(l01) || !std::isfinite(l10) || !std::isfinite(l11))
        return false;
    if (!(std::abs(cx) < kMaxCentre) || !(std::abs(cy) < kMaxCentre)) return false;
    const double det = l00 * l11 - l01 * l10;
    if (det == 0.0 || !std::isfinite(det)) return false;
    // L⁻¹ = [l11, −l01; −l10, l00] / det maps canvas offsets to bound-space offsets.
    const double i00 = l11 / det, i01 = -l01 / det, i10 = -l10 / det, i11 = l00 / det;
    for (double v : {i00, i01, i10, i11})
        if (!(std::abs(v) <= kMaxTexelsPerPixel)) return false;

    const double hw = image.width() / 2.0, hh = image.height() / 2.0;
    const detail::SpriteRows rows = detail::spriteRows(image, m);
    const double top = std::max(rows.top, 0.0);
    const double bottom = std::min(rows.bottom, double(canvas.height()));
    if (!(top < bottom)) return false;
    s.rowBegin = int(top);
    s.rowEnd = int(bottom);

    // Anchor: the pixel containing the sprite's centre. Its centre's offset from c is computed
    // exactly (a − c is exact for a = ⌊c⌋), so moving a sprite by whole pixels moves its pixels.
    s.ax = std::int64_t(std::floor(cx));
    s.ay = std::int64_t(std::floor(cy));
    const double dx = (double(s.ax) - cx) + 0.5, dy = (double(s.ay) - cy) + 0.5;
    // Bound space q = L⁻¹·(p − c); texel space t = (q.x + w/2, h/2 − q.y), y down, origin top-left.
    const double tx = (i00 * dx + i01 * dy) + hw;
    const double ty = hh - (i10 * dx + i11 * dy);
    s.ua = std::llround(tx * kFixedOne);
    s.va = std::llround(ty * kFixedOne);
    s.dux = std::llround(i00 * kFixedOne);
    s.duy = std::llround(i01 * kFixedOne);
    s.dvx = std::llround(-i10 * kFixedOne);
    s.dvy = std::llround(-i11 * kFixedOne);
    return true;
}

}  // namespace

namespace detail {

SpriteRows spriteRows(const Image& image, const Mat3& m) {
    // The canvas bounding box of the four corners, one row wider each side for rounding.
    const double l10 = m(1, 0), l11 = m(1, 1), cy = m(1, 2);
    const double hw = image.width() / 2.0, hh = image.height() / 2.0;
    double yMin = cy, yMax = cy;
    for (double sx : {-hw, hw})
        for (double sy : {-hh, hh}) {
            double y = l10 * sx + l11 * sy + cy;
            yMin = std::min(yMin, y);
            yMax = std::max(yMax, y);
        }
    return {std::floor(yMin - 0.5) - 1.0, std::ceil(yMax - 0.5) + 2.0};
}

void drawSpriteWith(Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style,
                    SpanKernel kernel) {
    drawSpriteWith(canvas, allRows(canvas), image, toCanvas, style, kernel);
}

void drawSprite(Canvas& canvas, RowClip rows, const Image& image, const Mat3& toCanvas,
                const SpriteStyle& style) {
    drawSpriteWith(canvas, rows, image, toCanvas, style, activeSpanKernel().kernel);
}

void drawSpriteWith(Canvas& canvas, RowClip clip, const Image& image, const Mat3& toCanvas,
                    const SpriteStyle& style, SpanKernel kernel) {
    PreparedSprite sprite;
    if (prepareSprite(canvas, image, toCanvas, style, sprite)) drawPrepared(canvas, clip, sprite, kernel);
}

bool prepareSprite(const Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style,
                   PreparedSprite& s) {
    if (image.visibleRegion().empty || style.opacity == 0 || style.tint.a == 0) return false;
    // The kernels pack texel coordinates and the row length into 16-bit lanes.
    if (image.width() > kMaxImageSide || image.height() > kMaxImageSide) return false;
    if (!setUp(canvas, image, toCanvas, s)) return false;

    SpanBatch& p = s.batch;
    p = SpanBatch{};
    p.texels = image.premultiplied();
    p.texelsPerRow = image.width();
    p.dux = s.dux;
    p.dvx = s.dvx;
    // Tint and opacity as premultiplied factors: alpha × tint.a·opacity, colour × tint.c·that.
    const std::uint32_t fa = mul255(style.tint.a, style.opacity);
    p.modulate = fa != 255 || style.tint.r != 255 || style.tint.g != 255 || style.tint.b != 255;
    p.fa = fa;
    p.fr = mul255(style.tint.r, fa);
    p.fg = mul255(style.tint.g, fa);
    p.fb = mul255(style.tint.b, fa);

    // A texel coordinate is inside the image when 0 ≤ U ≤ w·2³² − 1 and 0 ≤ V ≤ h·2³² − 1.
    s.uMax = (std::int64_t(image.width()) << 32) - 1;
    s.vMax = (std::int64_t(image.height()) << 32) - 1;

    // Each row's span is found in two steps that cannot change a pixel's value, only whether a
    // transparent texel gets visited:
    //  1. an estimate in doubles: the steps k (from the anchor column) whose texel coordinates fall
    //     in the visible octagon, widened a little each side so rounding can only add pixels;
    //  2. exact trimming of both ends in integers until their texels lie inside the image, so the
    //     kernels never read outside it.
    //
    // Each band is the strip lo ≤ a·U + b·V ≤ hi of one octagon direction (a, b). Along row y it
    // holds for k between (lo − r(y))/step and (hi − r(y))/step, with r linear in y, so both limits
    // are linear in y too: base + rows·slope, evaluated in doubles.
    // A band nearly parallel to the rows has huge limits whose doubles could round by more than the
    // widening; such a band is left out (it would only have saved work).
    // A band's kind while it is built: only those that limit or pick are kept.
    enum Kind { kLimitsSpan, kPicksRows, kUnused };
    struct Band {
        Kind kind;
        PreparedSprite::Band band;
    };
    // Limits up to 2⁴⁰ carry rounding errors of a few 2⁻¹² pixels, far below the widening of 2⁻⁶.
    constexpr double kLargestLimit = 1099511627776.0;
    constexpr double kWidening = 1.0 / 64.0;
    const double farthestRow = double(std::max(std::abs(s.rowBegin - s.ay), std::abs(s.rowEnd - s.ay)));
    const Image::VisibleRegion& region = image.visibleRegion();
    const std::int64_t one = std::int64_t{1} << 32;
    auto band = [&](int a, int b, int lo, int hi) {
        Band built{};
        PreparedSprite::Band& q = built.band;
        q.r0 = a * s.ua + b * s.va;
        q.perRow = a * s.duy + b * s.dvy;
        q.lo = lo * one;
        q.hi = hi * one;
        const std::int64_t step = a * s.dux + b * s.dvx;
        if (step == 0) {
            built.kind = kPicksRows;
            return built;
        }
        const double inverse = 1.0 / double(step);
        const double kLo = double(q.lo - q.r0) * inverse, kHi = double(q.hi - q.r0) * inverse;
        q.lowBase = std::min(kLo, kHi) - kWidening;
        q.highBase = std::max(kLo, kHi) + kWidening;
        q.slope = -double(q.perRow) * inverse;
        const bool moderate = std::abs(kLo) <= kLargestLimit && std::abs(kHi) <= kLargestLimit &&
                              std::abs(q.slope) * farthestRow <= kLargestLimit;
        built.kind = moderate ? kLimitsSpan : kUnused;
        return built;
    };
    const Band bands[4] = {band(1, 0, region.minX, region.maxX), band(0, 1, region.minY, region.maxY),
                           band(1, 1, region.minSum, region.maxSum),
                           band(1, -1, region.minDiff, region.maxDiff)};
    // The bands that limit spans and those that pick rows, so the row loop tests no kinds.
    s.limitCount = s.pickCount = 0;
    for (const Band& q : bands)
        if (q.kind == kLimitsSpan) s.bands[s.limitCount++] = q.band;
    for (const Band& q : bands)
        if (q.kind == kPicksRows) s.bands[s.limitCount + s.pickCount++] = q.band;
    s.canvasLow = double(-s.ax);
    s.canvasHigh = double(canvas.width() - 1 - s.ax);  // the canvas
    return true;
}

void drawPrepared(Canvas& canvas, RowClip clip, const PreparedSprite& s, SpanKernel kernel) {
    // Spans go to the kernel in batches, so it sets up once per batch rather than once per row.
    constexpr int kBatch = 128;
    Span spans[kBatch];
    SpanBatch p = s.batch;
    p.spans = spans;
    p.spanCount = 0;
    // Only the rows of the clip are drawn; everything above (farthestRow included) depends on the
    // sprite alone, so each row's pixels are the same whatever the clip.
    const int rowBegin = std::max(s.rowBegin, clip.begin), rowEnd = std::min(s.rowEnd, clip.end);
    for (int y = rowBegin; y < rowEnd; ++y) {
        const std::int64_t rows = y - s.ay;
        double kLow = s.canvasLow, kHigh = s.canvasHigh;
        const double rowsAsDouble = double(rows);
        for (int b = 0; b < s.limitCount; ++b) {
            const PreparedSprite::Band& q = s.bands[b];
            const double shift = rowsAsDouble * q.slope;
            kLow = std::max(kLow, q.lowBase + shift);
            kHigh = std::min(kHigh, q.highBase + shift);
        }
        bool empty = false;
        for (int b = 0; b < s.pickCount; ++b) {
            const PreparedSprite::Band& q = s.bands[s.limitCount + b];
            const std::int64_t r = q.r0 + rows * q.perRow;
            empty = empty || r < q.lo || r > q.hi;
        }
        if (empty || !(kLow <= kHigh)) continue;
        // ⌈kLow⌉ and ⌊kHigh⌋; both lie within the canvas columns, far inside the int64 range.
        std::int64_t kMin = std::int64_t(kLow), kMax = std::int64_t(kHigh);
        if (double(kMin) < kLow) ++kMin;
        if (double(kMax) > kHigh) --kMax;

        const std::int64_t ur = s.ua + rows * s.duy, vr = s.va + rows * s.dvy;
        auto insideImage = [&](std::int64_t k) {
            const std::int64_t u = ur + k * s.dux, v = vr + k * s.dvx;
            return u >= 0 && u <= s.uMax && v >= 0 && v <= s.vMax;
        };
        while (kMin <= kMax && !insideImage(kMin)) ++kMin;
        while (kMax >= kMin && !insideImage(kMax)) --kMax;
        if (kMin > kMax) continue;

        Span& span = spans[p.spanCount++];
        span.dst = canvas.row(y) + (s.ax + kMin);
        span.count = int(kMax - kMin + 1);
        span.roomAfter = int(canvas.width() - 1 - (s.ax + kMax));
        span.u = ur + kMin * s.dux;
        span.v = vr + kMin * s.dvx;
        if (p.spanCount == kBatch) {
            kernel(p);
            p.spanCount = 0;
        }
    }
    if (p.spanCount > 0) kernel(p);
}

}  // namespace detail

void drawSprite(Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style) {
    detail::drawSpriteWith(canvas, detail::allRows(canvas), image, toCanvas, style,
                           detail::activeSpanKernel().kernel);
}

void drawSprite(Canvas& canvas, const Image& image, const View& view, const Transform& transform,
                const SpriteStyle& style) {
    drawSprite(canvas, image, Mat3(view.matrix() * transform.matrix()), style);
}

void drawSprite(Canvas& canvas, const Image& image, const Vec2& centre, const SpriteStyle& style) {
    // Bound space is y up and the canvas y down: flip y, translate to the centre.
    Mat3 m = Mat3::Identity();
    m(1, 1) = -1.0;
    m(0, 2) = centre.x();
    m(1, 2) = centre.y();
    drawSprite(canvas, image, m, style);
}

}  // namespace polar::render
