#include "polar/bound.h"

#include <gtest/gtest.h>
#include <Eigen/LU>

#include <cmath>
#include <limits>
#include <random>

namespace polar {
namespace {

// An independent model of an outline, in degrees and with libm, to check the engine against.
struct ModelOutline {
    std::vector<DegreeSample> samples;  // any order, any angle range
    bool interpolate = false;

    // Samples as (reduced degrees, radius), sorted by angle.
    std::vector<DegreeSample> sorted() const {
        std::vector<DegreeSample> s = samples;
        for (DegreeSample& x : s) x[0] = std::fmod(std::fmod(x[0], 360.0) + 360.0, 360.0);
        std::sort(s.begin(), s.end());
        return s;
    }

    // Nearest rule: smallest circular distance, ties to the smaller reduced angle.
    double nearest(double degrees) const {
        std::vector<DegreeSample> s = sorted();
        double best = INFINITY, radius = 0;
        for (const DegreeSample& x : s) {  // ascending, so a strict < keeps the first of a tie
            double d = std::fabs(std::fmod(degrees - x[0] + 720.0 * 4, 360.0));
            d = std::min(d, 360.0 - d);
            if (d < best) best = d, radius = x[1];
        }
        return radius;
    }

    // Straight edges: where the ray at `degrees` crosses the segment between the neighbouring
    // sample points, by solving t·d = P1 + s·(P2 − P1).
    double chord(double degrees) const {
        std::vector<DegreeSample> s = sorted();
        double a = std::fmod(std::fmod(degrees, 360.0) + 360.0, 360.0);
        std::size_t k = s.size() - 1;
        for (std::size_t i = 0; i < s.size(); ++i)
            if (s[i][0] <= a) k = i;
        const DegreeSample& s1 = s[k];
        const DegreeSample& s2 = s[(k + 1) % s.size()];
        auto point = [](const DegreeSample& x) {
            double r = x[0] * M_PI / 180;
            return Vec2(x[1] * std::cos(r), x[1] * std::sin(r));
        };
        Vec2 p1 = point(s1), p2 = point(s2), edge = p2 - p1;
        Vec2 d(std::cos(a * M_PI / 180), std::sin(a * M_PI / 180));
        return (p1.x() * edge.y() - p1.y() * edge.x()) / (d.x() * edge.y() - d.y() * edge.x());
    }

    double radius(double degrees) const { return interpolate ? chord(degrees) : nearest(degrees); }
};

Bound build(const ModelOutline& m, Vec2 centre = Vec2::Zero()) {
    return Bound::fromDegrees(centre, m.samples, m.interpolate);
}

double rad(double degrees) {
    return degToRad(degrees);
}

TEST(Bound, OneSampleIsACircle) {
    Bound circle(Vec2(1, 2), 7.5);
    Bound single = Bound::fromDegrees(Vec2::Zero(), {{123, 4.0}}, false);
    for (double phi = -10; phi < 10; phi += 0.173) {
        EXPECT_EQ(circle.radius(phi), 7.5);
        EXPECT_EQ(single.radius(phi), 4.0);
        EXPECT_EQ(single.radiusChord(phi), 4.0);
    }
    EXPECT_EQ(circle.centre(), Vec2(1, 2));
    EXPECT_EQ(circle.maxRadius(), 7.5);
    EXPECT_FALSE(circle.interpolate());
}

TEST(Bound, SamplesAreSortedAndAnglesReduced) {
    Bound r = Bound::fromDegrees(Vec2::Zero(), {{-90, 5}, {720, 7}, {45, 6}, {-315.5, 8}}, true);
    ASSERT_EQ(r.samples().size(), 4u);
    EXPECT_EQ(r.samples()[0].angle, 0.0);  // 720
    EXPECT_EQ(r.samples()[0].radius, 7);
    EXPECT_DOUBLE_EQ(r.samples()[1].angle, rad(44.5));  // −315.5
    EXPECT_EQ(r.samples()[1].radius, 8);
    EXPECT_DOUBLE_EQ(r.samples()[2].angle, rad(45));
    EXPECT_DOUBLE_EQ(r.samples()[3].angle, rad(270));  // −90
    EXPECT_EQ(r.samples()[3].radius, 5);
    EXPECT_EQ(r.maxRadius(), 8);
    // Radian samples are reduced too.
    Bound q(Vec2::Zero(), {{-kHalfPi, 2}, {5 * kTwoPi + 1.0, 3}}, false);
    EXPECT_NEAR(q.samples()[0].angle, 1.0, 1e-13);
    EXPECT_NEAR(q.samples()[1].angle, 3 * kHalfPi, 1e-15);
}

TEST(Bound, NearestUsesCircularDistance) {
    ModelOutline m{{{0, 10}, {90, 20}, {180, 30}, {270, 40}}, false};
    Bound r = build(m);
    EXPECT_EQ(r.radius(rad(44)), 10);
    EXPECT_EQ(r.radius(rad(46)), 20);
    EXPECT_EQ(r.radius(rad(350)), 10);  // across the wrap, 10° from 0°
    EXPECT_EQ(r.radius(rad(-10)), 10);  // the same direction given negatively
    EXPECT_EQ(r.radius(rad(314)), 40);
    EXPECT_EQ(r.radius(rad(316)), 10);   // nearer 360 than 270
    EXPECT_EQ(r.radius(rad(1000)), 40);  // 1000 − 720 = 280, nearest 270
}

TEST(Bound, NearestMatchesTheModelEverywhere) {
    for (const ModelOutline& m : {ModelOutline{{{0, 10}, {90, 20}, {180, 30}, {270, 40}}, false},
                                  ModelOutline{{{-20, 5}, {15, 9}, {100, 3}, {200.5, 12}}, false},
                                  ModelOutline{{{350, 1}, {10, 2}}, false}}) {
        Bound r = build(m);
        for (double deg = -720.25; deg < 720; deg += 0.5) {  // never exactly on a midpoint
            ASSERT_EQ(r.radius(rad(deg)), m.nearest(deg)) << "at " << deg << " degrees";
        }
    }
}

TEST(Bound, NearestTiesGoToTheSampleFirstInAscendingAngleOrder) {
    // Angles that are exact binary fractions, so the tie is exact in radians too.
    Bound r(Vec2::Zero(), {{1.5, 2.0}, {0.5, 1.0}, {3.0, 3.0}}, false);
    EXPECT_EQ(r.radius(1.0), 1.0);   // halfway between 0.5 and 1.5: 0.5 comes first
    EXPECT_EQ(r.radius(2.25), 2.0);  // halfway between 1.5 and 3.0: 1.5 comes first

    // The same from file degrees: 180° lies halfway between 90° and 270°, and so does 0°.
    Bound d = Bound::fromDegrees(Vec2::Zero(), {{270, 2.0}, {90, 1.0}}, false);
    EXPECT_EQ(d.radius(rad(180)), 1.0);
    EXPECT_EQ(d.radius(0.0), 1.0);
    EXPECT_EQ(d.radius(rad(360)), 1.0);

    // Across the wrap: 0° is 10° from both 350° and 10°; 10° comes first in ascending order.
    Bound w = Bound::fromDegrees(Vec2::Zero(), {{350, 2.0}, {10, 1.0}}, false);
    EXPECT_EQ(w.radius(0.0), 1.0);
    EXPECT_EQ(w.radius(kTwoPi), 1.0);
    EXPECT_EQ(w.radius(rad(180)), 1.0);  // the far tie, 170° from each
    EXPECT_EQ(w.radius(rad(1)), 1.0);
    EXPECT_EQ(w.radius(rad(359)), 2.0);
}

TEST(Bound, ChordFollowsTheStraightEdgeBetweenNeighbours) {
    ModelOutline m{{{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true};
    Bound r = build(m);
    for (double deg = -360; deg <= 720; deg += 0.37) {
        double engine = r.radius(rad(deg));
        ASSERT_NEAR(engine, m.chord(deg), 1e-12 * engine) << "at " << deg << " degrees";
    }
    // The outline points between 0° and 90° lie on the segment from (30, 0) to (0, 24.5).
    for (double deg = 1; deg < 90; deg += 7) {
        Vec2 x = r.outlinePoint(rad(deg));
        EXPECT_NEAR(cross(Vec2(0, 24.5) - Vec2(30, 0), x - Vec2(30, 0)), 0.0, 1e-11) << deg;
    }
    // The chord formula r(φ) = r1·r2·sin Δ / (r1·sin(φ − a1) + r2·sin(a2 − φ)) by hand, at 30°
    // between (0°, 30) and (90°, 24.5).
    double a1 = 0, a2 = kHalfPi, r1 = 30, r2 = 24.5, phi = rad(30);
    double formula = r1 * r2 * std::sin(a2 - a1) / (r1 * std::sin(phi - a1) + r2 * std::sin(a2 - phi));
    EXPECT_NEAR(r.radius(phi), formula, 1e-12);
    // Between samples the chord dips below both ends (a straight edge, not an arc).
    EXPECT_LT(r.radius(rad(45)), 24.5);
}

TEST(Bound, ChordMatchesTheModelForIrregularOutlines) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> radius(0.5, 50), unit(-1, 1);
    for (int shape = 0; shape < 40; ++shape) {
        ModelOutline m;
        m.interpolate = true;
        int n = 3 + shape % 9;
        double offset = unit(rng) * 400;  // some shapes start at negative angles, some past 360
        for (int i = 0; i < n; ++i) {
            double a = offset + i * (360.0 / n) + unit(rng) * (90.0 / n);  // gaps stay under 180°
            m.samples.push_back({a, radius(rng)});
        }
        ASSERT_FALSE(Bound::check(m.samples, true).has_value());
        Bound r = build(m);
        for (double deg = 0.05; deg < 360; deg += 1.1) {
            double engine = r.radius(rad(deg));
            ASSERT_NEAR(engine, m.chord(deg), 1e-10 * engine) << "shape " << shape << " at " << deg;
        }
    }
}

TEST(Bound, SamplesStraddlingZero) {
    // The edge from 330° (given as −30) to 30° crosses 0°.
    ModelOutline m{{{-30, 20}, {30, 25}, {150, 18}, {210, 22}}, true};
    Bound r = build(m);
    for (double deg : {-29.0, -10.0, -0.001, 0.0, 0.001, 10.0, 29.999, 359.0, 360.0, 719.0}) {
        double engine = r.radius(rad(deg));
        EXPECT_NEAR(engine, m.chord(deg), 1e-12 * engine) << deg;
    }
    // The edge point at 0° by the formula: Δ = 60°, φ − a1 = 30°, a2 − φ = 30°.
    double expected = 20 * 25 * std::sin(rad(60)) / (20 * std::sin(rad(30)) + 25 * std::sin(rad(30)));
    EXPECT_NEAR(r.radius(0.0), expected, 1e-12);
    // Nearest across the wrap.
    ModelOutline n{{{-30, 20}, {30, 25}, {150, 18}, {210, 22}}, false};
    Bound nr = build(n);
    EXPECT_EQ(nr.radius(rad(-1)), 20);
    EXPECT_EQ(nr.radius(rad(1)), 25);
    EXPECT_EQ(nr.radius(rad(359)), 20);
}

TEST(Bound, QueryExactlyOnASampleAndAt360) {
    ModelOutline m{{{-90, 5}, {720, 7}, {45, 6}, {180, 9}}, true};
    Bound r = build(m);
    EXPECT_DOUBLE_EQ(r.radius(0.0), 7);
    EXPECT_DOUBLE_EQ(r.radius(rad(45)), 6);
    EXPECT_DOUBLE_EQ(r.radius(kPi), 9);
    EXPECT_DOUBLE_EQ(r.radius(rad(270)), 5);
    EXPECT_DOUBLE_EQ(r.radius(-kHalfPi), 5);  // −90 given at query time too
    EXPECT_DOUBLE_EQ(r.radius(kTwoPi), 7);    // exactly 360°
    EXPECT_DOUBLE_EQ(r.radius(rad(360)), 7);
    EXPECT_DOUBLE_EQ(r.radius(rad(720)), 7);
    EXPECT_DOUBLE_EQ(r.radius(4 * kTwoPi), 7);
    EXPECT_NEAR(r.radius(std::nextafter(kTwoPi, 0.0)), 7, 1e-13);  // just below 360°
    Bound n = Bound::fromDegrees(Vec2::Zero(), m.samples, false);
    EXPECT_EQ(n.radius(kTwoPi), 7);
    EXPECT_EQ(n.radius(rad(45)), 6);
    EXPECT_EQ(n.radius(-kHalfPi), 5);
}

TEST(Bound, OutlinePointIsRadiusTimesDirection) {
    Bound r = Bound::fromDegrees(Vec2(3, 4), {{0, 10}, {120, 12}, {240, 8}}, true);
    for (double phi : {0.0, 0.5, 2.0, 4.0, -1.0}) {
        Vec2 p = r.outlinePoint(phi);
        EXPECT_NEAR(p.norm(), r.radius(phi), 1e-12);
        EXPECT_NEAR(std::atan2(p.y(), p.x()), std::remainder(phi, kTwoPi), 1e-12);
    }
}

// Maps the world point centre + worldRadius·ŵ back through L⁻¹ and checks that it lands on the
// model's bound-space outline: |q| = radius(angle(q)).
void expectOnOutline(const ModelOutline& m, const Bound& r, const Mat2& linear, const Vec2& w) {
    double world = r.worldRadius(linear, w);
    Vec2 q = linear.inverse() * (world * w.normalized());
    double angle = std::atan2(q.y(), q.x()) * 180 / M_PI;
    EXPECT_NEAR(q.norm(), m.radius(angle), 1e-9 * m.radius(angle))
        << "w = (" << w.x() << ", " << w.y() << "), L = " << linear;
}

Mat2 linearOf(double angle, Vec2 scale) {
    Mat2 rot;
    rot << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
    return rot * scale.asDiagonal();
}

TEST(Bound, WorldRadiusUnderRotationIsTheTurnedQuery) {
    ModelOutline m{{{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true};
    Bound r = build(m);
    for (double angle : {0.0, 0.3, kHalfPi, 2.0, -2.5}) {
        for (double dir = -3; dir < 3.2; dir += 0.29) {
            Vec2 w(std::cos(dir), std::sin(dir));
            EXPECT_NEAR(r.worldRadius(linearOf(angle, Vec2(1, 1)), w), m.chord((dir - angle) * 180 / M_PI),
                        1e-10);
        }
    }
}

TEST(Bound, WorldRadiusIsExactUnderScaleAndMirroring) {
    std::vector<ModelOutline> outlines = {
        ModelOutline{{{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true},
        ModelOutline{{{-30, 20}, {30, 25}, {150, 18}, {210, 22}}, true},
        ModelOutline{{{0, 10}, {90, 20}, {180, 30}, {270, 40}}, false},
    };
    std::vector<Vec2> scales = {Vec2(1, 1),     Vec2(2, 0.5),    Vec2(-1, 1),
                                Vec2(1, -3),    Vec2(-2, -0.25), Vec2(1e-3, 1e-3),
                                Vec2(1e3, 1e3), Vec2(1e-3, 1e3), Vec2(-1e3, 2)};
    for (const ModelOutline& m : outlines) {
        Bound r = build(m);
        for (const Vec2& s : scales) {
            for (double angle : {0.0, 0.7, 2.9, -1.3}) {
                Mat2 linear = linearOf(angle, s);
                for (double dir = -3.1; dir < 3.2; dir += 0.23) {
                    expectOnOutline(m, r, linear, Vec2(std::cos(dir), std::sin(dir)));
                }
            }
        }
    }
}

TEST(Bound, WorldRadiusOfUniformScaleIsScaledRadius) {
    ModelOutline m{{{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true};
    Bound r = build(m);
    for (double s : {1e-3, 0.5, 2.0, 1e3}) {
        for (double dir : {0.0, 0.4, 1.9, -2.2}) {
            Vec2 w(std::cos(dir), std::sin(dir));
            double expected = s * m.chord(dir * 180 / M_PI);
            EXPECT_NEAR(r.worldRadius(Mat2::Identity() * s, w), expected, 1e-12 * expected);
            // Mirrored on x: the outline is read toward the mirrored direction.
            double mirrored = s * m.chord(std::atan2(w.y(), -w.x()) * 180 / M_PI);
            EXPECT_NEAR(r.worldRadius(Vec2(-s, s).asDiagonal(), w), mirrored, 1e-12 * mirrored);
        }
    }
}

TEST(Bound, WorldRadiusIgnoresTheLengthOfTheDirection) {
    Bound r = Bound::fromDegrees(Vec2::Zero(), {{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true);
    Mat2 l = linearOf(0.8, Vec2(2, -0.7));
    Vec2 w(0.3, -0.8);
    double unit = r.worldRadius(l, w.normalized());
    EXPECT_NEAR(r.worldRadius(l, w * 1e6), unit, 1e-12 * unit);
    EXPECT_NEAR(r.worldRadius(l, w * 1e-6), unit, 1e-12 * unit);
}

TEST(Bound, NonUniformScaleStretchesTheCircle) {
    // A circle of radius 10 scaled (3, 0.5): an ellipse with semi-axes 30 and 5.
    Bound c(Vec2::Zero(), 10);
    Mat2 l = Vec2(3, 0.5).asDiagonal();
    EXPECT_NEAR(c.worldRadius(l, Vec2(1, 0)), 30, 1e-12);
    EXPECT_NEAR(c.worldRadius(l, Vec2(0, -1)), 5, 1e-12);
    // In direction (cos t, sin t) an ellipse has r = ab / √((b cos t)² + (a sin t)²).
    for (double t = 0; t < 6.3; t += 0.1) {
        double expected = 30 * 5 / std::hypot(5 * std::cos(t), 30 * std::sin(t));
        EXPECT_NEAR(c.worldRadius(l, Vec2(std::cos(t), std::sin(t))), expected, 1e-12 * expected);
    }
}

TEST(Bound, ZeroScaleGivesZeroAndNeverNaN) {
    Bound r = Bound::fromDegrees(Vec2::Zero(), {{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true);
    for (const Mat2& l : {Mat2(Mat2::Zero()), Mat2(Vec2(0, 1).asDiagonal()), Mat2(Vec2(2, 0).asDiagonal()),
                          linearOf(1.0, Vec2(0, 3))}) {
        for (double dir = 0; dir < 6.3; dir += 0.5) {
            double w = r.worldRadius(l, Vec2(std::cos(dir), std::sin(dir)));
            EXPECT_EQ(w, 0.0);
            EXPECT_FALSE(std::isnan(w));
        }
    }
    EXPECT_EQ(r.worldRadius(Mat2::Identity(), Vec2::Zero()), 0.0);  // no direction
    // Extremely small but non-zero scales stay finite and right.
    double tiny = r.worldRadius(Mat2::Identity() * 1e-100, Vec2(1, 0));
    EXPECT_NEAR(tiny, 30e-100, 1e-112);
    // Where det(L) underflows to 0 the radius is 0 (treated as singular), still not NaN.
    double underflow = r.worldRadius(Mat2::Identity() * 1e-200, Vec2(1, 0));
    EXPECT_FALSE(std::isnan(underflow));
    EXPECT_LE(underflow, 30e-200);
}

TEST(CollisionRadiiCheck, ValidListsPass) {
    EXPECT_FALSE(Bound::check({{0, 1}}, false).has_value());
    EXPECT_FALSE(Bound::check({{0, 1}, {10, 2}}, false).has_value());  // a gap is fine without interpolation
    EXPECT_FALSE(Bound::check({{0, 1}, {120, 2}, {240, 3}}, true).has_value());
    EXPECT_FALSE(Bound::check({{0, 1}, {179.999, 2}, {270, 3}}, true).has_value());
    EXPECT_FALSE(Bound::check({{-90, 1}, {720, 2}, {90, 3}, {180, 1}}, true).has_value());
}

TEST(CollisionRadiiCheck, EmptyList) {
    auto p = Bound::check({}, false);
    ASSERT_TRUE(p.has_value());
    EXPECT_EQ(p->index, SampleProblem::kWholeList);
}

TEST(CollisionRadiiCheck, NonFiniteValues) {
    const double inf = std::numeric_limits<double>::infinity(),
                 nan = std::numeric_limits<double>::quiet_NaN();
    for (DegreeSample bad :
         {DegreeSample{nan, 1}, DegreeSample{inf, 1}, DegreeSample{0, inf}, DegreeSample{5, nan}}) {
        auto p = Bound::check({{90, 1}, bad}, false);
        ASSERT_TRUE(p.has_value());
        EXPECT_EQ(p->index, 1u);
        EXPECT_NE(p->what.find("non-finite"), std::string::npos) << p->what;
    }
}

TEST(CollisionRadiiCheck, RadiusNotPositive) {
    for (double bad : {0.0, -1.0, -0.0}) {
        auto p = Bound::check({{0, 1}, {90, 2}, {180, bad}}, false);
        ASSERT_TRUE(p.has_value()) << bad;
        EXPECT_EQ(p->index, 2u);
        EXPECT_NE(p->what.find("not positive"), std::string::npos) << p->what;
        EXPECT_NE(p->expected.find("> 0"), std::string::npos) << p->expected;
    }
}

TEST(CollisionRadiiCheck, SameAngleAfterReducing) {
    struct Case {
        std::vector<DegreeSample> samples;
        std::size_t index;
    };
    for (const Case& c : {Case{{{0, 1}, {360, 2}}, 1}, Case{{{270, 1}, {90, 1}, {-90, 2}}, 2},
                          Case{{{-90, 1}, {90, 1}, {270, 2}}, 2}, Case{{{10, 1}, {20, 1}, {730, 2}}, 2},
                          Case{{{5, 1}, {5, 2}}, 1}}) {
        auto p = Bound::check(c.samples, false);
        ASSERT_TRUE(p.has_value());
        EXPECT_EQ(p->index, c.index);  // the later of the two, in file order
        EXPECT_NE(p->what.find("same direction"), std::string::npos) << p->what;
        EXPECT_NE(p->what.find("modulo 360"), std::string::npos) << p->what;
    }
}

TEST(CollisionRadiiCheck, InterpolateNeedsThreeSamples) {
    for (const std::vector<DegreeSample>& s : {std::vector<DegreeSample>{{0, 1}}, {{0, 1}, {120, 1}}}) {
        auto p = Bound::check(s, true);
        ASSERT_TRUE(p.has_value());
        EXPECT_EQ(p->index, SampleProblem::kWholeList);
        EXPECT_NE(p->what.find("at least 3"), std::string::npos) << p->what;
        EXPECT_FALSE(Bound::check(s, false).has_value());
    }
}

TEST(CollisionRadiiCheck, InterpolateGapOf180OrMore) {
    // Gaps: 0→180 is exactly 180.
    auto exact = Bound::check({{0, 1}, {180, 1}, {270, 1}}, true);
    ASSERT_TRUE(exact.has_value());
    EXPECT_EQ(exact->index, 0u);
    EXPECT_NE(exact->what.find("gap of 180"), std::string::npos) << exact->what;
    EXPECT_NE(exact->expected.find("star-shaped"), std::string::npos);
    // The gap across the wrap: 100 → 350 → 10; the wide one is 100 → 350 (250°), at sample 2 (100).
    auto wrap = Bound::check({{350, 1}, {10, 1}, {100, 1}}, true);
    ASSERT_TRUE(wrap.has_value());
    EXPECT_EQ(wrap->index, 2u);
    // Wide gap crossing 0: 200 → 20 is 180.
    auto across = Bound::check({{20, 1}, {110, 1}, {200, 1}}, true);
    ASSERT_TRUE(across.has_value());
    EXPECT_EQ(across->index, 2u);
}

}  // namespace
}  // namespace polar
