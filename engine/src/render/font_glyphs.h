#pragma once
// The built-in font's pixels. Private to the renderer; text.h is the public face.
#include <array>
#include <cstdint>

namespace polar::render::detail {

// A glyph as rows top to bottom; bit 4 of each row is the leftmost of its 5 columns.
using GlyphRows = std::array<std::uint8_t, 9>;

// The glyph for c: printable ASCII has its own, anything else a hollow box.
const GlyphRows& glyphFor(char c);

}  // namespace polar::render::detail
