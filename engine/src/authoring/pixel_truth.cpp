#include "polar/authoring/pixel_truth.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace polar {

OpaquePixels::OpaquePixels(const AlphaMask& mask, std::uint8_t threshold) : mask_(mask) {
    opaque_.assign(static_cast<std::size_t>(mask.width) * mask.height, 0);
    for (int y = 0; y < mask.height; ++y)
        for (int x = 0; x < mask.width; ++x)
            opaque_[static_cast<std::size_t>(y) * mask.width + x] = mask.opaque(x, y, threshold);
    for (int y = 0; y < mask.height; ++y) {
        for (int x = 0; x < mask.width; ++x) {
            if (!opaque(x, y)) continue;
            Vec2 c = mask.pixelCentre(x, y);
            boundRadius_ = std::max(boundRadius_, (c.cwiseAbs() + Vec2(0.5, 0.5)).norm());
            if (!opaque(x - 1, y) || !opaque(x + 1, y) || !opaque(x, y - 1) || !opaque(x, y + 1))
                boundary_.push_back({x, y});
        }
    }
}

namespace {

// Projections of the square [x, x+1] × [y, y+1] and of a parallelogram (corner c, edges e1, e2) on
// the parallelogram's edge normals; bounding boxes cover the square's own axes.
bool parallelogramMeetsSquare(const Vec2& c, const Vec2& e1, const Vec2& e2, int x, int y) {
    Vec2 normals[2] = {Vec2(-e1.y(), e1.x()), Vec2(-e2.y(), e2.x())};
    Vec2 other[2] = {e2, e1};
    for (int k = 0; k < 2; ++k) {
        const Vec2& n = normals[k];
        double p0 = n.dot(c), p1 = p0 + n.dot(other[k]);
        double lo = std::min(p0, p1), hi = std::max(p0, p1);
        double s0 = n.x() * x + n.y() * y;
        double s1 = s0 + n.x(), s2 = s0 + n.y(), s3 = s0 + n.x() + n.y();
        double slo = std::min({s0, s1, s2, s3}), shi = std::max({s0, s1, s2, s3});
        if (shi <= lo || slo >= hi) return false;
    }
    return true;
}

// Whether a boundary square of `from` overlaps any opaque square of `to`, working in `to`'s pixel
// coordinates (x right, y down, pixel (i, j) = [i, i+1] × [j, j+1]).
bool boundaryMeets(const OpaquePixels& from, const Vec2& pf, const Mat2& lf, const OpaquePixels& to,
                   const Vec2& pt, const Mat2& lt) {
    double det = lt(0, 0) * lt(1, 1) - lt(0, 1) * lt(1, 0);
    if (det == 0.0 || lf(0, 0) * lf(1, 1) - lf(0, 1) * lf(1, 0) == 0.0) return false;
    Mat2 inverse;
    inverse << lt(1, 1) / det, -lt(0, 1) / det, -lt(1, 0) / det, lt(0, 0) / det;
    const AlphaMask& fm = from.mask();
    const AlphaMask& tm = to.mask();
    // from's bound space → to's pixel coordinates: bound q → world → to's bound r → (r.x + w/2, h/2 − r.y).
    Mat2 flip;
    flip << 1, 0, 0, -1;
    Mat2 m = flip * inverse * lf;
    Vec2 offset = flip * (inverse * (pf - pt)) + Vec2(tm.width * 0.5, tm.height * 0.5);
    Vec2 e1 = m.col(0), e2 = m.col(1);
    // A square can only meet `to` if its centre is within reach of to's opaque pixels.
    double reach = to.boundRadius() + 0.75 * (e1.norm() + e2.norm());
    Vec2 toCentre(tm.width * 0.5, tm.height * 0.5);
    for (const auto& [x, y] : from.boundary()) {
        Vec2 q = fm.pixelCentre(x, y);
        Vec2 centre = m * q + offset;
        if ((centre - toCentre).norm() > reach) continue;
        // The square's lower-left bound-space corner q − (½, ½) maps to c; its edges to e1, e2.
        Vec2 c = m * (q - Vec2(0.5, 0.5)) + offset;
        Vec2 corners[3] = {c + e1, c + e2, c + e1 + e2};
        double minX = c.x(), maxX = c.x(), minY = c.y(), maxY = c.y();
        for (const Vec2& k : corners) {
            minX = std::min(minX, k.x());
            maxX = std::max(maxX, k.x());
            minY = std::min(minY, k.y());
            maxY = std::max(maxY, k.y());
        }
        int x0 = static_cast<int>(std::floor(minX)), x1 = static_cast<int>(std::ceil(maxX));
        int y0 = static_cast<int>(std::floor(minY)), y1 = static_cast<int>(std::ceil(maxY));
        x0 = std::max(x0, 0);
        y0 = std::max(y0, 0);
        x1 = std::min(x1, tm.width);
        y1 = std::min(y1, tm.height);
        for (int j = y0; j < y1; ++j)
            for (int i = x0; i < x1; ++i)
                if (to.opaque(i, j) && parallelogramMeetsSquare(c, e1, e2, i, j)) return true;
    }
    return false;
}

}  // namespace

bool opaquePixelsOverlap(const OpaquePixels& a, const Vec2& positionA, const Mat2& linearA,
                         const OpaquePixels& b, const Vec2& positionB, const Mat2& linearB) {
    if (a.empty() || b.empty()) return false;
    double stretchA = linearA.norm(), stretchB = linearB.norm();  // Frobenius ≥ the largest stretch
    if ((positionB - positionA).norm() > a.boundRadius() * stretchA + b.boundRadius() * stretchB)
        return false;
    return boundaryMeets(a, positionA, linearA, b, positionB, linearB) ||
           boundaryMeets(b, positionB, linearB, a, positionA, linearA);
}

}  // namespace polar
