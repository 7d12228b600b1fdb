// The exact narrow phase (outlinesOverlap, outlineLeaves) against an independent model: each outline
// is bracketed in the world between an inner and an outer polygon (arcs by inscribed chords and by
// circumscribed tangents; straight edges scaled by 1 ∓ 1e-9 about the centre), and the polygons are
// compared by brute force (every edge pair, then point in polygon). Where the brackets agree, the
// exact test must agree too.
#include "narrow_phase/exact_overlap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "narrow_phase/pair_test.h"
#include "polar/bound.h"
#include "polar/collision.h"

namespace polar {
namespace {

// The model uses its own plain point type (no Eigen): independent, and fast in Debug builds too.
struct P {
    double x, y;
};
using Polygon = std::vector<P>;

double orient(const P& a, const P& b, const P& c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

bool onSegment(const P& a, const P& b, const P& p) {
    return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
           p.y <= std::max(a.y, b.y);
}

bool segmentsMeet(const P& a, const P& b, const P& c, const P& d) {
    if (std::max(a.x, b.x) < std::min(c.x, d.x) || std::max(c.x, d.x) < std::min(a.x, b.x) ||
        std::max(a.y, b.y) < std::min(c.y, d.y) || std::max(c.y, d.y) < std::min(a.y, b.y))
        return false;
    double d1 = orient(c, d, a), d2 = orient(c, d, b), d3 = orient(a, b, c), d4 = orient(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return true;
    if (d1 == 0 && onSegment(c, d, a)) return true;
    if (d2 == 0 && onSegment(c, d, b)) return true;
    if (d3 == 0 && onSegment(a, b, c)) return true;
    if (d4 == 0 && onSegment(a, b, d)) return true;
    return false;
}

bool inside(const Polygon& poly, const P& p) {  // crossing number
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const P &a = poly[i], &b = poly[j];
        if ((a.y > p.y) != (b.y > p.y) && p.x < (b.x - a.x) * (p.y - a.y) / (b.y - a.y) + a.x) in = !in;
    }
    return in;
}

bool edgesMeet(const Polygon& p, const Polygon& q) {
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = 0; j < q.size(); ++j)
            if (segmentsMeet(p[i], p[(i + 1) % p.size()], q[j], q[(j + 1) % q.size()])) return true;
    return false;
}

bool polygonsOverlap(const Polygon& p, const Polygon& q) {
    return edgesMeet(p, q) || inside(q, p[0]) || inside(p, q[0]);
}

// The outline of r under the chosen rule, in the world (world centre c, linear part L), pushed out
// (outer) or in (inner) so that inner ⊂ outline ⊂ outer.
Polygon bracket(const Bound& r, OutlineShape shape, const Mat2& l, const Vec2& c, bool outer) {
    const auto& s = r.samples();
    Polygon poly;
    auto put = [&](double angle, double radius) {
        double qx = radius * std::cos(angle), qy = radius * std::sin(angle);
        poly.push_back({c.x() + l(0, 0) * qx + l(0, 1) * qy, c.y() + l(1, 0) * qx + l(1, 1) * qy});
    };
    bool chord = shape == OutlineShape::Chord && r.chordDefined() && s.size() > 1;
    if (chord) {
        for (const RadiusSample& k : s) put(k.angle, k.radius * (outer ? 1 + 1e-9 : 1 - 1e-9));
        return poly;
    }
    if (s.size() == 1) {
        int n = 144;
        double half = kPi / n;
        for (int i = 0; i < n; ++i)
            put(kTwoPi * i / n, s[0].radius * (outer ? (1 + 1e-9) / std::cos(half) : 1 - 1e-9));
        return poly;
    }
    for (std::size_t k = 0; k < s.size(); ++k) {
        double prev = k == 0 ? s.back().angle - kTwoPi : s[k - 1].angle;
        double next = k + 1 < s.size() ? s[k + 1].angle : s[0].angle + kTwoPi;
        double from = 0.5 * (prev + s[k].angle), to = 0.5 * (s[k].angle + next);
        int n = std::max(1, static_cast<int>(std::ceil((to - from) / degToRad(2.5))));
        double half = 0.5 * (to - from) / n;
        double radius = s[k].radius * (outer ? (1 + 1e-9) / std::cos(half) : 1 - 1e-9);
        for (int i = 0; i <= n; ++i) put(from + (to - from) * i / n, radius);
    }
    return poly;
}

Bound randomOverlapRadii(std::mt19937_64& rng, bool& interpolate) {
    std::uniform_real_distribution<double> unit(0, 1);
    static const int kCounts[] = {1, 3, 4, 5, 7, 12, 24, 40};
    int count = kCounts[rng() % std::size(kCounts)];
    std::vector<RadiusSample> samples;
    double base = 5 + 20 * unit(rng), wobble = unit(rng) * 0.8;
    for (int k = 0; k < count; ++k)
        samples.push_back({kTwoPi * (k + 0.4 * unit(rng)) / count, base * (1 - wobble * unit(rng))});
    Bound probe(Vec2::Zero(), samples, false);
    interpolate = probe.chordDefined() && count >= 3 && rng() % 2 == 0;
    return Bound(Vec2(4 * unit(rng) - 2, 4 * unit(rng) - 2), samples, interpolate);
}

Mat2 randomOverlapLinear(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    double s = 0.4 + 2 * unit(rng);
    Vec2 scale(s, rng() % 3 == 0 ? s * (0.3 + 1.5 * unit(rng)) : s);
    if (rng() % 4 == 0) scale.x() = -scale.x();
    if (rng() % 4 == 0) scale.y() = -scale.y();
    return rotationMatrix(unit(rng) * kTwoPi) * scale.asDiagonal();
}

struct Tally {
    int decided = 0, hits = 0, ruleMissedHits = 0;
};

TEST(ExactOverlap, AgreesWithPolygonBracketsOnRandomPairs) {
    std::mt19937_64 rng(2024);
    std::uniform_real_distribution<double> unit(0, 1);
    Tally tally;
    for (int c = 0; c < 1500; ++c) {
        bool ia, ib;
        Bounds ba{randomOverlapRadii(rng, ia)}, bb{randomOverlapRadii(rng, ib)};
        Mat2 la = randomOverlapLinear(rng), lb = randomOverlapLinear(rng);
        ObjectPose a(Vec2(10 * unit(rng), -5), la, &ba, kCollisions);
        double reach = ba[0].maxRadius() * a.stretchMax + bb[0].maxRadius() * LinearMap(lb).stretchMax;
        double angle = unit(rng) * kTwoPi;
        Vec2 pb = a.position + reach * (0.3 + 0.8 * unit(rng)) * Vec2(std::cos(angle), std::sin(angle));
        ObjectPose b(pb, lb, &bb, kCollisions);
        Vec2 ca = a.worldCentre(0), cb = b.worldCentre(0);
        OutlineShape sa = ba[0].shape(), sb = bb[0].shape();
        bool surely = polygonsOverlap(bracket(ba[0], sa, la, ca, false), bracket(bb[0], sb, lb, cb, false));
        bool surelyNot =
            !surely && !polygonsOverlap(bracket(ba[0], sa, la, ca, true), bracket(bb[0], sb, lb, cb, true));
        bool exact = outlinesOverlap(outlineOf(ba[0]), a, outlineOf(bb[0]), b, cb - ca);
        EXPECT_EQ(testPair(a, b, Accuracy::Exact).hit, exact) << c;
        if (surely) {
            EXPECT_TRUE(exact) << "case " << c;
        } else if (surelyNot) {
            EXPECT_FALSE(exact) << "case " << c;
        } else {
            continue;
        }
        ++tally.decided;
        tally.hits += exact;
        tally.ruleMissedHits += exact && !testPair(a, b).hit;
    }
    EXPECT_GT(tally.decided, 1400);
    EXPECT_GT(tally.hits, 300);
    EXPECT_GT(tally.ruleMissedHits, 60);  // cases where only the exact test sees the overlap
}

TEST(ExactOverlap, ContainersAgreeWithPolygonBrackets) {
    std::mt19937_64 rng(77);
    std::uniform_real_distribution<double> unit(0, 1);
    int decided = 0, leaves = 0, ruleMissed = 0;
    for (int c = 0; c < 1500; ++c) {
        bool ih, ic;
        Bounds bh{randomOverlapRadii(rng, ih)}, bc{randomOverlapRadii(rng, ic)};
        Mat2 lh = randomOverlapLinear(rng), lc = randomOverlapLinear(rng) * 3.0;
        ObjectPose box(Vec2(-3, 7), lc, &bc, kCollisions | kContainer);
        double room = outlineOf(bc[0]).minRadius() * box.stretchMin();
        double angle = unit(rng) * kTwoPi;
        Vec2 ph = box.position + room * 1.1 * unit(rng) * Vec2(std::cos(angle), std::sin(angle));
        ObjectPose held(ph, lh, &bh, kCollisions);
        Vec2 cc = box.worldCentre(0), chc = held.worldCentre(0);
        OutlineShape sh = bh[0].shape(), sc = bc[0].shape();
        Polygon heldInner = bracket(bh[0], sh, lh, chc, false), heldOuter = bracket(bh[0], sh, lh, chc, true);
        Polygon wallInner = bracket(bc[0], sc, lc, cc, false), wallOuter = bracket(bc[0], sc, lc, cc, true);
        bool surelyLeaves = !inside(wallOuter, heldInner[0]) || edgesMeet(heldInner, wallOuter);
        bool surelyInside =
            !surelyLeaves && inside(wallInner, heldOuter[0]) && !edgesMeet(heldOuter, wallInner);
        bool exact = outlineLeaves(outlineOf(bh[0]), held, outlineOf(bc[0]), box, chc - cc);
        EXPECT_EQ(testPair(box, held, Accuracy::Exact).hit, exact) << c;
        EXPECT_EQ(testPair(held, box, Accuracy::Exact).hit, exact) << c;
        if (surelyLeaves) {
            EXPECT_TRUE(exact) << "case " << c;
        } else if (surelyInside) {
            EXPECT_FALSE(exact) << "case " << c;
        } else {
            continue;
        }
        ++decided;
        leaves += exact;
        ruleMissed += exact && !testPair(box, held).hit;
    }
    EXPECT_GT(decided, 1400);
    EXPECT_GT(leaves, 200);
    EXPECT_LT(leaves, decided - 200);
    EXPECT_GT(ruleMissed, 50);
}

TEST(ExactOverlap, CrossedThinBarsOverlapOffTheLineOfCentres) {
    // Two bars 200 × 2 crossing like a plus sign, their centres 60 apart along the first bar: the
    // rule looks along the line of centres and misses; the outlines plainly cross.
    Bounds bar{
        Bound::fromDegrees(Vec2::Zero(), {{0.5, 100}, {179.5, 100}, {180.5, 100}, {359.5, 100}}, true)};
    ObjectPose a(Vec2(0, 0), Mat2::Identity(), &bar, kCollisions);
    ObjectPose b(Vec2(60, 30), rotationMatrix(kHalfPi), &bar, kCollisions);
    EXPECT_FALSE(testPair(a, b).hit);
    EXPECT_TRUE(testPair(a, b, Accuracy::Exact).hit);
    ObjectPose far(Vec2(60, 120), rotationMatrix(kHalfPi), &bar, kCollisions);  // bar B ends at y = 20
    EXPECT_FALSE(testPair(a, far, Accuracy::Exact).hit);
}

TEST(ExactOverlap, NearestArcsUnderNonUniformScale) {
    // A circle of radius 10 squashed to an ellipse 20 × 5 (a = 20 along x, b = 5 along y), against a
    // unit circle placed just inside and just outside the ellipse at 45°: the arc's image is exact.
    Bounds circle{Bound(Vec2::Zero(), 10.0)};
    Bounds dot{Bound(Vec2::Zero(), 1.0)};
    ObjectPose ellipse(Vec2(0, 0), Vec2(2.0, 0.5).asDiagonal().toDenseMatrix(), &circle, kCollisions);
    // The ellipse point at parameter 45°: (20 cos, 5 sin); its outward normal ∝ (x/a², y/b²).
    Vec2 onEdge(20 * std::sqrt(0.5), 5 * std::sqrt(0.5));
    Vec2 normal = Vec2(onEdge.x() / 400, onEdge.y() / 25).normalized();
    for (double gap : {-1e-6, 1e-6}) {
        ObjectPose b(onEdge + (1 + gap) * normal, Mat2::Identity(), &dot, kCollisions);
        EXPECT_EQ(testPair(ellipse, b, Accuracy::Exact).hit, gap < 0) << gap;
    }
}

TEST(ExactOverlap, SingularMapsArePoints) {
    Bounds circle{Bound(Vec2::Zero(), 10.0)};
    Mat2 zero = Mat2::Zero();
    ObjectPose a(Vec2(0, 0), Mat2::Identity(), &circle, kCollisions);
    ObjectPose point(Vec2(9.5, 0), zero, &circle, kCollisions);
    ObjectPose farPoint(Vec2(10.5, 0), zero, &circle, kCollisions);
    EXPECT_TRUE(testPair(a, point, Accuracy::Exact).hit);
    EXPECT_FALSE(testPair(a, farPoint, Accuracy::Exact).hit);
    EXPECT_FALSE(testPair(point, farPoint, Accuracy::Exact).hit);
    EXPECT_TRUE(testPair(point, point, Accuracy::Exact).hit);
    ObjectPose flat(Vec2(30, 0), Vec2(0, 1).asDiagonal().toDenseMatrix(), &circle,
                    kCollisions);  // a point too
    EXPECT_FALSE(testPair(a, flat, Accuracy::Exact).hit);
    // A container of scale 0 holds nothing; a held point leaves when it reaches the wall.
    ObjectPose box(Vec2(0, 0), Mat2::Identity(), &circle, kCollisions | kContainer);
    ObjectPose zeroBox(Vec2(0, 0), zero, &circle, kCollisions | kContainer);
    EXPECT_TRUE(testPair(zeroBox, a, Accuracy::Exact).hit);
    EXPECT_FALSE(testPair(box, point, Accuracy::Exact).hit);
    EXPECT_TRUE(testPair(box, farPoint, Accuracy::Exact).hit);
}

}  // namespace
}  // namespace polar
