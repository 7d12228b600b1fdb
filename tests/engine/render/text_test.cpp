#include "polar/render/text.h"

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "golden.h"
#include "render/font_glyphs.h"

namespace polar::render {
namespace {

using testing::expectGoldenAtEveryThreadCount;

TEST(TextGolden, PrintableAsciiAndScales) {
    Canvas canvas(160, 104);
    std::string ascii;
    for (int c = 32; c < 127; ++c) {
        ascii.push_back(char(c));
        if ((c - 31) % 24 == 0) ascii.push_back('\n');
    }
    expectGoldenAtEveryThreadCount(canvas, "text", [&](auto& painter) {
        painter.clear(Color{16, 20, 32, 255});
        painter.drawText(ascii, 2, 2, 1, kWhite);
        painter.drawText("SCORE 01230", 2, 48, 2, kYellow);
        painter.drawText("Lives: 3", 2, 72, 2, kGreen.withAlpha(160));
        painter.drawText("\x01\x7f", 120, 72, 2, kRed);  // not printable: hollow boxes
        painter.drawText("clipped", 130, 96, 2, kOrange);
    });
}

TEST(Text, MeasureMatchesWhatIsDrawn) {
    EXPECT_EQ(measureText("", 3).width, 0);
    EXPECT_EQ(measureText("", 3).height, 0);
    EXPECT_EQ(measureText("A", 1).width, 5);
    EXPECT_EQ(measureText("A", 1).height, 9);
    EXPECT_EQ(measureText("AB", 2).width, 22);
    EXPECT_EQ(measureText("ab\nlonger", 1).width, 35);
    EXPECT_EQ(measureText("ab\nlonger", 1).height, 19);

    // Every inked pixel lies inside the measured box, and the box's edges are reached.
    const std::string text = "Wg|_\nQy";
    const TextSize size = measureText(text, 3);
    Canvas canvas(80, 80);
    canvas.clear(kBlack);
    drawText(canvas, text, 5, 7, 3, kWhite);
    int maxX = -1, maxY = -1;
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 80; ++x)
            if (canvas.pixel(x, y) == kWhite) {
                ASSERT_GE(x, 5);
                ASSERT_GE(y, 7);
                maxX = std::max(maxX, x);
                maxY = std::max(maxY, y);
            }
    EXPECT_EQ(maxX, 5 + size.width - 1);
    EXPECT_EQ(maxY, 7 + size.height - 1);
}

TEST(Text, EveryPrintableGlyphIsDistinctAndInked) {
    std::set<detail::GlyphRows> seen;
    for (int c = 33; c < 127; ++c) {
        const detail::GlyphRows& rows = detail::glyphFor(char(c));
        int ink = 0;
        for (auto row : rows) ink += row != 0;
        EXPECT_GT(ink, 0) << char(c);
        EXPECT_TRUE(seen.insert(rows).second) << "glyph '" << char(c) << "' duplicates another";
    }
    for (auto row : detail::glyphFor(' ')) EXPECT_EQ(row, 0);
    EXPECT_EQ(detail::glyphFor('\x01'), detail::glyphFor('\x7f'));
    EXPECT_NE(detail::glyphFor('\x01'), detail::glyphFor('O'));
}

// The game prints "µs" (the debug panel's time per effect): UTF-8 µ is one glyph of its own, one
// cell wide, neither the box nor a 'u'; a broken sequence is one box a byte.
TEST(Text, MicroIsAGlyphOfItsOwn) {
    const detail::GlyphRows& micro = detail::glyphFor(U'\u00B5');
    EXPECT_NE(micro, detail::glyphFor('\x01'));
    EXPECT_NE(micro, detail::glyphFor('u'));
    EXPECT_NE(micro[7], 0) << "a descender";
    EXPECT_EQ(measureText("12 \xC2\xB5s", 1).width, measureText("12 us", 1).width);
    Canvas drawn(20, 12), expected(20, 12);
    drawText(drawn, "\xC2\xB5", 0, 0, 1, kWhite);
    for (int r = 0; r < kGlyphHeight; ++r)
        for (int c = 0; c < kGlyphWidth; ++c)
            EXPECT_EQ(drawn.pixel(c, r) == kWhite, ((micro[r] >> (kGlyphWidth - 1 - c)) & 1) != 0)
                << c << "," << r;
    std::size_t at = 0;
    EXPECT_EQ(detail::nextCodePoint("\xC2", at), char32_t(0xC2)) << "cut short: the byte itself";
    at = 0;
    EXPECT_EQ(detail::nextCodePoint("\xC0\x80", at), char32_t(0xC0)) << "an overlong form";
    EXPECT_EQ(at, 1u);
    EXPECT_EQ(measureText("\xC2", 1).width, measureText("x", 1).width);
}

}  // namespace
}  // namespace polar::render
