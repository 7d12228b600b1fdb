#include "polar/render/canvas.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "polar/render/image.h"
#include "polar/render/view.h"

namespace polar::render {
namespace {

TEST(Canvas, StartsOpaqueBlackAndClears) {
    Canvas canvas(5, 3);
    EXPECT_EQ(canvas.pixel(4, 2), kBlack);
    canvas.clear(kOrange);
    EXPECT_EQ(canvas.pixel(0, 0), kOrange);
    EXPECT_EQ(canvas.pixel(4, 2), kOrange);
}

TEST(Canvas, PixelAccessOutsideIsIgnored) {
    Canvas canvas(4, 4);
    canvas.setPixel(-1, 0, kWhite);
    canvas.setPixel(0, 4, kWhite);
    canvas.blendPixel(4, 0, kWhite);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) EXPECT_EQ(canvas.pixel(x, y), kBlack);
    EXPECT_EQ(canvas.pixel(-1, -1), kTransparent);
}

TEST(Canvas, BlendPixelIsPremultipliedOver) {
    Canvas canvas(1, 1);
    canvas.clear(Color{100, 50, 0, 255});
    canvas.blendPixel(0, 0, Color{200, 250, 255, 51});  // 20 % over
    // d' = round(c·a/255) + round(d·(255 − a)/255): 40 + 80, 50 + 40, 51 + 0
    EXPECT_EQ(canvas.pixel(0, 0), (Color{120, 90, 51, 255}));
    canvas.blendPixel(0, 0, Color{1, 2, 3, 255});
    EXPECT_EQ(canvas.pixel(0, 0), (Color{1, 2, 3, 255}));
    canvas.blendPixel(0, 0, Color{255, 255, 255, 0});
    EXPECT_EQ(canvas.pixel(0, 0), (Color{1, 2, 3, 255}));
}

TEST(Canvas, WrapsMemoryWithPadding) {
    // Rows longer than the width (pitch > 4·w): rows must be found by pitch.
    std::vector<std::uint32_t> memory(64 * 2, 0);
    {
        Canvas canvas = Canvas::wrap(memory.data(), 10, 2, 64 * 4);
        EXPECT_EQ(canvas.pitch(), 256);
        canvas.clear(kBlue);
        canvas.setPixel(9, 1, kRed);
    }
    EXPECT_EQ(memory[0], kBlue.argb());
    EXPECT_EQ(memory[10], 0u);  // beyond the wrapped width: untouched
    EXPECT_EQ(memory[64 + 9], kRed.argb());
}

TEST(Canvas, OwnsRowsOfExactlyItsWidthOnACacheLine) {
    Canvas canvas(13, 3);
    EXPECT_EQ(canvas.pitch(), 13 * 4);
    EXPECT_EQ(canvas.row(1), canvas.row(0) + 13);
    EXPECT_EQ(reinterpret_cast<std::uintptr_t>(canvas.row(0)) % 64, 0u);
}

TEST(Canvas, MovesAndClones) {
    Canvas a(3, 3);
    a.setPixel(1, 1, kRed);
    Canvas b = a.clone();
    Canvas c = std::move(a);
    EXPECT_EQ(c.pixel(1, 1), kRed);
    b.setPixel(1, 1, kGreen);
    EXPECT_EQ(c.pixel(1, 1), kRed);
    EXPECT_EQ(b.pixel(1, 1), kGreen);
}

TEST(Image, PremultiplyRoundsAndUnpremultiplyInverts) {
    EXPECT_EQ(premultiply(Color{255, 128, 0, 255}), 0xFFFF8000u);
    EXPECT_EQ(premultiply(Color{255, 128, 7, 0}), 0u);
    EXPECT_EQ(premultiply(Color{255, 255, 255, 128}), 0x80808080u);
    for (int a : {1, 17, 128, 254, 255})
        for (int c : {0, 1, 100, 254, 255}) {
            const Color in{std::uint8_t(c), 0, 0, std::uint8_t(a)};
            const Color out = unpremultiply(premultiply(in));
            // Premultiplying loses precision at low alpha: the round trip is within 255/(2a).
            EXPECT_LE(std::abs(int(out.r) - c), 255 / (2 * a) + 1) << c << "@" << a;
            EXPECT_EQ(out.a, a);
        }
}

TEST(Image, VisibleRegionCoversEveryVisibleTexel) {
    Image image(10, 8);
    EXPECT_TRUE(image.visibleRegion().empty);
    image.setPixel(3, 2, kWhite);
    image.setPixel(6, 5, kWhite.withAlpha(1));
    image.setPixel(9, 7, kTransparent);  // transparent texels do not count
    const Image::VisibleRegion& r = image.visibleRegion();
    EXPECT_FALSE(r.empty);
    EXPECT_EQ(r.minX, 3);
    EXPECT_EQ(r.maxX, 7);
    EXPECT_EQ(r.minY, 2);
    EXPECT_EQ(r.maxY, 6);
    EXPECT_EQ(r.minSum, 5);
    EXPECT_EQ(r.maxSum, 13);
    EXPECT_EQ(r.minDiff, 0);
    EXPECT_EQ(r.maxDiff, 2);
}

TEST(View, MapsWorldYUpToCanvasYDown) {
    View view(200, 100);
    EXPECT_EQ(view.toCanvas({0, 0}), Vec2(0, 100));  // world origin: bottom-left corner
    EXPECT_EQ(view.toCanvas({200, 100}), Vec2(200, 0));
    view.setCentre({10, 20});
    view.setZoom(2);
    EXPECT_EQ(view.toCanvas({10, 20}), Vec2(100, 50));
    EXPECT_EQ(view.toCanvas({11, 21}), Vec2(102, 48));
    const Vec2 p(-3.25, 7.5);
    EXPECT_TRUE(view.toWorld(view.toCanvas(p)).isApprox(p));
    EXPECT_TRUE(transformPoint(view.matrix(), p).isApprox(view.toCanvas(p)));
}

}  // namespace
}  // namespace polar::render
