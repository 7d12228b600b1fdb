#pragma once
#include <string_view>

#include "polar/render/canvas.h"
#include "polar/render/color.h"

namespace polar::render {

// Polarcade's built-in bitmap font: printable ASCII (32–126) and µ, each glyph 5 × 9 pixels (7
// above the baseline, 2 for descenders) in a 6 × 10 cell, drawn at an integer scale. Text is
// UTF-8; any other character shows as one hollow box.
inline constexpr int kGlyphWidth = 5;
inline constexpr int kGlyphHeight = 9;
inline constexpr int kCharAdvance = 6;  // glyph width + 1 pixel of spacing
inline constexpr int kLineHeight = 10;  // glyph height + 1 pixel of leading

struct TextSize {
    int width = 0;
    int height = 0;
};

// Draws `text` with its top-left cell corner at canvas pixel (x, y), every font pixel a
// scale × scale block (scale ≥ 1). '\n' starts a new line. Clipped at the canvas edges.
void drawText(Canvas& canvas, std::string_view text, int x, int y, int scale, Color color);
// The size of the box drawText fills: the longest line's advance (less the trailing spacing) by
// the number of lines' height (less the last line's leading), times scale; {0, 0} for "".
TextSize measureText(std::string_view text, int scale);

}  // namespace polar::render
