#pragma once
// Integer pixel arithmetic shared by the renderer's drawing code. Everything is exact integer
// math, so every compiler and every code path (scalar or SSE2) produces the same bytes.
#include <cstdint>

namespace polar::render::detail {

// round(x·y / 255) for x, y in [0, 255], exactly: with t = x·y + 128, (t + (t >> 8)) >> 8.
inline std::uint32_t mul255(std::uint32_t x, std::uint32_t y) {
    std::uint32_t t = x * y + 128;
    return (t + (t >> 8)) >> 8;
}

// Premultiplied "over": each channel d' = s + round(d·(255 − a_s)/255). Two channels are scaled at
// once in the 16-bit lanes of one 32-bit word (products ≤ 255·255 + 128 never carry into the next
// lane), and s + round(d·(255 − a)/255) ≤ a + (255 − a), so the channel sums never carry either.
inline std::uint32_t blendOver(std::uint32_t dst, std::uint32_t src) {
    std::uint32_t ia = 255 - (src >> 24);
    std::uint32_t rb = (dst & 0x00FF00FFu) * ia + 0x00800080u;
    rb = ((rb + ((rb >> 8) & 0x00FF00FFu)) >> 8) & 0x00FF00FFu;
    std::uint32_t ag = ((dst >> 8) & 0x00FF00FFu) * ia + 0x00800080u;
    ag = (ag + ((ag >> 8) & 0x00FF00FFu)) & 0xFF00FF00u;
    return src + rb + ag;
}

// Blends the premultiplied pixel src over *dst, skipping the arithmetic when src is transparent or
// opaque.
inline void blendInto(std::uint32_t* dst, std::uint32_t src) {
    std::uint32_t a = src >> 24;
    if (a == 255)
        *dst = src;
    else if (a != 0)
        *dst = blendOver(*dst, src);
}

// Multiplies premultiplied src by per-channel factors (each in [0, 255], 255 = unchanged).
inline std::uint32_t modulate(std::uint32_t src, std::uint32_t fa, std::uint32_t fr, std::uint32_t fg,
                              std::uint32_t fb) {
    return (mul255(src >> 24, fa) << 24) | (mul255((src >> 16) & 0xFF, fr) << 16) |
           (mul255((src >> 8) & 0xFF, fg) << 8) | mul255(src & 0xFF, fb);
}

}  // namespace polar::render::detail
