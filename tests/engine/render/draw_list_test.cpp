#include "polar/render/draw_list.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdint>
#include <cstdlib>
#include <new>
#include <string>
#include <vector>

#include "golden.h"
#include "polar/render/view.h"
#include "polar/tasks.h"

// Counts every allocation of this test program while `counting` is set, so a test can show that a
// warm frame allocates nothing.
namespace {
std::atomic<bool> counting{false};
std::atomic<long> allocations{0};
}  // namespace

void* operator new(std::size_t size) {
    if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1, std::memory_order_relaxed);
    if (void* p = std::malloc(size ? size : 1)) return p;
    throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}

namespace polar::render {
namespace {

using testing::drawCheckerboard;
using testing::Immediate;
using testing::makeArrowSprite;

// A busy frame with every kind of command: 600 sprites (rotated, scaled, mirrored, tinted, faded,
// off the edges), shapes of every kind, text, single pixels, all from a fixed 32-bit LCG.
template <class Painter>
void busyScene(Painter& painter, const Image& arrow, int width, int height) {
    std::uint32_t state = 2024;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / 16777216.0;
    };
    const View view(width, height);
    for (int i = 0; i < 600; ++i) {
        const Vec2 at(-20 + next() * (width + 40), -20 + next() * (height + 40));
        const double sx = (next() < 0.2 ? -1 : 1) * (0.5 + 2.5 * next()), sy = 0.5 + 2.5 * next();
        const Transform t(view.toWorld(at), next() * kTwoPi, Vec2(sx, sy));
        SpriteStyle style;
        if (i % 5 == 0) style = {Color{200, 255, 120, 230}, std::uint8_t(40 + 200 * next())};
        painter.drawSprite(arrow, Mat3(view.matrix() * t.matrix()), style);
        if (i % 40 == 0) {
            const Vec2 c(next() * width, next() * height);
            painter.fillCircle(c, 3 + 30 * next(), kBlue.withAlpha(120));
            painter.drawCircle(c, 3 + 30 * next(), kWhite);
            painter.drawLine(c, {next() * width, next() * height}, kYellow.withAlpha(200));
            const std::vector<Vec2> poly{c, c + Vec2(40, 5), c + Vec2(10, 50), c + Vec2(-20, 20)};
            painter.fillPolygon(poly, kRed.withAlpha(100));
            painter.drawPolygon(poly, kGreen);
            painter.drawPolyline(poly, kOrange);
            painter.fillRect(int(c.x()), int(c.y()), 37, 23, kGray.withAlpha(90));
            painter.drawRect(int(c.x()) - 5, int(c.y()) - 5, 47, 33, kWhite);
            painter.drawText("BAND 42\nx", int(c.x()), int(c.y()), 1 + i % 3, kYellow);
        }
    }
}

// The immediate-mode adapter plus the pixel calls the scene needs.
struct ImmediatePixels : Immediate {
    ImmediatePixels(Canvas& canvas) : Immediate(canvas), canvas(canvas) {}
    void blendPixel(int x, int y, Color c) { canvas.blendPixel(x, y, c); }
    void setPixel(int x, int y, Color c) { canvas.setPixel(x, y, c); }
    Canvas& canvas;
};

template <class Painter>
void pixels(Painter& painter, int width, int height) {
    for (int i = 0; i < 500; ++i) {
        painter.blendPixel((i * 37) % (width + 10) - 5, (i * 53) % (height + 10) - 5, kWhite.withAlpha(100));
        painter.setPixel((i * 41) % (width + 10) - 5, (i * 29) % (height + 10) - 5, kRed);
    }
}

bool sameBytes(const Canvas& a, const Canvas& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.row(y)[x] != b.row(y)[x]) return false;
    return true;
}

TEST(DrawList, BusyFrameIsTheSameBytesAtEveryThreadCount) {
    const Image arrow = makeArrowSprite();
    const int width = 333, height = 251;  // bands that do not divide the rows evenly
    Canvas expected(width, height);
    drawCheckerboard(expected);
    ImmediatePixels immediate(expected);
    busyScene(immediate, arrow, width, height);
    pixels(immediate, width, height);

    DrawList list;
    busyScene(list, arrow, width, height);
    pixels(list, width, height);
    for (std::uint32_t workers : {1u, 2u, 3u, 4u, 7u, 8u, 16u}) {
        ThreadPool pool(workers);
        Canvas canvas(width, height);
        drawCheckerboard(canvas);
        list.draw(canvas, &pool);
        EXPECT_TRUE(sameBytes(canvas, expected)) << workers << " threads";
    }
    Canvas alone(width, height);
    drawCheckerboard(alone);
    list.draw(alone);
    EXPECT_TRUE(sameBytes(alone, expected));
}

TEST(DrawList, DrawsOverWhatIsAlreadyThereAndResetForgets) {
    Canvas canvas(40, 30);
    canvas.clear(kBlue);
    DrawList list;
    list.fillRect(0, 0, 10, 10, kRed);
    EXPECT_EQ(list.size(), 1u);
    list.draw(canvas);
    EXPECT_EQ(canvas.pixel(5, 5), kRed);
    EXPECT_EQ(canvas.pixel(20, 20), kBlue);
    list.reset();
    EXPECT_EQ(list.size(), 0u);
    canvas.clear(kBlue);
    list.draw(canvas);
    EXPECT_EQ(canvas.pixel(5, 5), kBlue);
}

TEST(DrawList, AWarmFrameAllocatesNothing) {
    const Image arrow = makeArrowSprite();
    ThreadPool pool(3);
    Canvas canvas(320, 200);
    DrawList list;
    for (int frame = 0; frame < 3; ++frame) {
        if (frame == 2) counting = true;
        list.reset();
        list.clear(kBlack);
        for (int i = 0; i < 50; ++i) {
            list.drawSprite(arrow, Vec2(7.0 * i, 4.0 * i));
            const Vec2 tri[] = {{1.0 * i, 2}, {3.0 * i, 90}, {2.0 * i, 150}};
            list.fillPolygon(tri, kRed.withAlpha(80));
            list.drawText("WAVE 3", i, 2 * i, 1, kWhite);
        }
        list.draw(canvas, &pool);
        counting = false;
    }
    EXPECT_EQ(allocations.load(), 0);
}

}  // namespace
}  // namespace polar::render
