#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "math/bit_cast.h"
#include "polar/bound.h"
#include "polar/math.h"

namespace polar {

struct RadiusSample;

// The sector key of direction (x, y) ≠ 0: t = |y| / (|x| + |y|) ∈ [0, 1], monotone in the angle
// inside each quadrant (growing in quadrants 1 and 3, falling in 2 and 4). keyDivisor is its
// |x| + |y|, 0 only for (0, 0). Every sector look-up reads its direction by this key.
inline double keyDivisor(double x, double y) {
    return std::fabs(x) + std::fabs(y);
}
inline double sectorKey(double x, double y) {
    return std::fabs(y) / keyDivisor(x, y);
}
// The same key for two directions A and B through one reciprocal q = 1 / (sA·sB) of their divisors:
// tA = |yA|·sB·q, and tB = |yB|·sA·q (the chord contact path divides once for both).
inline double sectorKeyShared(double y, double otherDivisor, double q) {
    return std::fabs(y) * otherDivisor * q;
}
// The quadrant of direction (x, y), from the sign bits alone (so a ±0 picks a side): 0, 1, 2, 3
// counter-clockwise from +x.
inline std::size_t quadrantOf(double x, double y) {
    std::uint64_t bx = bitCast<std::uint64_t>(x) >> 63, by = bitCast<std::uint64_t>(y) >> 63;
    return 2 * by + (bx ^ by);
}

// The world radius of one sector's piece, read toward world direction w (|w| = wNorm) whose bound
// direction is e = L⁻¹·|det L|·w: offset·|det L|·(|w| / divisor), the divisor n·e for a chord edge
// (h / (n·L⁻¹ŵ): |e| cancels) and |e| for a nearest arc (r / |L⁻¹ŵ|).
inline double sectorRadius(double offset, double absDet, double wNorm, double divisor) {
    return offset * absDet * (wNorm / divisor);
}

// A stand-in for the angle of direction (x, y) that costs one division and no trigonometry:
//   t = sectorKey(x, y),  p = t, 2 − t, 2 + t, 4 − t in quadrants 1, 2, 3, 4,
// so p ∈ [0, 4] grows with the true angle, p(−v) = p(v) + 2 (mod 4), and the axes land on 0, 1, 2, 3
// (4 is the +x axis again, reached from just below it). It orders directions as atan2 does (up to
// rounding), which is all a sorted table needs. The quadrant is applied with copysign, not with
// branches: random directions would mispredict them half the time. (0, 0) has no pseudo-angle.
inline double pseudoAngle(double x, double y) {
    double t = sectorKey(x, y);
    double p = 1.0 - std::copysign(1.0 - t, x);  // t, or 2 − t when x < 0
    return 2.0 - std::copysign(2.0 - p, y);      // p, or 4 − p when y < 0
}
inline double pseudoAngle(const Vec2& v) {
    return pseudoAngle(v.x(), v.y());
}

// The nearest rule itself on samples sorted by angle: the radius of the sample nearest to φ by
// circular distance; a tie (within 1e-12 rad, since angles given in degrees are rounded once as
// radians) goes to the sample first in ascending angle order. Bound::radiusNearest and
// the tables' tie-breaking both call it, so they cannot disagree.
double nearestRuleRadius(const std::vector<RadiusSample>& sorted, double phi);

// A linear part L = R·S prepared once per object per step for radius queries in world directions.
//
// Why L⁻¹·|det L| and not L⁻¹? A bound-space direction only needs L⁻¹ up to a positive factor,
// and sign(det)·adj(L) = L⁻¹·|det L| has the size of L itself: a scale of 1e-6 or 1e6 overflows
// nothing. The world radius formulas carry |det L| where the true L⁻¹ would have been.
// Why derive it rather than store it? adj(L) is L's own entries, swapped and negated, and the
// sign is one stored bit: rebuilding it costs a few exact sign flips, while storing it made every
// per-step pose 40 bytes wider (this and σmin), which a 100k-object scene pays in memory and in
// cache lines on every pair it tests.
struct LinearMap {
    Mat2 linear = Mat2::Identity();  // L
    double absDet = 1.0;             // |det L|; exactly 0 when L is singular or not finite
    double stretchMax = 1.0;         // σmax(L): |L·v| ≤ σmax·|v|
    // σmax/σmin: how much L⁻¹ amplifies rounding in a direction (∞ when singular).
    double condition = 1.0;
    bool mirrored = false;  // det L < 0

    LinearMap() = default;
    explicit LinearMap(const Mat2& linear);
    // L⁻¹·|det L| = sign(det L)·adj(L), entry for entry the same numbers as when it was stored:
    // multiplying by ±1 is exact.
    Mat2 inverseScaled() const {
        double s = mirrored ? -1.0 : 1.0;
        Mat2 m;
        m << s * linear(1, 1), -s * linear(0, 1), -s * linear(1, 0), s * linear(0, 0);
        return m;
    }
    // L⁻¹·|det L|·w, the same bits as inverseScaled() * w (signed zeros included): each product of
    // adj(L)·w takes the sign ±1 before the sum, as the stored matrix had it, since (±a)·b = ±(a·b)
    // exactly; the products do not wait for the sign. The hot path of every pair test.
    Vec2 toBound(const Vec2& w) const {
        double s = mirrored ? -1.0 : 1.0;
        double x = s * (linear(1, 1) * w.x()) - s * (linear(0, 1) * w.y());
        double y = s * (linear(0, 0) * w.y()) - s * (linear(1, 0) * w.x());
        return Vec2(x, y);
    }
    // σmin(L): |L·v| ≥ σmin·|v|. Derived (containers want it; every nearest-rule radius wants the
    // condition number, so that is the one stored).
    double stretchMin() const { return absDet == 0.0 ? 0.0 : absDet / stretchMax; }
    bool singular() const { return absDet == 0.0; }
};

// The outline of one Bound as angular sectors about its centre, looked up by pseudo-angle.
//
// Why sectors? Both rules describe a star-shaped outline whose boundary, inside each angular
// sector, is one simple piece: a straight edge n·p = h (chord; sectors run from sample to sample)
// or a circular arc |p| = r (nearest; sectors run from bisector to bisector). A radius query is
// then: find the sector of the direction, evaluate one piece. The sector is found without atan2 or
// a binary search: a table indexed by pseudo-angle gives the first candidate and a short scan the
// rest. Rays (sector boundaries) are sorted by pseudo-angle; sector j ends at ray j, and sector S
// (after the last ray) is the same piece as sector 0 (before the first ray), so a lookup never wraps.
class Outline {
  public:
    // A boundary between two sectors: a sample direction (chord) or a bisector (nearest).
    struct Ray {
        Vec2 dir = Vec2::UnitX();  // unit, from trig::sincos of the angle
        double pseudo = 0.0;       // pseudoAngle(dir), non-decreasing along the list
        double radius = 0.0;       // chord: the sample's radius (the vertex is radius·dir); nearest: 0
    };
    // One piece of the boundary. Chord: the edge's line n·p = h, n outward (not unit), h = cross(P1, P2) > 0.
    // Nearest: the arc |p| = r (nx = ny = 0). `offset` is h or r: what the radius formula scales.
    struct Sector {
        double nx = 0.0;
        double ny = 0.0;
        double offset = 0.0;    // chord: the line's offset h; nearest: the arc's radius r
        double end = INFINITY;  // the pseudo-angle of the ray that ends the sector (+∞ for sector S)
        // n·(x, y): a chord radius's divisor, and which side of the edge's line (x, y) lies on.
        double dot(double x, double y) const { return nx * x + ny * y; }
    };

    Outline() = default;
    // Samples sorted by angle in [0, 2π), distinct, radii > 0. A chord outline needs 3 or more
    // samples and every gap under π (asserted); one sample is a circle either way.
    Outline(const std::vector<RadiusSample>& sorted, OutlineShape shape);

    OutlineShape shape() const { return shape_; }
    bool chord() const { return shape_ == OutlineShape::Chord; }
    // The rays S (0 for a circle), and S + 1 sectors (see the class comment).
    const std::vector<Ray>& rays() const { return rays_; }
    const std::vector<Sector>& sectors() const { return sectors_; }
    std::size_t rayCount() const { return rays_.size(); }
    // The farthest and the nearest point of the outline from the centre.
    double maxRadius() const { return maxRadius_; }
    double minRadius() const { return minRadius_; }

    // The sector holding pseudo-angle p ∈ [0, 4]: the first j with sectors()[j].end > p, in [0, S].
    std::size_t sectorAt(double p) const {
        std::size_t j = table_[static_cast<std::uint32_t>(p * cellsPerUnit_)];
        // A cell rarely holds a ray and almost never two: step over one without a branch (a random
        // direction would mispredict it), as "p − end ≥ 0", i.e. the sign bit of p − end is clear.
        j += 1u ^ static_cast<std::size_t>(bitCast<std::uint64_t>(p - sectors_[j].end) >> 63);
        while (sectors_[j].end <= p) ++j;
        return j;
    }

    // The sector of direction (x, y) ≠ 0 given t = |y| / (|x| + |y|), found without the pseudo-angle's
    // quadrant arithmetic: the quadrant (from the sign bits) and t index a cell, and each cell holds at
    // most one ray, so one comparison with that ray's t picks the sector. Same sectors as sectorAt
    // (up to which side an exact tie on a ray falls). Cells too crowded for that (very many, very
    // close samples) fall back to sectorAt.
    [[gnu::always_inline]] std::size_t sectorOf(double x, double y, double t) const {
        const Cell& c =
            cells_[quadrantOf(x, y) * cellStride_ + static_cast<std::uint32_t>(t * cellsPerQuadrant_)];
        // t ≥ ray, as the clear sign bit of t − ray: an index, not a branch (it would mispredict).
        std::size_t past = 1u ^ static_cast<std::size_t>(bitCast<std::uint64_t>(t - c.ray) >> 63);
        std::uint32_t j = c.sector[past];
        return j != kCrowded ? j : sectorAt(pseudoAngle(x, y));
    }

    // The world radius toward world direction w (any length, |w| = wNorm > 0) under map m:
    //   e = L⁻¹·|det L|·w (the bound-space direction), its sector by sectorKey(e), then sectorRadius:
    //   chord:   h / (n·L⁻¹ŵ) = h·|det L|·(|w| / (n·e))   (no square root: |e| cancels),
    //   nearest: r / |L⁻¹ŵ|   = r·|det L|·(|w| / |e|).
    // 0 for a singular map, as the plain formula gives. Equal to Bound::worldRadius within
    // rounding.
    double worldRadius(const LinearMap& m, const Vec2& w, double wNorm) const {
        if (m.absDet == 0.0) return 0.0;
        Vec2 e = m.toBound(w);
        if (!(keyDivisor(e.x(), e.y()) > 0.0)) return 0.0;
        std::size_t j = sectorOf(e.x(), e.y(), sectorKey(e.x(), e.y()));
        const Sector& s = sectors_[j];
        if (shape_ == OutlineShape::Chord)
            return sectorRadius(s.offset, m.absDet, wNorm, s.dot(e.x(), e.y()));
        double norm = std::sqrt(e.x() * e.x() + e.y() * e.y());
        double offset =
            nearTie(j, e, norm, m.condition) ? tieOffset(m.inverseScaled() * Vec2(w / wNorm)) : s.offset;
        return sectorRadius(offset, m.absDet, wNorm, norm);
    }
    // Nearest rule: whether bound direction e (|e| = norm) in sector j, read through a map of this
    // condition number, is so close to a bisector that worldRadius lets the plain rule decide.
    bool nearTie(std::size_t j, const Vec2& e, double norm, double condition) const {
        return nearBisector(j, e, norm, kTieBand * condition);
    }

    // The bound-space radius toward bound direction d ≠ 0 (any length).
    double radiusToward(const Vec2& d) const;
    // Whether the bound-space point y (relative to the centre, scaled by k > 0) lies inside or on
    // the outline: |y/k| ≤ radius toward y. k lets callers pass L⁻¹·|det L|·x with k = |det L|.
    bool contains(const Vec2& y, double k = 1.0) const;

  private:
    // A cell of the quadrant table: the sectors below and from the cell's one ray (by t), or kCrowded.
    struct Cell {
        double ray = INFINITY;             // t of the ray inside the cell; +∞ when there is none
        std::uint32_t sector[2] = {0, 0};  // [t < ray, t ≥ ray]
    };
    static constexpr std::uint32_t kCrowded = 0xffffffffu;
    void buildCells();

    // Nearest rule: whether direction e (|e| = norm) lies within `band` radians of a ray (a
    // bisector) of sector j, where rounding alone decides between two samples. The band is
    // kTieBand times the map's condition number: L⁻¹ amplifies the rounding of a world direction
    // (w against w/|w|) by that much, and inside the band the plain rule decides.
    bool nearBisector(std::size_t j, const Vec2& e, double norm, double band = kTieBand) const {
        if (rays_.empty()) return false;
        const Vec2& start = rays_[j == 0 ? rays_.size() - 1 : j - 1].dir;
        const Vec2& end = rays_[j == rays_.size() ? 0 : j].dir;
        return std::fabs(cross(start, e)) <= band * norm || std::fabs(cross(end, e)) <= band * norm;
    }
    // The nearest sample's radius toward bound direction d decided exactly as the plain rule does
    // (Bound::radiusNearest on trig::atan2 of d: ties go to the sample first in angle order),
    // so that the fast path and the plain formulas agree even on exact ties.
    double tieOffset(const Vec2& d) const;
    static constexpr double kTieBand = 1e-11;

    OutlineShape shape_ = OutlineShape::Nearest;
    std::vector<Ray> rays_;
    std::vector<Sector> sectors_{Sector{}};
    std::vector<std::uint32_t> table_{0u, 0u};            // cells + 1 entries (p = 4 is a valid index)
    double cellsPerUnit_ = 0.25;                          // cells / 4
    std::vector<Cell> cells_ = std::vector<Cell>(4 * 2);  // 4 quadrants × (cells + 1): t = 1 is valid
    double cellsPerQuadrant_ = 1.0;
    std::size_t cellStride_ = 2;
    double maxRadius_ = 0.0;
    double minRadius_ = 0.0;
    std::vector<RadiusSample> samples_;  // nearest rule only: the sorted samples, for tieOffset
};

// The two outlines of one Bound, built once with it: under the nearest rule, and under the
// chord rule (the nearest one again where chord is not defined). Private to Bound, so the
// public header shows no table; the engine reads them through OutlineAccess.
struct Bound::Outlines {
    Outline nearest;
    Outline chord;
};

struct OutlineAccess {
    static const Outline& of(const Bound& r, OutlineShape shape) {
        return shape == OutlineShape::Chord ? r.outlines_->chord : r.outlines_->nearest;
    }
};

// The table-driven outline of r under the file's rule, or under a chosen one (same fallback).
inline const Outline& outlineOf(const Bound& r, OutlineShape shape) {
    return OutlineAccess::of(r, shape);
}
inline const Outline& outlineOf(const Bound& r) {
    return outlineOf(r, r.shape());
}

}  // namespace polar
