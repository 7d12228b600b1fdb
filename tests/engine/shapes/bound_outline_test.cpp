#include "polar/bound_outline.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "polar/transform.h"

namespace polar {
namespace {

// How far from `origin` the ray toward `dir` leaves the closed polygon: the largest t at which
// origin + t·dir crosses an edge (a star-shaped outline is crossed once, away from radial edges).
double rayExit(const std::vector<Vec2>& polygon, const Vec2& origin, const Vec2& dir) {
    double best = -1;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        Vec2 a = polygon[i] - origin, b = polygon[(i + 1) % polygon.size()] - origin;
        Vec2 e = b - a;
        double den = cross(dir, e);
        if (std::fabs(den) < 1e-15) continue;
        double t = cross(a, e) / den;    // origin + t·dir on the edge's line
        double u = cross(a, dir) / den;  // a + u·e
        if (u >= -1e-12 && u <= 1 + 1e-12 && t > 0) best = std::max(best, t);
    }
    return best;
}

const std::vector<DegreeSample> kSamples = {{10, 30}, {80, 18}, {150, 26}, {200, 12}, {260, 22}, {330, 35}};

TEST(BoundOutline, ChordVerticesAreTheSamplePointsAndEdgesFollowTheRule) {
    Bound bound = Bound::fromDegrees(Vec2(3, -2), kSamples, true);
    std::vector<Vec2> outline = boundOutline(bound, Mat3::Identity());
    ASSERT_EQ(outline.size(), kSamples.size()) << "straight edges need no more points than the samples";
    std::vector<Vec2> samples = boundSamplePoints(bound, Mat3::Identity());
    for (std::size_t k = 0; k < outline.size(); ++k) EXPECT_NEAR((outline[k] - samples[k]).norm(), 0, 1e-12);
    for (int i = 0; i < 720; ++i) {
        double phi = kTwoPi * (i + 0.37) / 720;
        Vec2 dir(std::cos(phi), std::sin(phi));
        EXPECT_NEAR(rayExit(outline, bound.centre(), dir), bound.radiusChord(phi), 1e-9) << "angle " << phi;
    }
}

TEST(BoundOutline, NearestRuleIsArcsWithRadialStepsAtBisectors) {
    Bound bound = Bound::fromDegrees(Vec2(-1, 4), kSamples, false);
    const double tolerance = 0.05;
    std::vector<Vec2> outline = boundOutline(bound, Mat3::Identity(), tolerance);
    // Every point lies on one of the arcs: its distance from the centre is a sample's radius, and
    // the rule gives that radius in its direction (or, on a bisector, a neighbour's).
    for (const Vec2& p : outline) {
        Vec2 d = p - bound.centre();
        double phi = std::atan2(d.y(), d.x());
        double r = d.norm();
        double rule = bound.radiusNearest(phi);
        double nudgedLeft = bound.radiusNearest(phi - 1e-9), nudgedRight = bound.radiusNearest(phi + 1e-9);
        EXPECT_TRUE(std::fabs(r - rule) < 1e-9 || std::fabs(r - nudgedLeft) < 1e-9 ||
                    std::fabs(r - nudgedRight) < 1e-9)
            << "point at angle " << phi << " radius " << r << ", rule says " << rule;
    }
    // Between the bisectors the polygon stays within the tolerance inside the true arc.
    for (int i = 0; i < 720; ++i) {
        double phi = kTwoPi * (i + 0.37) / 720;
        double exit = rayExit(outline, bound.centre(), Vec2(std::cos(phi), std::sin(phi)));
        double r = bound.radiusNearest(phi);
        EXPECT_LE(exit, r + 1e-9) << "angle " << phi;
        EXPECT_GE(exit, r - tolerance - 1e-9) << "angle " << phi;
    }
    // The steps: at the bisector between 10° and 80° (45°) both radii 30 and 18 are outline points.
    bool outer = false, inner = false;
    for (const Vec2& p : outline) {
        Vec2 d = p - bound.centre();
        if (std::fabs(std::atan2(d.y(), d.x()) - degToRad(45)) > 1e-9) continue;
        outer |= std::fabs(d.norm() - 30) < 1e-9;
        inner |= std::fabs(d.norm() - 18) < 1e-9;
    }
    EXPECT_TRUE(outer && inner) << "a radial step from radius 30 to 18 at 45°";
}

TEST(BoundOutline, OneSampleIsACircle) {
    Bound bound(Vec2(2, 2), 10);
    std::vector<Vec2> outline = boundOutline(bound, Mat3::Identity(), 0.01);
    EXPECT_GE(outline.size(), 60u);
    for (const Vec2& p : outline) EXPECT_NEAR((p - Vec2(2, 2)).norm(), 10, 1e-12);
}

// Under a world transform (scale, rotation, mirroring) the outline is the bound-space outline
// carried by M, and its extent in each world direction is Bound::worldRadius.
TEST(BoundOutline, WorldTransformMatchesWorldRadius) {
    for (bool interpolate : {true, false}) {
        Bound bound = Bound::fromDegrees(Vec2(3, -2), kSamples, interpolate);
        Transform t(Vec2(100, -50), degToRad(33), Vec2(-2.0, 1.5));  // mirrored and stretched
        Mat3 m = t.matrix();
        const double tolerance = 0.01;
        std::vector<Vec2> outline = boundOutline(bound, m, tolerance);
        Vec2 centre = t.apply(bound.centre());
        std::mt19937 rng(5);
        std::uniform_real_distribution<double> angle(0, kTwoPi);
        for (int i = 0; i < 500; ++i) {
            double a = angle(rng);
            Vec2 w(std::cos(a), std::sin(a));
            double expected = bound.worldRadius(t.linear(), w);
            double exit = rayExit(outline, centre, w);
            if (interpolate) {
                EXPECT_NEAR(exit, expected, 1e-9) << "direction " << a;
            } else {
                EXPECT_LE(exit, expected + 1e-9) << "direction " << a;
                // The tolerance bounds the chords' distance from the arc along its normal; along a ray
                // the gap grows by 1/cos of the angle between ray and normal (small at this stretch).
                EXPECT_GE(exit, expected - 2 * tolerance) << "direction " << a;
            }
        }
    }
}

TEST(BoundOutline, TighterToleranceOrLargerZoomMeansMoreChords) {
    Bound bound = Bound::fromDegrees(Vec2::Zero(), kSamples, false);
    std::size_t coarse = boundOutline(bound, Mat3::Identity(), 1.0).size();
    std::size_t fine = boundOutline(bound, Mat3::Identity(), 0.01).size();
    Mat3 zoom = Mat3::Identity();
    zoom(0, 0) = zoom(1, 1) = 20;
    std::size_t zoomed = boundOutline(bound, zoom, 1.0).size();
    EXPECT_LT(coarse, fine);
    EXPECT_LT(coarse, zoomed);
}

}  // namespace
}  // namespace polar
