#include "polar/render/sprite.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "golden.h"
#include "polar/render/view.h"
#include "render/blend.h"
#include "render/row_clip.h"
#include "render/sprite_span.h"

namespace polar::render {
namespace {

using testing::drawCheckerboard;
using testing::expectGoldenAtEveryThreadCount;
using testing::expectMatchesGolden;
using testing::makeArrowSprite;

// The canvas matrix of an object at canvas point (cx, cy) (y down) turned `degrees` counter-clockwise
// on screen and scaled by (sx, sy), through a View whose world is the canvas with y flipped.
Mat3 placed(const Canvas& canvas, double cx, double cy, double degrees, double sx, double sy) {
    const View view(canvas.width(), canvas.height());
    const Transform t(view.toWorld({cx, cy}), degToRad(degrees), Vec2(sx, sy));
    return view.matrix() * t.matrix();
}

bool sameRegion(const Canvas& a, int ax, int ay, const Canvas& b, int bx, int by, int w, int h) {
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (a.row(ay + y)[ax + x] != b.row(by + y)[bx + x]) return false;
    return true;
}

TEST(SpriteGolden, Rotated) {
    Canvas canvas(128, 96);
    drawCheckerboard(canvas);
    const Image arrow = makeArrowSprite();
    const double angles[] = {0, 30, 90, 135, 200, -60};
    expectGoldenAtEveryThreadCount(canvas, "sprite_rotated", [&](auto& painter) {
        for (int i = 0; i < 6; ++i)
            painter.drawSprite(arrow,
                               placed(canvas, 24 + (i % 3) * 40, 26 + (i / 3) * 46, angles[i], 1.5, 1.5));
    });
}

TEST(SpriteGolden, Scaled) {
    Canvas canvas(128, 96);
    drawCheckerboard(canvas);
    const Image arrow = makeArrowSprite();
    expectGoldenAtEveryThreadCount(canvas, "sprite_scaled", [&](auto& painter) {
        painter.drawSprite(arrow, placed(canvas, 40, 30, 0, 3.0, 3.0));
        painter.drawSprite(arrow, placed(canvas, 100, 24, 0, 0.5, 0.5));
        painter.drawSprite(arrow, placed(canvas, 100, 50, 0, 1.0, 1.0));
        painter.drawSprite(arrow, placed(canvas, 50, 75, 20, 2.25, 2.25));
        painter.drawSprite(arrow, placed(canvas, 104, 78, 0, 1.7, 1.7));
    });
}

TEST(SpriteGolden, NonUniformlyScaled) {
    Canvas canvas(128, 96);
    drawCheckerboard(canvas);
    const Image arrow = makeArrowSprite();
    expectGoldenAtEveryThreadCount(canvas, "sprite_nonuniform", [&](auto& painter) {
        painter.drawSprite(arrow, placed(canvas, 36, 24, 0, 3.0, 1.0));
        painter.drawSprite(arrow, placed(canvas, 100, 30, 0, 1.0, 3.0));
        painter.drawSprite(arrow, placed(canvas, 36, 70, 45, 3.0, 1.0));  // rotation after scale: no shear
        painter.drawSprite(arrow, placed(canvas, 100, 72, -30, 0.75, 2.5));
    });
}

TEST(SpriteGolden, Mirrored) {
    Canvas canvas(128, 96);
    drawCheckerboard(canvas);
    const Image arrow = makeArrowSprite();
    expectGoldenAtEveryThreadCount(canvas, "sprite_mirrored", [&](auto& painter) {
        painter.drawSprite(arrow, placed(canvas, 32, 24, 0, 2, 2));     // as drawn
        painter.drawSprite(arrow, placed(canvas, 96, 24, 0, -2, 2));    // points left, stripe on top
        painter.drawSprite(arrow, placed(canvas, 32, 72, 0, 2, -2));    // points right, stripe below
        painter.drawSprite(arrow, placed(canvas, 96, 72, 30, -2, -2));  // both: a rotation by 180° + 30°
    });
}

TEST(SpriteGolden, AlphaBlendedTintedAndFaded) {
    Canvas canvas(128, 96);
    drawCheckerboard(canvas);
    // A translucent disc sprite (alpha rising towards its centre) over the checkerboard and over
    // other sprites, plus tint and opacity.
    Image glow(24, 24);
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const double dx = x + 0.5 - 12, dy = y + 0.5 - 12, r2 = dx * dx + dy * dy;
            if (r2 < 144) glow.setPixel(x, y, Color{120, 220, 255, std::uint8_t(255 - r2 * 255 / 144)});
        }
    const Image arrow = makeArrowSprite();
    expectGoldenAtEveryThreadCount(canvas, "sprite_alpha", [&](auto& painter) {
        painter.drawSprite(arrow, placed(canvas, 34, 26, 0, 2, 2));
        painter.drawSprite(glow, placed(canvas, 40, 30, 0, 1.5, 1.5));
        painter.drawSprite(glow, placed(canvas, 90, 26, 0, 1.5, 1.5), {Color{255, 120, 120, 255}, 255});
        painter.drawSprite(arrow, placed(canvas, 34, 72, 15, 2, 2), {kWhite, 128});
        painter.drawSprite(arrow, placed(canvas, 92, 72, -15, 2, 2), {Color{120, 255, 120, 200}, 200});
    });
}

TEST(SpriteGolden, ClippedAtEveryEdge) {
    Canvas canvas(96, 64);
    drawCheckerboard(canvas);
    const Image arrow = makeArrowSprite();
    const double spots[][3] = {{0, 0, 20},    {48, -4, 95},  {96, 0, 160},  {100, 32, 180},
                               {96, 64, 250}, {48, 68, 275}, {-2, 64, 330}, {-6, 32, 0}};
    expectGoldenAtEveryThreadCount(canvas, "sprite_clipped", [&](auto& painter) {
        for (auto& s : spots) painter.drawSprite(arrow, placed(canvas, s[0], s[1], s[2], 2, 2));
    });
}

TEST(Sprite, IdentityPlacementCopiesTheImage) {
    const Image arrow = makeArrowSprite();
    Canvas canvas(40, 30);
    canvas.clear(kTransparent);
    // Centre (20, 15): texel (u, v) lands on pixel (u + 10, v + 8).
    drawSprite(canvas, arrow, Vec2(20, 15));
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) {
            const int u = x - 10, v = y - 8;
            const bool inside = u >= 0 && v >= 0 && u < arrow.width() && v < arrow.height();
            const std::uint32_t want = inside ? arrow.premultiplied()[v * arrow.width() + u] : 0;
            ASSERT_EQ(canvas.row(y)[x], want) << x << "," << y;
        }
}

TEST(Sprite, QuarterTurnPermutesTexelsExactly) {
    const Image arrow = makeArrowSprite();  // 20 × 14
    Canvas canvas(40, 40);
    canvas.clear(kTransparent);
    drawSprite(canvas, arrow, placed(canvas, 20, 20, 90, 1, 1));
    // Counter-clockwise on screen: the arrow points up; texel (u, v) lands at (20 − 7 + v, 20 + 10 − 1 − u).
    for (int v = 0; v < arrow.height(); ++v)
        for (int u = 0; u < arrow.width(); ++u)
            ASSERT_EQ(canvas.row(29 - u)[13 + v], arrow.premultiplied()[v * arrow.width() + u])
                << u << "," << v;
}

TEST(Sprite, MirroringTwiceIsTheIdentity) {
    const Image arrow = makeArrowSprite();
    Canvas a(48, 48), b(48, 48);
    drawCheckerboard(a);
    drawCheckerboard(b);
    drawSprite(a, arrow, placed(a, 24, 24, 37, 1.5, 1.5));
    drawSprite(b, arrow, placed(b, 24, 24, 37 + 180, -1.5, -1.5));
    EXPECT_TRUE(sameRegion(a, 0, 0, b, 0, 0, 48, 48));
}

TEST(Sprite, ClippingMatchesALargerCanvas) {
    // The same sprites drawn on a large canvas and on a small window of it, placed by whole-pixel
    // offsets: the window's pixels must equal the large canvas's, at every edge and corner.
    const Image arrow = makeArrowSprite();
    Canvas big(160, 120);
    big.clear(kBlack);
    const int ox = 50, oy = 40;
    Canvas small(60, 40);
    small.clear(kBlack);
    for (int i = 0; i < 40; ++i) {
        const double x = 40 + (i * 37) % 80 + 0.37, y = 30 + (i * 53) % 60 + 0.81, deg = i * 29.0;
        const double sx = 0.7 + (i % 5) * 0.4, sy = (i % 3 == 0 ? -1 : 1) * (0.8 + (i % 4) * 0.3);
        drawSprite(big, arrow, placed(big, x, y, deg, sx, sy));
        // The small canvas is 60 × 40, so its View's world differs: place through canvas matrices.
        Mat3 m = placed(big, x, y, deg, sx, sy);
        m(0, 2) -= ox;
        m(1, 2) -= oy;
        drawSprite(small, arrow, m);
    }
    EXPECT_TRUE(sameRegion(big, ox, oy, small, 0, 0, small.width(), small.height()));
}

TEST(Sprite, WholePixelMovesMoveEveryPixel) {
    const Image arrow = makeArrowSprite();
    Canvas a(64, 64), b(64, 64);
    a.clear(kBlack);
    b.clear(kBlack);
    drawSprite(a, arrow, placed(a, 20.25, 22.625, 41, 1.3, 0.9));
    drawSprite(b, arrow, placed(b, 20.25 + 17, 22.625 + 9, 41, 1.3, 0.9));
    EXPECT_TRUE(sameRegion(a, 0, 0, b, 17, 9, 64 - 17, 64 - 9));
}

TEST(Sprite, DegenerateMatricesDrawNothing) {
    const Image arrow = makeArrowSprite();
    Canvas canvas(32, 32);
    canvas.clear(kBlack);
    Mat3 zero = Mat3::Zero();
    zero(2, 2) = 1;
    zero(0, 2) = zero(1, 2) = 16;
    drawSprite(canvas, arrow, zero);
    Mat3 nan = placed(canvas, 16, 16, 0, 1, 1);
    nan(0, 0) = std::numeric_limits<double>::quiet_NaN();
    drawSprite(canvas, arrow, nan);
    Mat3 far = placed(canvas, 1e30, 16, 0, 1, 1);
    drawSprite(canvas, arrow, far);
    Mat3 tiny = placed(canvas, 16, 16, 0, 1e-9, 1e-9);
    drawSprite(canvas, arrow, tiny);
    drawSprite(canvas, Image(), placed(canvas, 16, 16, 0, 1, 1));
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(canvas.row(y)[x], kBlack.argb());
}

TEST(Sprite, HugeMagnificationFillsTheCanvasWithOneTexel) {
    Image red(4, 4);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            red.setPixel(x, y, Color{std::uint8_t(60 * x), std::uint8_t(60 * y), 0, 255});
    Canvas canvas(32, 32);
    // Magnified 10⁴ times, the canvas centre shows bound point (−0.5, −0.5), texel (1.5, 2.5), and
    // the whole 32-pixel canvas stays within 0.002 of it: all one texel, (1, 2).
    drawSprite(canvas, red, placed(canvas, 16 + 5000, 16 - 5000, 0, 1e4, 1e4));
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) ASSERT_EQ(canvas.row(y)[x], red.premultiplied()[2 * 4 + 1]);
}

// The sampling rule of sprite.h evaluated for every pixel of the canvas, with no spans: texel
// coordinates in 32.32 fixed point from the anchor pixel ⌊c⌋, blended premultiplied "over".
void referenceDraw(Canvas& canvas, const Image& image, const Mat3& m) {
    const double l00 = m(0, 0), l01 = m(0, 1), l10 = m(1, 0), l11 = m(1, 1), cx = m(0, 2), cy = m(1, 2);
    const double det = l00 * l11 - l01 * l10;
    const double i00 = l11 / det, i01 = -l01 / det, i10 = -l10 / det, i11 = l00 / det;
    const double one = 4294967296.0, hw = image.width() / 2.0, hh = image.height() / 2.0;
    const std::int64_t ax = std::int64_t(std::floor(cx)), ay = std::int64_t(std::floor(cy));
    const double dx = (double(ax) - cx) + 0.5, dy = (double(ay) - cy) + 0.5;
    const std::int64_t ua = std::llround(((i00 * dx + i01 * dy) + hw) * one);
    const std::int64_t va = std::llround((hh - (i10 * dx + i11 * dy)) * one);
    const std::int64_t dux = std::llround(i00 * one), duy = std::llround(i01 * one);
    const std::int64_t dvx = std::llround(-i10 * one), dvy = std::llround(-i11 * one);
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) {
            const std::int64_t u = ua + (x - ax) * dux + (y - ay) * duy,
                               v = va + (x - ax) * dvx + (y - ay) * dvy;
            if (u < 0 || v < 0 || (u >> 32) >= image.width() || (v >> 32) >= image.height()) continue;
            detail::blendInto(&canvas.row(y)[x],
                              image.premultiplied()[(v >> 32) * image.width() + (u >> 32)]);
        }
}

TEST(Sprite, SpansMatchThePerPixelRule) {
    const Image arrow = makeArrowSprite();
    std::uint32_t state = 99;
    auto uniform = [&state](double lo, double hi) {
        state = state * 1664525u + 1013904223u;
        return lo + (hi - lo) * ((state >> 8) / 16777216.0);
    };
    for (int i = 0; i < 300; ++i) {
        Canvas fast(61, 47), reference(61, 47);
        drawCheckerboard(fast);
        drawCheckerboard(reference);
        // Ordinary placements, then nearly axis-aligned turns, then extreme scales.
        double deg = uniform(0, 360), sx = uniform(0.2, 4), sy = uniform(0.2, 4);
        if (i % 3 == 1) deg = (i % 4) * 90 + uniform(-1e-7, 1e-7);
        if (i % 10 == 2) sx = sy = uniform(20, 200);
        if (i % 10 == 5) sx = sy = uniform(0.01, 0.1);
        if (i % 2) sx = -sx;
        const Mat3 m = placed(fast, uniform(-20, 80), uniform(-20, 66), deg, sx, sy);
        drawSprite(fast, arrow, m);
        referenceDraw(reference, arrow, m);
        ASSERT_TRUE(sameRegion(fast, 0, 0, reference, 0, 0, 61, 47)) << "placement " << i;
    }
}

// Sprite edges exactly on whole pixels (between two pixel centres) and on half pixels (through a
// row or column of centres, where the half-open rule [0, w) × [0, h) decides), on each of the four
// sides, at several scales, mirrored and turned, through the public drawSprite against the
// sampling rule evaluated pixel by pixel (referenceDraw). A row or column too many or too few at
// any edge differs.
TEST(Sprite, EdgesOnWholeAndHalfPixelsFollowTheSamplingRule) {
    std::vector<Image> images;
    for (auto [w, h] : {std::pair{6, 4}, std::pair{5, 3}}) {
        Image image(w, h);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x)
                image.setPixel(x, y, Color{std::uint8_t(40 * x + 20), std::uint8_t(60 * y + 30), 200, 255});
        images.push_back(std::move(image));
    }
    // How often each side (left, right, top, bottom) fell on a whole and on a half pixel.
    int whole[4] = {0, 0, 0, 0}, half[4] = {0, 0, 0, 0};
    auto classify = [&](int side, double edge) {
        double f = edge - std::floor(edge);
        if (std::fabs(f) < 1e-9 || std::fabs(f - 1) < 1e-9) ++whole[side];
        if (std::fabs(f - 0.5) < 1e-9) ++half[side];
    };
    int placements = 0;
    for (const Image& image : images)
        for (double degrees : {0.0, 90.0, 180.0, 270.0, 30.0, 45.0})
            for (double sx : {0.5, 1.0, 1.5, 2.0, 2.5, -1.0, -3.0})
                for (double sy : {1.0, 1.5, 0.5, 3.0})
                    for (double ox : {0.0, 0.25, 0.5, 0.75})
                        for (double oy : {0.0, 0.5, 0.25}) {
                            Canvas fast(48, 40), reference(48, 40);
                            drawCheckerboard(fast);
                            drawCheckerboard(reference);
                            const Mat3 m = placed(fast, 20 + ox, 17 + oy, degrees, sx, sy);
                            drawSprite(fast, image, m);
                            referenceDraw(reference, image, m);
                            ASSERT_TRUE(sameRegion(fast, 0, 0, reference, 0, 0, 48, 40))
                                << image.width() << "x" << image.height() << " at (" << 20 + ox << ", "
                                << 17 + oy << "), " << degrees << " degrees, scale (" << sx << ", " << sy
                                << ")";
                            ++placements;
                            if (std::fmod(degrees, 90.0) != 0.0) continue;
                            double minX = 1e9, maxX = -1e9, minY = 1e9, maxY = -1e9;
                            for (double bx : {-image.width() / 2.0, image.width() / 2.0})
                                for (double by : {-image.height() / 2.0, image.height() / 2.0}) {
                                    double x = m(0, 0) * bx + m(0, 1) * by + m(0, 2);
                                    double y = m(1, 0) * bx + m(1, 1) * by + m(1, 2);
                                    minX = std::min(minX, x), maxX = std::max(maxX, x);
                                    minY = std::min(minY, y), maxY = std::max(maxY, y);
                                }
                            classify(0, minX), classify(1, maxX), classify(2, minY), classify(3, maxY);
                        }
    EXPECT_EQ(placements, 2 * 6 * 7 * 4 * 4 * 3);
    for (int side = 0; side < 4; ++side) {
        EXPECT_GE(whole[side], 50) << "side " << side << " on whole pixels";
        EXPECT_GE(half[side], 50) << "side " << side << " on half pixels";
    }
}

TEST(Sprite, EveryKernelDrawsTheSameBytes) {
    // Every kernel this CPU runs against the scalar reference, over many random placements,
    // including tints, fades, mirrors and spans ending at the canvas edge.
    const Image arrow = makeArrowSprite();
    Image noise(33, 17);  // odd sizes and every alpha value
    std::uint32_t state = 7;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return state >> 8;
    };
    for (int y = 0; y < noise.height(); ++y)
        for (int x = 0; x < noise.width(); ++x) {
            const std::uint32_t v = next();
            noise.setPixel(
                x, y,
                Color{std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), std::uint8_t(next())});
        }
    for (const detail::NamedKernel& kernel : detail::spanKernels()) {
        SCOPED_TRACE(kernel.name);
        state = 7;
        Canvas fast(83, 61), reference(83, 61);
        drawCheckerboard(fast);
        drawCheckerboard(reference);
        for (int i = 0; i < 400; ++i) {
            const Image& image = i % 2 ? arrow : noise;
            const double x = (next() % 1000) / 1000.0 * 100 - 10, y = (next() % 1000) / 1000.0 * 80 - 10;
            const double deg = next() % 3600 / 10.0, sx = 0.3 + next() % 300 / 100.0,
                         sy = (next() % 2 ? -1 : 1) * (0.3 + next() % 300 / 100.0);
            SpriteStyle style;
            if (i % 7 == 0) style = {Color{200, 100, 50, 180}, std::uint8_t(next())};
            const Mat3 m = placed(fast, x, y, deg, sx, sy);
            detail::drawSpriteWith(fast, image, m, style, kernel.kernel);
            detail::drawSpriteWith(reference, image, m, style, detail::scalarSpanKernel);
        }
        Canvas untouched(83, 61);
        drawCheckerboard(untouched);
        ASSERT_FALSE(sameRegion(fast, 0, 0, untouched, 0, 0, fast.width(), fast.height()));
        EXPECT_TRUE(sameRegion(fast, 0, 0, reference, 0, 0, fast.width(), fast.height()));
    }
}

TEST(Sprite, EveryKernelMatchesScalarOnRandomScenes) {
    // Every kernel against the scalar reference, one draw at a time on random canvases: random
    // image sizes (1 to 70 texels a side) with runs of transparent and opaque texels among every
    // alpha, random transforms, tints and fades, random row clips, and sprites placed so their spans
    // end on the canvas's last column (no room after them) or cover one or two pixels.
    std::uint32_t state = 2024;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return state >> 8;
    };
    auto uniform = [&](double lo, double hi) { return lo + (hi - lo) * ((next() & 0xFFFF) / 65536.0); };
    const std::vector<detail::NamedKernel> kernels = detail::spanKernels();
    ASSERT_GE(kernels.size(), 1u);
    int drawnPixels = 0;
    for (int i = 0; i < 600; ++i) {
        const int iw = 1 + int(next() % 70), ih = 1 + int(next() % 70);
        Image image(iw, ih);
        for (int y = 0; y < ih; ++y)
            for (int x = 0; x < iw; ++x) {
                const std::uint32_t v = next(), kind = (x / 5 + y / 3 + i) % 4;
                const std::uint8_t a = kind == 0 ? 0 : kind == 1 ? 255 : std::uint8_t(next());
                image.setPixel(x, y, Color{std::uint8_t(v), std::uint8_t(v >> 8), std::uint8_t(v >> 16), a});
            }
        const int cw = 1 + int(next() % 90), ch = 1 + int(next() % 60);
        Canvas base(cw, ch);
        drawCheckerboard(base);
        // Centres anywhere near the canvas, or on its right edge, or on a corner.
        double cx = uniform(-20, cw + 20), cy = uniform(-20, ch + 20);
        if (i % 5 == 1) cx = cw - uniform(0, 3);
        if (i % 5 == 2) cx = cw, cy = uniform(0, ch);
        if (i % 11 == 3) cx = 0, cy = 0;
        double deg = uniform(0, 360), sx = uniform(0.05, 3), sy = uniform(0.05, 3);
        if (i % 4 == 0) deg = (i % 8) * 45;
        if (i % 9 == 4) sx = sy = uniform(0.01, 0.2);  // a pixel or two
        if (next() % 2) sy = -sy;
        const Mat3 m = placed(base, cx, cy, deg, sx, sy);
        SpriteStyle style;
        if (i % 3 == 0)
            style.tint = Color{std::uint8_t(next()), std::uint8_t(next()), std::uint8_t(next()), 255};
        if (i % 4 == 1) style.opacity = std::uint8_t(next());
        if (i % 13 == 2) style.tint.a = std::uint8_t(next());
        detail::RowClip clip = detail::allRows(base);
        if (i % 2) {
            clip.begin = int(next() % std::uint32_t(ch + 1));
            clip.end = clip.begin + int(next() % std::uint32_t(ch - clip.begin + 1));
        }
        Canvas reference = base.clone();
        detail::drawSpriteWith(reference, clip, image, m, style, detail::scalarSpanKernel);
        for (int y = 0; y < ch; ++y)
            for (int x = 0; x < cw; ++x) drawnPixels += reference.row(y)[x] != base.row(y)[x];
        for (const detail::NamedKernel& kernel : kernels) {
            Canvas fast = base.clone();
            detail::drawSpriteWith(fast, clip, image, m, style, kernel.kernel);
            ASSERT_TRUE(sameRegion(fast, 0, 0, reference, 0, 0, cw, ch)) << kernel.name << ", scene " << i;
        }
    }
    EXPECT_GT(drawnPixels, 50000);  // the scenes draw something
}

TEST(Sprite, TheActiveKernelIsTheFastestUnlessChosen) {
    const std::vector<detail::NamedKernel> kernels = detail::spanKernels();
    const std::string fastest = detail::activeSpanKernel().name;
#if defined(__x86_64__)
    EXPECT_EQ(fastest, __builtin_cpu_supports("avx2") ? "avx2" : "sse2");
#endif
    EXPECT_FALSE(detail::chooseSpanKernel("no-such-kernel"));
    EXPECT_EQ(detail::activeSpanKernel().name, fastest);
    for (const detail::NamedKernel& kernel : kernels) {
        ASSERT_TRUE(detail::chooseSpanKernel(kernel.name));
        EXPECT_EQ(detail::activeSpanKernel().kernel, kernel.kernel);
    }
    ASSERT_TRUE(detail::chooseSpanKernel(fastest));
}

}  // namespace
}  // namespace polar::render
