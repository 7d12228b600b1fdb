#include "polar/render/shapes.h"

#include <gtest/gtest.h>

#include <vector>

#include "golden.h"

namespace polar::render {
namespace {

using testing::drawCheckerboard;
using testing::expectGoldenAtEveryThreadCount;
using testing::expectMatchesGolden;

int countColor(const Canvas& canvas, Color c) {
    int n = 0;
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) n += canvas.row(y)[x] == c.argb();
    return n;
}

TEST(ShapesGolden, LinesPolygonsCirclesRects) {
    Canvas canvas(128, 96);
    drawCheckerboard(canvas);
    expectGoldenAtEveryThreadCount(canvas, "shapes", [&](auto& painter) {
        // A star of lines in every octant.
        for (int i = 0; i < 16; ++i) {
            const double a = i * kTwoPi / 16;
            painter.drawLine({24.5, 24.5}, {24.5 + 20 * trig::cos(a), 24.5 + 20 * trig::sin(a)}, kYellow);
        }
        // A filled concave polygon with its outline, and a translucent one overlapping it.
        const std::vector<Vec2> arrowhead{{52, 6}, {84, 22}, {52, 38}, {62, 22}};
        painter.fillPolygon(arrowhead, kBlue);
        painter.drawPolygon(arrowhead, kWhite);
        const std::vector<Vec2> square{{70, 10}, {92, 10}, {92, 32}, {70, 32}};
        painter.fillPolygon(square, kRed.withAlpha(128));
        // An open polyline.
        const std::vector<Vec2> zigzag{{98, 6}, {106, 30}, {114, 6}, {122, 30}};
        painter.drawPolyline(zigzag, kGreen);
        // Circles: filled, outlined, translucent, and fractional centres.
        painter.fillCircle({20, 68}, 14, kOrange);
        painter.drawCircle({20, 68}, 17, kWhite);
        painter.fillCircle({52.3, 64.7}, 9.5, kGreen.withAlpha(140));
        painter.drawCircle({52.3, 64.7}, 9.5, kYellow);
        painter.drawCircle({52, 86}, 3, kWhite);
        painter.fillCircle({60.5, 86.5}, 0.5, kWhite);  // exactly one pixel centre
        // Rectangles: filled, outlined, translucent.
        painter.fillRect(74, 46, 30, 20, kBlue);
        painter.drawRect(70, 42, 38, 28, kWhite);
        painter.fillRect(90, 58, 30, 30, kYellow.withAlpha(96));
    });
}

TEST(ShapesGolden, ClippedAtEveryEdge) {
    Canvas canvas(64, 48);
    drawCheckerboard(canvas);
    expectGoldenAtEveryThreadCount(canvas, "shapes_clipped", [&](auto& painter) {
        painter.fillCircle({0, 0}, 12, kOrange);
        painter.drawCircle({64, 48}, 14, kWhite);
        painter.fillPolygon(std::vector<Vec2>{{50, -10}, {80, 20}, {40, 20}}, kBlue);
        painter.fillRect(-5, 30, 20, 40, kGreen);
        painter.drawLine({-100, 10}, {200, 40}, kYellow);
        painter.drawLine({30, -1000}, {34, 1000}, kRed);
        painter.drawPolygon(std::vector<Vec2>{{-8, 40}, {20, 52}, {10, 30}}, kWhite);
    });
}

TEST(Shapes, LineIncludesBothEndsAndIsSymmetric) {
    Canvas a(40, 30), b(40, 30);
    a.clear(kBlack);
    b.clear(kBlack);
    drawLine(a, {3.2, 4.9}, {35.7, 21.1}, kWhite);
    drawLine(b, {35.7, 21.1}, {3.2, 4.9}, kWhite);
    EXPECT_EQ(a.pixel(3, 4), kWhite);
    EXPECT_EQ(a.pixel(35, 21), kWhite);
    EXPECT_EQ(countColor(a, kWhite), 33);  // one pixel per column from 3 to 35
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 40; ++x) ASSERT_EQ(a.row(y)[x], b.row(y)[x]) << x << "," << y;
}

TEST(Shapes, ClippedLineKeepsItsPixels) {
    Canvas big(100, 100), small(30, 20);
    big.clear(kBlack);
    small.clear(kBlack);
    const Vec2 a(-250.5, -20.75), b(180.0, 25.5);  // crosses the small canvas
    drawLine(big, a + Vec2(40, 40), b + Vec2(40, 40), kWhite);
    drawLine(small, a, b, kWhite);
    for (int y = 0; y < 20; ++y)
        for (int x = 0; x < 30; ++x) ASSERT_EQ(small.row(y)[x], big.row(y + 40)[x + 40]) << x << "," << y;
    EXPECT_GT(countColor(small, kWhite), 0);
}

TEST(Shapes, TranslucentOutlineBlendsEachPixelOnce) {
    Canvas canvas(40, 40);
    canvas.clear(kBlack);
    const std::vector<Vec2> triangle{{5, 5}, {35, 8}, {12, 33}};
    drawPolygon(canvas, triangle, kWhite.withAlpha(128));
    // Once-blended white at half alpha over black is 128; twice would be 192.
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 40; ++x) {
            const Color c = canvas.pixel(x, y);
            ASSERT_TRUE((c == kBlack || c == Color{128, 128, 128, 255})) << x << "," << y;
        }
}

TEST(Shapes, PolygonsSharingAnEdgeDoNotOverlap) {
    Canvas canvas(40, 40);
    canvas.clear(kBlack);
    const Color half = kWhite.withAlpha(128);
    fillPolygon(canvas, std::vector<Vec2>{{3.3, 2.1}, {36.7, 9.4}, {14.2, 37.9}}, half);
    fillPolygon(canvas, std::vector<Vec2>{{36.7, 9.4}, {39.5, 39.5}, {14.2, 37.9}}, half);
    EXPECT_EQ(countColor(canvas, Color{192, 192, 192, 255}), 0);
    EXPECT_GT(countColor(canvas, Color{128, 128, 128, 255}), 500);
}

TEST(Shapes, FillRectClipsAndCountsExactly) {
    Canvas canvas(20, 10);
    canvas.clear(kBlack);
    fillRect(canvas, -3, 7, 10, 10, kRed);  // x 0..6, y 7..9
    EXPECT_EQ(countColor(canvas, kRed), 7 * 3);
    fillRect(canvas, 5, 5, -2, 3, kGreen);  // negative width: nothing
    fillRect(canvas, 100, 0, 5, 5, kGreen);
    EXPECT_EQ(countColor(canvas, kGreen), 0);
}

TEST(Shapes, FilledCircleHoldsTheCentresWithinTheRadius) {
    Canvas canvas(30, 30);
    canvas.clear(kBlack);
    const Vec2 c(14.7, 15.2);
    const double r = 9.3;
    fillCircle(canvas, c, r, kWhite);
    for (int y = 0; y < 30; ++y)
        for (int x = 0; x < 30; ++x) {
            const double dx = x + 0.5 - c.x(), dy = y + 0.5 - c.y(), d2 = dx * dx + dy * dy;
            if (std::abs(d2 - r * r) < 1e-6) continue;  // too close to call
            ASSERT_EQ(canvas.pixel(x, y) == kWhite, d2 <= r * r) << x << "," << y;
        }
}

TEST(Shapes, NonFiniteInputDrawsNothing) {
    Canvas canvas(10, 10);
    canvas.clear(kBlack);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    drawLine(canvas, {nan, 1}, {5, 5}, kWhite);
    fillCircle(canvas, {5, 5}, nan, kWhite);
    drawCircle(canvas, {nan, 5}, 3, kWhite);
    fillPolygon(canvas, std::vector<Vec2>{{0, 0}, {nan, 5}, {9, 9}}, kWhite);
    EXPECT_EQ(countColor(canvas, kWhite), 0);
}

}  // namespace
}  // namespace polar::render
