#include "polar/authoring/bounds_gen.h"

#include <gtest/gtest.h>

#include <functional>

#include "pixel_truth.h"

namespace polar {
namespace {

// A mask of w × h pixels, opaque where `inside(x, y)` holds for the pixel's centre in bound space.
AlphaMask maskOf(int w, int h, const std::function<bool(const Vec2&)>& inside) {
    AlphaMask mask{w, h, std::vector<std::uint8_t>(static_cast<std::size_t>(w) * h, 0)};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (inside(mask.pixelCentre(x, y))) mask.alpha[static_cast<std::size_t>(y) * w + x] = 255;
    return mask;
}

GeneratedBounds generate(const AlphaMask& mask, BoundsGenOptions options = {}) {
    Result<GeneratedBounds> g = generateBounds(mask, options);
    EXPECT_TRUE(g.ok()) << (g.ok() ? "" : g.error().message());
    return g.ok() ? *g : GeneratedBounds{};
}

// The checks every generated enclosing outline must pass, recomputed independently.
void expectGoodEnclosing(const AlphaMask& mask, const GeneratedBounds& g) {
    PixelSet set = PixelSet::opaque(mask);
    Bounds bounds = buildBounds(g.spec);
    EXPECT_TRUE(truth::enclosesEveryPixel(set, bounds));
    for (std::size_t k = 0; k < bounds.size(); ++k) {
        const BoundSpec& r = g.spec.radii[k];
        EXPECT_TRUE(r.interpolate);
        EXPECT_FALSE(Bound::check(r.samples, true)) << "the loader would reject it";
        EXPECT_EQ(g.quality[k].worstMiss, 0.0);
        if (bounds.size() == 1) {
            truth::Slack slack = truth::slackOf(set, bounds[k], false);
            EXPECT_NEAR(g.quality[k].worstSlack, slack.worst, 1e-9);
            EXPECT_NEAR(g.quality[k].meanSlack, slack.mean, 1e-9);
        }
        for (std::size_t i = 0; i < r.samples.size(); ++i) {
            double gap = r.samples[(i + 1) % r.samples.size()][0] - r.samples[i][0];
            if (gap <= 0) gap += 360.0;
            EXPECT_LE(gap, BoundsGenOptions::kMaxGapDegrees);
            if (i > 0) {
                EXPECT_GT(r.samples[i][0], r.samples[i - 1][0]) << "samples ascend from 0 degrees";
            }
        }
    }
}

TEST(BoundsGen, ASquareGetsItsOwnCornersAsSamples) {
    AlphaMask mask =
        maskOf(16, 16, [](const Vec2& p) { return std::fabs(p.x()) < 4 && std::fabs(p.y()) < 4; });
    BoundsGenOptions options;
    options.samples = 4;
    GeneratedBounds g = generate(mask, options);
    expectGoodEnclosing(mask, g);
    ASSERT_EQ(g.spec.radii.size(), 1u);
    const BoundSpec& r = g.spec.radii[0];
    EXPECT_EQ(r.centre, Vec2(0, 0));
    ASSERT_EQ(r.samples.size(), 4u);
    // The least-area outline is the square itself: samples at its corners, 4·√2 away.
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_EQ(r.samples[k][0], 45.0 + 90.0 * k);
        EXPECT_NEAR(r.samples[k][1], 4 * std::sqrt(2.0), 0.0011);
    }
    EXPECT_LT(g.quality[0].worstSlack, 0.002);
    EXPECT_EQ(g.partPixels[0], 64);
}

TEST(BoundsGen, AnLShapeIsEnclosedAndItsSlackReportedExactly) {
    AlphaMask mask = maskOf(24, 24, [](const Vec2& p) {
        return (p.x() > -9 && p.x() < -2 && p.y() > -9 && p.y() < 9) ||
               (p.x() > -9 && p.x() < 9 && p.y() > -9 && p.y() < -2);
    });
    GeneratedBounds g = generate(mask);
    expectGoodEnclosing(mask, g);
    // The centroid of the L, not the image centre.
    EXPECT_LT(g.spec.radii[0].centre.x(), -1.0);
    EXPECT_LT(g.spec.radii[0].centre.y(), -1.0);
    // The concave corner costs slack, but the outline reaches into it.
    EXPECT_GT(g.quality[0].worstSlack, 1.0);
    EXPECT_LT(g.quality[0].meanSlack, 2.0);
}

TEST(BoundsGen, ARingWithAHollowCentreIsEnclosed) {
    AlphaMask mask = maskOf(30, 30, [](const Vec2& p) { return p.norm() < 13 && p.norm() > 8; });
    GeneratedBounds g = generate(mask);
    expectGoodEnclosing(mask, g);
    EXPECT_LT(g.quality[0].worstSlack, 1.5);
}

TEST(BoundsGen, PixelsOnTheImageEdgeAreEnclosed) {
    // A pixel whose only transparent neighbours lie outside the image is on the boundary too.
    AlphaMask full = maskOf(14, 14, [](const Vec2&) { return true; });
    GeneratedBounds g = generate(full);
    expectGoodEnclosing(full, g);
    EXPECT_LT(g.quality[0].worstSlack, 1.1);
}

TEST(BoundsGen, ASinglePixelAndAnOffCentreCentre) {
    AlphaMask dot = maskOf(5, 5, [](const Vec2& p) { return p.norm() < 0.6; });
    expectGoodEnclosing(dot, generate(dot));
    BoundsGenOptions options;
    options.centre = Vec2(-1.5, 2.0);  // the modder's choice, even outside the opaque area
    GeneratedBounds g = generate(dot, options);
    EXPECT_EQ(g.spec.radii[0].centre, Vec2(-1.5, 2.0));
    expectGoodEnclosing(dot, g);
}

TEST(BoundsGen, ContainerOutlineStaysInTheFreeSpace) {
    // A room: walls everywhere except an irregular, star-shaped interior around the centre.
    auto room = [](const Vec2& p) {
        double phi = std::atan2(p.y(), p.x());
        double r = 17.0 + 3.0 * std::cos(3 * phi) + 1.5 * std::sin(5 * phi);
        return p.norm() >= r;
    };
    AlphaMask mask = maskOf(48, 44, room);
    BoundsGenOptions options;
    options.container = true;
    GeneratedBounds g = generate(mask, options);
    ASSERT_EQ(g.spec.radii.size(), 1u);
    Bound radii = buildBounds(g.spec)[0];
    PixelSet walls = PixelSet::opaque(mask);
    EXPECT_TRUE(truth::avoidsEveryWall(walls, radii));
    EXPECT_EQ(g.quality[0].worstMiss, 0.0);
    truth::Slack slack = truth::slackOf(walls, radii, true);
    EXPECT_NEAR(g.quality[0].worstSlack, slack.worst, 1e-9);
    EXPECT_NEAR(g.quality[0].meanSlack, slack.mean, 1e-9);
    EXPECT_LT(slack.mean, 1.0) << "as large as it can be";
}

TEST(BoundsGen, ContainerWithoutWallsUsesTheImageEdge) {
    AlphaMask empty = maskOf(20, 12, [](const Vec2&) { return false; });
    BoundsGenOptions options;
    options.container = true;
    options.samples = 4;
    GeneratedBounds g = generate(empty, options);
    Bound radii = buildBounds(g.spec)[0];
    EXPECT_TRUE(truth::avoidsEveryWall(PixelSet::opaque(empty), radii));
    // The best 4-sample outline is nearly the image rectangle (its corners are off the 1° grid).
    EXPECT_LT(g.quality[0].meanSlack, 0.2);
}

TEST(BoundsGen, ContainerCentreOnAWallIsAnError) {
    AlphaMask mask = maskOf(20, 20, [](const Vec2& p) { return p.norm() < 3; });
    BoundsGenOptions options;
    options.container = true;
    Result<GeneratedBounds> g = generateBounds(mask, options);
    ASSERT_FALSE(g.ok());
    EXPECT_NE(g.error().message().find("lies on an opaque pixel"), std::string::npos) << g.error().message();
}

TEST(BoundsGen, SplitsAnElongatedSpriteAlongItsAxis) {
    // A bar tilted by 30°, 40 × 6 pixels.
    auto bar = [](const Vec2& p) {
        double c = std::cos(kPi / 6), s = std::sin(kPi / 6);
        Vec2 q(c * p.x() + s * p.y(), -s * p.x() + c * p.y());
        return std::fabs(q.x()) < 20 && std::fabs(q.y()) < 3;
    };
    AlphaMask mask = maskOf(48, 32, bar);
    BoundsGenOptions options;
    options.radii = 2;
    GeneratedBounds g = generate(mask, options);
    ASSERT_EQ(g.spec.radii.size(), 2u);
    expectGoodEnclosing(mask, g);
    EXPECT_EQ(g.partPixels[0] + g.partPixels[1], PixelSet::opaque(mask).count());
    // The two centres sit on either half of the bar, along its axis.
    Vec2 between = g.spec.radii[1].centre - g.spec.radii[0].centre;
    EXPECT_GT(between.norm(), 15.0);
    EXPECT_NEAR(std::fabs(std::atan2(between.y(), between.x())), kPi / 6, 0.1);
}

// The area inside a straight-edge outline: ½·Σ r_k·r_{k+1}·sin Δ_k.
double outlineArea(const Bound& r) {
    double area = 0.0;
    const auto& s = r.samples();
    for (std::size_t k = 0; k < s.size(); ++k) {
        const RadiusSample& a = s[k];
        const RadiusSample& b = s[(k + 1) % s.size()];
        area += 0.5 * a.radius * b.radius * std::sin(b.angle - a.angle);
    }
    return area;
}

// The distance from p to the segment ab.
double toSegment(const Vec2& p, const Vec2& a, const Vec2& b) {
    double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
    return (p - (a + t * (b - a))).norm();
}

TEST(BoundsGen, TwoRadiiFitAVFarTighterThanOne) {
    // A V whose centroid lies in its open mouth: no single centre sees it well.
    auto vee = [](const Vec2& p) {
        return toSegment(p, Vec2(-12, 0), Vec2(12, 18)) < 2 || toSegment(p, Vec2(-12, 0), Vec2(12, -18)) < 2;
    };
    AlphaMask mask = maskOf(32, 44, vee);
    BoundsGenOptions options;
    options.radii = 2;
    GeneratedBounds two = generate(mask, options);
    GeneratedBounds one = generate(mask);
    expectGoodEnclosing(mask, two);
    expectGoodEnclosing(mask, one);
    Bounds a = buildBounds(two.spec), b = buildBounds(one.spec);
    // The sum of the two areas bounds their union's area from above.
    EXPECT_LT(outlineArea(a[0]) + outlineArea(a[1]), 0.85 * outlineArea(b[0]));
}

TEST(BoundsGen, HonoursTheSampleCount) {
    AlphaMask mask = maskOf(
        32, 32, [](const Vec2& p) { return p.norm() < 12 + 2 * std::sin(4 * std::atan2(p.y(), p.x())); });
    for (int n : {3, 5, 12, 40}) {
        BoundsGenOptions options;
        options.samples = n;
        GeneratedBounds g = generate(mask, options);
        ASSERT_EQ(g.spec.radii.size(), 1u);
        EXPECT_EQ(g.spec.radii[0].samples.size(), static_cast<std::size_t>(n));
        expectGoodEnclosing(mask, g);
    }
}

TEST(BoundsGen, IsDeterministic) {
    AlphaMask mask =
        maskOf(26, 20, [](const Vec2& p) { return std::fabs(p.x()) + 2 * std::fabs(p.y()) < 14; });
    GeneratedBounds a = generate(mask), b = generate(mask);
    EXPECT_EQ(boundsToJson(a.spec), boundsToJson(b.spec));
}

TEST(BoundsGen, BadOptionsAreErrors) {
    AlphaMask mask = maskOf(8, 8, [](const Vec2& p) { return p.norm() < 3; });
    AlphaMask empty = maskOf(8, 8, [](const Vec2&) { return false; });
    auto message = [](const AlphaMask& m, BoundsGenOptions o) {
        Result<GeneratedBounds> g = generateBounds(m, o);
        return g.ok() ? std::string("no error") : g.error().message();
    };
    BoundsGenOptions twoSamples;
    twoSamples.samples = 2;
    EXPECT_NE(message(mask, twoSamples).find("at least 3 samples"), std::string::npos);
    BoundsGenOptions noRadii;
    noRadii.radii = 0;
    EXPECT_NE(message(mask, noRadii).find("1 to 16 radii"), std::string::npos);
    BoundsGenOptions containerSplit;
    containerSplit.container = true;
    containerSplit.radii = 2;
    EXPECT_NE(message(mask, containerSplit).find("one bound for a container"), std::string::npos);
    BoundsGenOptions centredSplit;
    centredSplit.radii = 2;
    centredSplit.centre = Vec2(0, 0);
    EXPECT_NE(message(mask, centredSplit).find("--centre only for one bound"), std::string::npos);
    EXPECT_NE(message(empty, {}).find("no opaque pixels"), std::string::npos);
}

TEST(BoundsGen, ThresholdDecidesWhatIsOpaque) {
    AlphaMask mask = maskOf(20, 20, [](const Vec2& p) { return p.norm() < 4; });
    // A faint halo: alpha 100, below the default threshold 127.
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 20; ++x)
            if (mask.pixelCentre(x, y).norm() >= 4 && mask.pixelCentre(x, y).norm() < 8)
                mask.alpha[y * 20 + x] = 100;
    GeneratedBounds tight = generate(mask);
    BoundsGenOptions low;
    low.threshold = 99;
    GeneratedBounds wide = generate(mask, low);
    EXPECT_LT(buildBounds(tight.spec)[0].maxRadius(), 5.5);
    EXPECT_GT(buildBounds(wide.spec)[0].maxRadius(), 7.5);
}

}  // namespace
}  // namespace polar
