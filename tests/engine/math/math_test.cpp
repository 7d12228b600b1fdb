#include "polar/math.h"
#include "polar/splitmix64.h"

#include <gtest/gtest.h>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <vector>

namespace polar {
namespace {

// Angles to compare the engine's trigonometry with libm on: a dense sweep of [−4π, 4π], every
// multiple of π/4 (the axes and diagonals, where quadrant bookkeeping goes wrong), values just
// either side of them, and large and negative angles.
std::vector<double> testAngles() {
    std::vector<double> xs;
    for (int i = -40000; i <= 40000; ++i) xs.push_back(i * (4 * kPi / 40000.0));
    for (int k = -64; k <= 64; ++k) {
        double axis = k * (kPi / 4);
        xs.push_back(axis);
        xs.push_back(std::nextafter(axis, 1e300));
        xs.push_back(std::nextafter(axis, -1e300));
        xs.push_back(axis + 1e-9);
        xs.push_back(axis - 1e-9);
    }
    for (double big : {100.0, 1000.0, 12345.678, 1e5, 314159.26, 1e6}) {
        for (int i = 0; i < 500; ++i) {
            xs.push_back(big + i * 0.0137);
            xs.push_back(-big - i * 0.0137);
        }
    }
    for (double tiny : {1e-300, 1e-20, 1e-8, 1e-4}) {
        xs.push_back(tiny);
        xs.push_back(-tiny);
    }
    return xs;
}

TEST(Trig, SinAndCosMatchLibmEverywhere) {
    double worstSin = 0, worstCos = 0;
    for (double x : testAngles()) {
        double s = trig::sin(x), c = trig::cos(x);
        ASSERT_NEAR(s, std::sin(x), 1e-15) << "x = " << x;
        ASSERT_NEAR(c, std::cos(x), 1e-15) << "x = " << x;
        worstSin = std::max(worstSin, std::fabs(s - std::sin(x)));
        worstCos = std::max(worstCos, std::fabs(c - std::cos(x)));
    }
    char text[64];
    std::snprintf(text, sizeof text, "%.3g", worstSin);
    RecordProperty("worst_sin_error", text);
    std::snprintf(text, sizeof text, "%.3g", worstCos);
    RecordProperty("worst_cos_error", text);
}

TEST(Trig, SincosGivesTheSameBitsAsSinAndCos) {
    for (double x : {-1e6, -7.5, -kPi, -1.0, 0.0, 0.3, kHalfPi, 2.0, 3 * kPi / 4, 1e5}) {
        double s = 0, c = 0;
        trig::sincos(x, s, c);
        EXPECT_EQ(s, trig::sin(x)) << x;
        EXPECT_EQ(c, trig::cos(x)) << x;
    }
}

TEST(Trig, SignsInEveryQuadrantAndExactValuesOnTheAxes) {
    EXPECT_EQ(trig::sin(0.0), 0.0);
    EXPECT_EQ(trig::cos(0.0), 1.0);
    // Quadrant k of [0, 2π): the signs of (cos, sin).
    const int signs[4][2] = {{1, 1}, {-1, 1}, {-1, -1}, {1, -1}};
    for (int turn = -3; turn <= 3; ++turn) {
        for (int q = 0; q < 4; ++q) {
            double x = turn * kTwoPi + q * kHalfPi + kPi / 4 + 0.1;
            EXPECT_EQ(trig::cos(x) > 0 ? 1 : -1, signs[q][0]) << "x = " << x;
            EXPECT_EQ(trig::sin(x) > 0 ? 1 : -1, signs[q][1]) << "x = " << x;
        }
        // On the axes the other function is (within rounding of kHalfPi) zero.
        EXPECT_NEAR(trig::sin(turn * kTwoPi + kHalfPi), 1.0, 1e-15);
        EXPECT_NEAR(trig::cos(turn * kTwoPi + kPi), -1.0, 1e-15);
        EXPECT_NEAR(trig::sin(turn * kTwoPi + 3 * kHalfPi), -1.0, 1e-15);
    }
    EXPECT_EQ(trig::sin(-0.5), -trig::sin(0.5));  // odd
    EXPECT_EQ(trig::cos(-0.5), trig::cos(0.5));   // even
}

TEST(Trig, NonFiniteInputGivesNaNNotACrash) {
    EXPECT_TRUE(std::isnan(trig::sin(INFINITY)));
    EXPECT_TRUE(std::isnan(trig::cos(-INFINITY)));
    EXPECT_TRUE(std::isnan(trig::sin(NAN)));
    EXPECT_TRUE(std::isnan(trig::atan2(NAN, 1.0)));
}

TEST(Trig, Atan2MatchesLibmInEveryQuadrantAndOnTheAxes) {
    std::vector<double> coords = {1e-300, 1e-9, 0.001, 0.1,  0.4142, 0.5, 0.99, 1.0,
                                  1.01,   2.0,  3.7,   10.0, 1e3,    1e9, 1e300};
    for (double x : coords) {
        for (double y : coords) {
            for (int sx : {-1, 1}) {
                for (int sy : {-1, 1}) {
                    ASSERT_NEAR(trig::atan2(sy * y, sx * x), std::atan2(sy * y, sx * x), 1e-15)
                        << "y = " << sy * y << ", x = " << sx * x;
                }
            }
        }
    }
    for (int i = 0; i < 20000; ++i) {  // round the unit circle
        double a = -kPi + (i + 0.5) * (kTwoPi / 20000);
        double y = std::sin(a) * 3.5, x = std::cos(a) * 3.5;
        ASSERT_NEAR(trig::atan2(y, x), std::atan2(y, x), 1e-15) << "a = " << a;
    }
    // The axes and the origin.
    EXPECT_EQ(trig::atan2(0.0, 0.0), 0.0);
    EXPECT_EQ(trig::atan2(0.0, 5.0), 0.0);
    EXPECT_NEAR(trig::atan2(5.0, 0.0), kHalfPi, 1e-16);
    EXPECT_NEAR(trig::atan2(-5.0, 0.0), -kHalfPi, 1e-16);
    EXPECT_NEAR(trig::atan2(0.0, -5.0), kPi, 1e-16);
    // The documented range is (−π, π]: the negative x axis is +π, even from below (−0).
    EXPECT_GT(trig::atan2(-0.0, -5.0), 3.14);
    EXPECT_EQ(trig::atan2(-0.0, 0.0), 0.0);
    EXPECT_EQ(trig::atan2(0.0, -0.0), 0.0);
    // Signs follow y; the magnitude grows through the quadrants.
    EXPECT_GT(trig::atan2(1.0, 1.0), 0.0);
    EXPECT_GT(trig::atan2(1.0, -1.0), trig::atan2(1.0, 1.0));
    EXPECT_LT(trig::atan2(-1.0, -1.0), trig::atan2(-1.0, 1.0));
    EXPECT_NEAR(trig::atan2(1.0, 1.0), kPi / 4, 1e-16);
    EXPECT_NEAR(trig::atan2(-1.0, -1.0), -3 * kPi / 4, 1e-15);
    // Infinities.
    EXPECT_NEAR(trig::atan2(INFINITY, 1.0), kHalfPi, 1e-16);
    EXPECT_NEAR(trig::atan2(1.0, -INFINITY), kPi, 1e-16);
    EXPECT_NEAR(trig::atan2(-INFINITY, INFINITY), -kPi / 4, 1e-16);
}

TEST(Trig, RotationMatrixIsCounterClockwiseAndOrthonormal) {
    Mat2 r = rotationMatrix(kHalfPi);
    Vec2 x = r * Vec2(1, 0);  // +x turns to +y
    EXPECT_NEAR(x.x(), 0.0, 1e-16);
    EXPECT_NEAR(x.y(), 1.0, 1e-16);
    for (double a : {-1e4, -3.0, -0.2, 0.0, 0.7, 2.5, 1e3}) {
        Mat2 m = rotationMatrix(a);
        EXPECT_NEAR(m(0, 0), std::cos(a), 1e-15);
        EXPECT_NEAR(m(1, 0), std::sin(a), 1e-15);
        EXPECT_EQ(m(0, 1), -m(1, 0));
        EXPECT_EQ(m(1, 1), m(0, 0));
        EXPECT_NEAR((m.transpose() * m - Mat2::Identity()).cwiseAbs().maxCoeff(), 0.0, 1e-15);
        EXPECT_NEAR(m.determinant(), 1.0, 1e-15);
    }
    // Composition adds angles.
    Mat2 ab = rotationMatrix(0.4) * rotationMatrix(1.1);
    EXPECT_NEAR((ab - rotationMatrix(1.5)).cwiseAbs().maxCoeff(), 0.0, 1e-15);
}

TEST(Angles, ReduceDegreesIsHalfOpenAndExact) {
    EXPECT_EQ(reduceDegrees(-90), 270);
    EXPECT_EQ(reduceDegrees(720), 0);
    EXPECT_EQ(reduceDegrees(360), 0);
    EXPECT_EQ(reduceDegrees(0), 0);
    EXPECT_EQ(reduceDegrees(-360), 0);
    EXPECT_EQ(reduceDegrees(725.5), 5.5);
    EXPECT_EQ(reduceDegrees(-0.25), 359.75);
    EXPECT_EQ(reduceDegrees(1e-20), 1e-20);
    EXPECT_EQ(reduceDegrees(-1e-20), 0.0);  // 360 − 1e-20 rounds to 360, which is outside [0, 360)
    EXPECT_LT(reduceDegrees(-1e-12), 360.0);
    EXPECT_EQ(degToRad(180), kPi);
    EXPECT_EQ(radToDeg(kPi), 180);
}

TEST(Angles, ReduceRadiansIsHalfOpen) {
    EXPECT_EQ(reduceRadians(0.0), 0.0);
    EXPECT_EQ(reduceRadians(kTwoPi), 0.0);
    EXPECT_NEAR(reduceRadians(-kHalfPi), 3 * kHalfPi, 1e-15);
    EXPECT_NEAR(reduceRadians(5 * kTwoPi + 1.0), 1.0, 1e-13);
    EXPECT_EQ(reduceRadians(-1e-20), 0.0);
    for (double a : {-1e5, -7.0, -1e-9, 3.0, 6.283185307179586, 1e6}) {
        double r = reduceRadians(a);
        EXPECT_GE(r, 0.0) << a;
        EXPECT_LT(r, kTwoPi) << a;
    }
}

TEST(Vectors, CrossIsPositiveCounterClockwise) {
    EXPECT_EQ(cross(Vec2(1, 0), Vec2(0, 1)), 1.0);
    EXPECT_EQ(cross(Vec2(0, 1), Vec2(1, 0)), -1.0);
    EXPECT_EQ(cross(Vec2(2, 3), Vec2(4, 6)), 0.0);
    EXPECT_EQ(cross(Vec2(3, -1), Vec2(2, 5)), 17.0);
}

// The published sequence for seed 1234567 (Vigna's splitmix64.c), which random scenes and generated
// art both draw from: a changed constant or shift changes every seeded scene.
TEST(Splitmix64, GivesThePublishedSequence) {
    std::uint64_t state = 1234567;
    const std::uint64_t expected[] = {6457827717110365317ull, 3203168211198807973ull, 9817491932198370423ull,
                                      4593380528125082431ull, 16408922859458223821ull};
    for (std::uint64_t value : expected) EXPECT_EQ(splitmix64(state), value);
    EXPECT_EQ(state, 1234567 + 5 * 0x9E3779B97F4A7C15ull);
}

}  // namespace
}  // namespace polar
