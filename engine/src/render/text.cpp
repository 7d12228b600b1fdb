#include "polar/render/text.h"

#include <algorithm>

#include "polar/render/shapes.h"
#include "render/font_glyphs.h"
#include "render/row_clip.h"

namespace polar::render {

void detail::drawText(Canvas& canvas, RowClip clip, std::string_view text, int x, int y, int scale,
                      Color color) {
    if (scale < 1) return;
    int penX = x, penY = y;
    for (std::size_t at = 0; at < text.size();) {
        const char32_t c = detail::nextCodePoint(text, at);
        if (c == U'\n') {
            penX = x;
            penY += kLineHeight * scale;
            continue;
        }
        const detail::GlyphRows& rows = detail::glyphFor(c);
        for (int r = 0; r < kGlyphHeight; ++r)
            for (int col = 0; col < kGlyphWidth; ++col)
                if (rows[r] & (1u << (kGlyphWidth - 1 - col)))
                    fillRect(canvas, clip, penX + col * scale, penY + r * scale, scale, scale, color);
        penX += kCharAdvance * scale;
    }
}

void drawText(Canvas& canvas, std::string_view text, int x, int y, int scale, Color color) {
    detail::drawText(canvas, detail::allRows(canvas), text, x, y, scale, color);
}

TextSize measureText(std::string_view text, int scale) {
    if (text.empty() || scale < 1) return {};
    int lines = 1, longest = 0, current = 0;
    for (std::size_t at = 0; at < text.size();) {
        if (detail::nextCodePoint(text, at) == U'\n') {
            ++lines;
            current = 0;
        } else {
            longest = std::max(longest, ++current);
        }
    }
    const int width = longest > 0 ? (longest * kCharAdvance - 1) * scale : 0;
    return {width, (lines * kLineHeight - 1) * scale};
}

}  // namespace polar::render
