#pragma once
// The built-in font's pixels. Private to the renderer; text.h is the public face.
#include <array>
#include <cstdint>
#include <string_view>

namespace polar::render::detail {

// A glyph as rows top to bottom; bit 4 of each row is the leftmost of its 5 columns.
using GlyphRows = std::array<std::uint8_t, 9>;

// The glyph for a code point: printable ASCII and the few others the game prints (µ) have their
// own, anything else a hollow box.
const GlyphRows& glyphFor(char32_t code);
// The code point of the UTF-8 sequence at text[at], moving `at` past it. A byte that does not
// start a whole, shortest-form sequence is one code point of its own (it draws as the box).
char32_t nextCodePoint(std::string_view text, std::size_t& at);

}  // namespace polar::render::detail
