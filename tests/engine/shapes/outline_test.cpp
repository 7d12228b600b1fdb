// The table-driven fast path (Outline, LinearMap, testPair) against the plain formulas
// (Bound::radius / worldRadius, testPairPlain) on many random cases, with ties and wrap.
#include "shapes/outline.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <random>

#include "narrow_phase/pair_test.h"
#include "pair_cases.h"
#include "polar/bound.h"
#include "polar/collision.h"

namespace polar {
namespace {

using testing::randomLinear;
using testing::randomRadii;

double relative(double a, double b) {
    return std::fabs(a - b) / std::max({std::fabs(a), std::fabs(b), 1e-300});
}

// The world directions worth testing for radii r under L: random ones, the image of every sample
// direction (exactly on a sample angle), of every bisector, and of directions a hair either side of
// 0/360.
std::vector<Vec2> directions(std::mt19937_64& rng, const Bound& r, const Mat2& l) {
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vec2> out;
    for (int i = 0; i < 40; ++i) {
        double a = unit(rng) * kTwoPi;
        out.push_back((0.1 + 10 * unit(rng)) * Vec2(std::cos(a), std::sin(a)));
    }
    const auto& s = r.samples();
    for (std::size_t k = 0; k < s.size(); ++k) {
        double a = s[k].angle, next = k + 1 < s.size() ? s[k + 1].angle : s[0].angle + kTwoPi;
        double sa, ca, sb, cb;
        trig::sincos(a, sa, ca);
        trig::sincos(0.5 * (a + next), sb, cb);
        out.push_back(l * Vec2(ca, sa));
        out.push_back(l * Vec2(cb, sb));
    }
    for (Vec2 d :
         {Vec2(1, 0), Vec2(1, 1e-17), Vec2(1, -1e-17), Vec2(1, -0.0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)})
        out.push_back(l * d);
    return out;
}

// The bound-space angle distance from d to the nearest nearest-rule bisector of r.
double distanceToBisector(const Bound& r, const Vec2& d) {
    double phi = reduceRadians(std::atan2(d.y(), d.x()));
    const auto& s = r.samples();
    double best = INFINITY;
    for (std::size_t k = 0; k < s.size(); ++k) {
        double next = k + 1 < s.size() ? s[k + 1].angle : s[0].angle + kTwoPi;
        double b = reduceRadians(0.5 * (s[k].angle + next));
        double gap = std::fabs(phi - b);
        best = std::min(best, std::min(gap, kTwoPi - gap));
    }
    return best;
}

double maxGap(const Bound& r) {
    const auto& s = r.samples();
    double gap = s.size() == 1 ? kTwoPi : 0.0;
    for (std::size_t k = 0; k + 1 < s.size(); ++k) gap = std::max(gap, s[k + 1].angle - s[k].angle);
    if (s.size() > 1) gap = std::max(gap, s[0].angle + kTwoPi - s.back().angle);
    return gap;
}

TEST(PseudoAngle, OrdersDirectionsLikeTheAngle) {
    EXPECT_EQ(pseudoAngle(1, 0), 0.0);
    EXPECT_EQ(pseudoAngle(0, 1), 1.0);
    EXPECT_EQ(pseudoAngle(-1, 0), 2.0);
    EXPECT_EQ(pseudoAngle(0, -1), 3.0);
    EXPECT_EQ(pseudoAngle(1, 1), 0.5);
    EXPECT_EQ(pseudoAngle(1, 0.0), 0.0);
    EXPECT_EQ(pseudoAngle(1, -0.0), 4.0);  // the same direction, from the other side: the tables accept both
    EXPECT_LE(pseudoAngle(1, -1e-300), 4.0);  // [0, 4]: 4 is the same direction as 0
    EXPECT_GT(pseudoAngle(1, -1e-300), 3.9);
    double previous = -1;
    for (int i = 0; i < 3600; ++i) {
        double a = kTwoPi * i / 3600;
        double p = pseudoAngle(std::cos(a), std::sin(a));
        EXPECT_GT(p, previous) << i;
        // Opposite directions are 2 apart.
        double q = pseudoAngle(-std::cos(a), -std::sin(a));
        EXPECT_NEAR(std::fmod(q - p + 4, 4), 2.0, 1e-12) << i;
        previous = p;
    }
}

// toBound(w) is the hot path's shortcut for inverseScaled() * w; the narrow phase relies on both
// giving the same bits, signed zeros included (the sign of a zero picks a quadrant of the sector
// look-up), or the fast path and the exact tests would see different directions.
TEST(LinearMap, ToBoundIsInverseScaledTimesTheDirectionToTheBit) {
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> coordinate(-1e3, 1e3);
    auto same = [](double a, double b) {
        return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
    };
    int mirrored = 0;
    for (int i = 0; i < 20000; ++i) {
        Mat2 l = i % 7 == 0 ? Mat2(Vec2(i % 2 ? -2.0 : 2.0, 0.0).asDiagonal()) : randomLinear(rng);
        LinearMap m(l);
        mirrored += m.mirrored;
        // Zeros, where products vanish or cancel exactly.
        Vec2 w(i % 3 == 0 ? 0.0 : coordinate(rng), i % 5 == 0 ? 0.0 : coordinate(rng));
        if (i % 11 == 0) w = -w;
        Vec2 fast = m.toBound(w), reference = m.inverseScaled() * w;
        ASSERT_TRUE(same(fast.x(), reference.x()) && same(fast.y(), reference.y())) << i;
    }
    EXPECT_GT(mirrored, 1000);  // both signs were exercised
}

TEST(LinearMap, InverseScaledAndStretch) {
    Mat2 l = rotationMatrix(0.3) * Vec2(2, -0.5).asDiagonal();
    LinearMap m(l);
    EXPECT_NEAR(m.absDet, 1.0, 1e-15);
    Mat2 product = m.inverseScaled() * l / m.absDet;
    EXPECT_LT((product - Mat2::Identity()).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_NEAR(m.stretchMax, 2.0, 1e-14);
    EXPECT_NEAR(m.stretchMin(), 0.5, 1e-14);
    LinearMap zero(Vec2(0, 3).asDiagonal().toDenseMatrix());
    EXPECT_TRUE(zero.singular());
    EXPECT_EQ(zero.stretchMin(), 0.0);
    EXPECT_EQ(zero.stretchMax, 3.0);
    LinearMap tiny(Vec2(1e-200, 1e-200).asDiagonal().toDenseMatrix());  // det underflows: singular
    EXPECT_TRUE(tiny.singular());
}

TEST(Outline, BoundRadiusMatchesThePlainRule) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int c = 0; c < 400; ++c) {
        bool interpolate;
        Bound r = randomRadii(rng, interpolate);
        for (OutlineShape shape : {OutlineShape::Nearest, OutlineShape::Chord}) {
            const Outline& o = outlineOf(r, shape);
            for (int i = 0; i < 50; ++i) {
                double phi = unit(rng) * kTwoPi;
                Vec2 d(std::cos(phi), std::sin(phi));
                double plain = r.radius(std::atan2(d.y(), d.x()), shape);
                double fast = o.radiusToward(3.0 * d);
                ASSERT_LT(relative(fast, plain), 1e-9) << "case " << c << " phi " << phi;
                // Inside just below the outline, outside just above it.
                EXPECT_TRUE(o.contains(plain * (1 - 1e-9) * d)) << c;
                if (distanceToBisector(r, d) > 1e-6) {
                    EXPECT_FALSE(o.contains(plain * (1 + 1e-9) * d)) << c;
                }
            }
        }
    }
}

TEST(Outline, WorldRadiusMatchesThePlainFormula) {
    std::mt19937_64 rng(7);
    int compared = 0, ties = 0;
    double worst = 0;
    for (int c = 0; c < 600; ++c) {
        bool interpolate;
        Bound r = randomRadii(rng, interpolate);
        Mat2 l = randomLinear(rng);
        LinearMap m(l);
        for (OutlineShape shape : {OutlineShape::Nearest, OutlineShape::Chord}) {
            for (const Vec2& w : directions(rng, r, l)) {
                // Both read the direction w/|w| (as the pair test passes it), so ties round alike.
                double plain = r.worldRadius(l, Vec2(w / w.norm()), shape);
                double fast = outlineOf(r, shape).worldRadius(m, w, w.norm());
                ASSERT_TRUE(std::isfinite(fast));
                double error = relative(fast, plain);
                // Ties (w on a bisector) are decided by the plain rule itself, so they agree too.
                Vec2 d = m.inverseScaled() * w;
                // Where both are ill-conditioned at once, a gap of almost π (the chord passes a hair
                // from the centre, so the radius swings with the last bits of the angle) under a map
                // that stretches 1000:1 or more (L⁻¹ amplifies the rounding of w by as much), neither
                // formula has 4 digits to agree on: skipped.
                if (maxGap(r) >= 0.9 * kPi && m.condition >= 1e3) continue;
                if ((shape == OutlineShape::Nearest || !r.chordDefined()) && distanceToBisector(r, d) < 1e-9)
                    ++ties;
                ASSERT_LT(error, 1e-4) << "case " << c << " w " << w.transpose() << " samples "
                                       << r.samples().size() << " fast " << fast << " plain " << plain;
                // Near a gap of almost π both formulas lose digits (sin Δ of a tiny value, or the
                // cross product of two almost opposite vertices); elsewhere they agree to rounding.
                if (maxGap(r) < 0.9 * kPi && m.condition < 1e3) worst = std::max(worst, error);
                ++compared;
            }
        }
    }
    // Nearly radial edges (two samples 0.1° apart, radii 24 and 31) amplify rounding of the angle
    // a thousandfold, and the map's condition number again: rounding, still far inside 1e-4.
    EXPECT_LT(worst, 1e-8);
    EXPECT_GT(compared, 50000);
    EXPECT_GT(ties, 1000);  // the bisector directions were tested
}

TEST(Outline, NearestTiesAtExactBisectors) {
    // Samples at 0° and 90°: the direction (1, 1) is an exact tie. The plain rule gives the sample
    // first in angle order, and so does the table (it hands ties to the plain rule).
    Bound r(Vec2::Zero(), {{0.0, 10.0}, {kHalfPi, 20.0}, {kPi, 30.0}, {3 * kHalfPi, 40.0}}, false);
    EXPECT_EQ(r.radius(kPi / 4), 10.0);
    EXPECT_EQ(outlineOf(r).radiusToward(Vec2(1, 1)), 10.0);
    EXPECT_EQ(outlineOf(r).worldRadius(LinearMap(Mat2::Identity()), Vec2(3, 3), std::sqrt(18.0)), 10.0);
    // 350° and 10° from a file: 0° is a tie in degrees, the first in angle order (10°) wins.
    auto wrap = Bound::fromDegrees(Vec2::Zero(), {{350, 30}, {10, 20}, {120, 25}, {240, 22}}, false);
    EXPECT_EQ(wrap.radius(0.0), 20.0);
    EXPECT_EQ(outlineOf(wrap).radiusToward(Vec2(1, 0)), 20.0);
    // Off the tie by a millionth of a radian, both agree.
    EXPECT_EQ(outlineOf(r).radiusToward(Vec2(1, 1 - 1e-6)), 10.0);
    EXPECT_EQ(outlineOf(r).radiusToward(Vec2(1 - 1e-6, 1)), 20.0);
    // The wrap: between 270° and 360° the bisector is 315°.
    EXPECT_EQ(outlineOf(r).radiusToward(Vec2(1, -1 + 1e-6)), 10.0);
    EXPECT_EQ(outlineOf(r).radiusToward(Vec2(1 - 1e-6, -1)), 40.0);
}

TEST(Outline, ChordAtSampleAnglesAndAcrossTheWrap) {
    // Samples straddling 0/360 at 350° and 10°, and one exactly at 0 after reduction (360).
    auto r = Bound::fromDegrees(Vec2::Zero(), {{350, 10}, {10, 20}, {120, 15}, {240, 12}}, true);
    const Outline& o = outlineOf(r);
    for (double deg : {350.0, 10.0, 120.0, 240.0, 0.0, 359.999999, 0.000001, 360.0}) {
        double phi = degToRad(deg);
        Vec2 d(std::cos(phi), std::sin(phi));
        EXPECT_NEAR(o.radiusToward(d), r.radius(phi), 1e-12 * r.radius(phi)) << deg;
    }
    EXPECT_NEAR(o.radiusToward(Vec2(1, 0)), r.radius(0.0), 1e-12);
}

TEST(Outline, ManySamplesAndOne) {
    std::vector<RadiusSample> many;
    for (int k = 0; k < 4096; ++k)
        many.push_back({kTwoPi * k / 4096, 20 + 5 * std::sin(7.0 * k * kTwoPi / 4096)});
    Bound r(Vec2::Zero(), many, true);
    EXPECT_EQ(outlineOf(r).rayCount(), 4096u);
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> unit(0, kTwoPi);
    for (int i = 0; i < 20000; ++i) {
        double phi = unit(rng);
        ASSERT_NEAR(outlineOf(r).radiusToward(Vec2(std::cos(phi), std::sin(phi))), r.radius(phi), 1e-10)
            << phi;
    }
    Bound one(Vec2::Zero(), 7.5);
    EXPECT_EQ(outlineOf(one).rayCount(), 0u);
    EXPECT_EQ(outlineOf(one, OutlineShape::Chord).rayCount(), 0u);
    EXPECT_EQ(outlineOf(one).worldRadius(LinearMap(Mat2::Identity()), Vec2(-3, 4), 5.0), 7.5);
}

TEST(Outline, ChordUndefinedFallsBackToNearest) {
    auto two = Bound::fromDegrees(Vec2::Zero(), {{0, 10}, {180, 1}}, false);
    EXPECT_FALSE(two.chordDefined());
    EXPECT_FALSE(outlineOf(two, OutlineShape::Chord).chord());
    EXPECT_EQ(two.radius(0.3, OutlineShape::Chord), 10.0);
    EXPECT_EQ(two.worldRadius(Mat2::Identity(), Vec2(-1, 0.1), OutlineShape::Chord), 1.0);
    auto wide = Bound::fromDegrees(Vec2::Zero(), {{0, 10}, {90, 10}, {180, 10}}, false);  // a 180° gap
    EXPECT_FALSE(wide.chordDefined());
    auto under = Bound::fromDegrees(Vec2::Zero(), {{0, 10}, {179.999, 10}, {270, 10}}, true);
    EXPECT_TRUE(under.chordDefined());
    // Just under 180°: the chord across the gap passes within a hair of the centre, and the table
    // still gives the plain formula's value there.
    double phi = degToRad(90);
    EXPECT_NEAR(outlineOf(under).radiusToward(Vec2(0, 1)), under.radius(phi), 1e-6 * under.radius(phi));
    EXPECT_LT(under.radius(phi), 1e-3);
}

TEST(TestPair, FastPathMatchesThePlainRule) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0, 1);
    int hits = 0, compared = 0, nearTangency = 0;
    for (int c = 0; c < 3000; ++c) {
        bool ia, ib;
        Bounds ba{randomRadii(rng, ia)}, bb{randomRadii(rng, ib)};
        if (rng() % 4 == 0) ba.push_back(Bound(Vec2(30 * unit(rng), 0), 5 + 10 * unit(rng)));
        ObjectFlags fa = kCollisions, fb = kCollisions;
        if (rng() % 5 == 0) (rng() % 2 ? fa : fb) |= kContainer;
        double angle = unit(rng) * kTwoPi, d = 120 * unit(rng);
        ObjectPose a(Vec2(50 * unit(rng), -20), randomLinear(rng), &ba, fa);
        ObjectPose b(a.position + d * Vec2(std::cos(angle), std::sin(angle)), randomLinear(rng), &bb, fb);
        if (c % 50 == 0) b.position = a.position;  // coincident
        for (Accuracy level : {Accuracy::Bounds, Accuracy::Nearest, Accuracy::Chord, Accuracy::Circle}) {
            PairTest fast = testPair(a, b, level), plain = testPairPlain(a, b, level);
            EXPECT_EQ(fast.kind, plain.kind);
            EXPECT_EQ(fast.radiiA, plain.radiiA);
            EXPECT_EQ(fast.radiiB, plain.radiiB);
            EXPECT_EQ(fast.distance, plain.distance);
            EXPECT_LT((fast.normal - plain.normal).norm(), 1e-15);
            // Every pair's radii agree to 1e-9: the tables hand a nearest-rule tie to the plain rule,
            // so ties agree too; the largest differences here (about 5e-10) are radii with a gap
            // near π read through a 1000:1 map, where both formulas lose digits.
            ASSERT_LT(relative(fast.ra, plain.ra), 1e-9) << c << " level " << accuracyName(level);
            ASSERT_LT(relative(fast.rb, plain.rb), 1e-9) << c << " level " << accuracyName(level);
            // The verdicts agree, except where the pair is within that rounding of its tangency
            // (|penetration| at most 1e-9 of the pair's size), where either verdict is right.
            bool tangent = std::fabs(plain.penetration) <= 1e-9 * (plain.ra + plain.rb + plain.distance);
            nearTangency += tangent;
            ASSERT_TRUE(fast.hit == plain.hit || tangent) << c << " level " << accuracyName(level);
            hits += fast.hit;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 4 * 3000);  // every pair at every level
    // Random distances almost never fall within 1e-9 of a tangency: the exemption stays rare.
    EXPECT_LE(nearTangency, compared / 1000);
    EXPECT_GT(hits, compared / 5);
    EXPECT_LT(hits, compared * 4 / 5);
}

}  // namespace
}  // namespace polar
