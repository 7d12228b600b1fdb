// The pixel truth: opaque squares mapped to parallelograms, overlapping with positive area.
#include "polar/authoring/pixel_truth.h"

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>
#include <random>

namespace polar {
namespace {

AlphaMask mask(int w, int h, const std::vector<std::string>& rows) {
    AlphaMask m;
    m.width = w;
    m.height = h;
    for (const std::string& row : rows)
        for (char c : row) m.alpha.push_back(c == '#' ? 255 : (c == '+' ? 100 : 0));
    return m;
}

Mat2 linear(double angle, Vec2 scale) {
    return rotationMatrix(angle) * scale.asDiagonal();
}

TEST(PixelTruth, SquaresOverlapOnlyWithArea) {
    OpaquePixels one(mask(1, 1, {"#"}));
    EXPECT_TRUE(
        opaquePixelsOverlap(one, Vec2(0, 0), Mat2::Identity(), one, Vec2(0.999, 0), Mat2::Identity()));
    EXPECT_FALSE(opaquePixelsOverlap(one, Vec2(0, 0), Mat2::Identity(), one, Vec2(1.0, 0),
                                     Mat2::Identity()));  // touching
    EXPECT_FALSE(
        opaquePixelsOverlap(one, Vec2(0, 0), Mat2::Identity(), one, Vec2(0.5, 1.0), Mat2::Identity()));
    // Turned 45°, a unit square reaches √2/2 along the axes.
    Mat2 turned = linear(kPi / 4, Vec2(1, 1));
    EXPECT_TRUE(opaquePixelsOverlap(one, Vec2(0, 0), turned, one, Vec2(1.2, 0), Mat2::Identity()));
    EXPECT_FALSE(opaquePixelsOverlap(one, Vec2(0, 0), turned, one, Vec2(1.22, 0), Mat2::Identity()));
    // Scale 0: no area, no overlap.
    EXPECT_FALSE(opaquePixelsOverlap(one, Vec2(0, 0), Mat2::Zero(), one, Vec2(0, 0), Mat2::Identity()));
}

TEST(PixelTruth, ThresholdAndTransparentPixels) {
    AlphaMask m = mask(3, 1, {"#.+"});
    OpaquePixels strict(m), loose(m, 99);
    EXPECT_EQ(strict.boundary().size(), 1u);  // alpha 100 is not above the default threshold 127
    EXPECT_FALSE(strict.opaque(2, 0));
    EXPECT_EQ(loose.boundary().size(), 2u);  // but above 99
    EXPECT_TRUE(loose.opaque(2, 0));
    EXPECT_FALSE(loose.opaque(1, 0));
    OpaquePixels dot(mask(1, 1, {"#"}));
    // The middle pixel is transparent: a dot there overlaps nothing.
    EXPECT_FALSE(opaquePixelsOverlap(strict, Vec2(0, 0), Mat2::Identity(), dot, Vec2(0, 0),
                                     linear(0, Vec2(0.9, 0.9))));
    EXPECT_TRUE(opaquePixelsOverlap(loose, Vec2(0, 0), Mat2::Identity(), dot, Vec2(1, 0), Mat2::Identity()));
    EXPECT_FALSE(
        opaquePixelsOverlap(strict, Vec2(0, 0), Mat2::Identity(), dot, Vec2(1, 0), Mat2::Identity()));
    OpaquePixels none(mask(1, 1, {"."}));
    EXPECT_TRUE(none.empty());
    EXPECT_FALSE(opaquePixelsOverlap(none, Vec2(0, 0), Mat2::Identity(), dot, Vec2(0, 0), Mat2::Identity()));
}

TEST(PixelTruth, ContainmentWithoutTouchingBoundaries) {
    // A dot deep inside a big block: no boundary square meets the other's boundary, still overlap.
    std::vector<std::string> rows(9, std::string(9, '#'));
    OpaquePixels block(mask(9, 9, rows)), dot(mask(1, 1, {"#"}));
    EXPECT_TRUE(
        opaquePixelsOverlap(block, Vec2(0, 0), Mat2::Identity(), dot, Vec2(0.3, -0.2), Mat2::Identity()));
    EXPECT_TRUE(
        opaquePixelsOverlap(dot, Vec2(0.3, -0.2), Mat2::Identity(), block, Vec2(0, 0), Mat2::Identity()));
}

// Against brute force: points spread over A's opaque squares, mapped into B's pixels. Any sample
// strictly inside an opaque B pixel proves an overlap; the exact test must then agree.
TEST(PixelTruth, AgreesWithDenseSampling) {
    std::mt19937_64 rng(8);
    std::uniform_real_distribution<double> unit(0, 1);
    auto blob = [&](int n) {
        AlphaMask m;
        m.width = m.height = n;
        for (int y = 0; y < n; ++y)
            for (int x = 0; x < n; ++x) {
                Vec2 c = m.pixelCentre(x, y);
                m.alpha.push_back(c.norm() < n * (0.3 + 0.2 * unit(rng)) ? 255 : 0);
            }
        return m;
    };
    int proven = 0, agreed = 0;
    for (int c = 0; c < 300; ++c) {
        AlphaMask ma = blob(10), mb = blob(12);
        OpaquePixels a(ma), b(mb);
        Mat2 la =
            linear(unit(rng) * kTwoPi, Vec2(0.5 + unit(rng), (unit(rng) < 0.3 ? -1 : 1) * (0.5 + unit(rng))));
        Mat2 lb = linear(unit(rng) * kTwoPi, Vec2(0.5 + unit(rng), 0.5 + unit(rng)));
        double angle = unit(rng) * kTwoPi;
        Vec2 pb = (4 + 12 * unit(rng)) * Vec2(std::cos(angle), std::sin(angle));
        bool exact = opaquePixelsOverlap(a, Vec2::Zero(), la, b, pb, lb);
        EXPECT_EQ(exact, opaquePixelsOverlap(b, pb, lb, a, Vec2::Zero(), la)) << c;  // symmetric
        bool sampled = false;
        Mat2 lbInverse = lb.inverse();
        for (int y = 0; y < ma.height && !sampled; ++y)
            for (int x = 0; x < ma.width && !sampled; ++x) {
                if (!a.opaque(x, y)) continue;
                for (int s = 0; s < 36 && !sampled; ++s) {
                    Vec2 q = ma.pixelCentre(x, y) + Vec2((s % 6 + 0.5) / 6 - 0.5, (s / 6 + 0.5) / 6 - 0.5);
                    Vec2 r = lbInverse * (la * q - pb);
                    double fx = r.x() + mb.width * 0.5, fy = mb.height * 0.5 - r.y();
                    int i = static_cast<int>(std::floor(fx)), j = static_cast<int>(std::floor(fy));
                    bool strictlyInside =
                        fx - i > 1e-9 && i + 1 - fx > 1e-9 && fy - j > 1e-9 && j + 1 - fy > 1e-9;
                    sampled = strictlyInside && b.opaque(i, j);
                }
            }
        if (sampled) {
            ++proven;
            EXPECT_TRUE(exact) << c;
        }
        agreed += sampled == exact;
    }
    EXPECT_GT(proven, 60);
    EXPECT_GT(agreed, 280);  // sampling misses only slivers thinner than a sixth of a pixel
}

}  // namespace
}  // namespace polar
