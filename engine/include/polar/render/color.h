#pragma once
#include <cstdint>

namespace polar::render {

// An 8-bit-per-channel colour with straight (not premultiplied) alpha; a = 255 is opaque.
//
// Why straight alpha here when the renderer blends premultiplied? This is the type people write
// (`{255, 128, 0, 64}` is "orange at a quarter"), and PNG files store straight alpha too. The
// renderer premultiplies once, where a colour or an image enters it, never per pixel.
struct Color {
    std::uint8_t r = 0;
    std::uint8_t g = 0;
    std::uint8_t b = 0;
    std::uint8_t a = 255;

    // The packed ARGB8888 value 0xAARRGGBB, the layout of a Canvas pixel.
    constexpr std::uint32_t argb() const {
        return (std::uint32_t{a} << 24) | (std::uint32_t{r} << 16) | (std::uint32_t{g} << 8) | b;
    }
    // The colour of a packed 0xAARRGGBB value.
    static constexpr Color fromArgb(std::uint32_t v) {
        return {std::uint8_t(v >> 16), std::uint8_t(v >> 8), std::uint8_t(v), std::uint8_t(v >> 24)};
    }
    // The same colour with alpha a.
    constexpr Color withAlpha(std::uint8_t alpha) const { return {r, g, b, alpha}; }

    friend constexpr bool operator==(const Color&, const Color&) = default;
};

inline constexpr Color kBlack{0, 0, 0, 255};
inline constexpr Color kWhite{255, 255, 255, 255};
inline constexpr Color kRed{230, 41, 55, 255};
inline constexpr Color kGreen{0, 200, 80, 255};
inline constexpr Color kBlue{0, 121, 241, 255};
inline constexpr Color kYellow{253, 249, 0, 255};
inline constexpr Color kOrange{255, 161, 0, 255};
inline constexpr Color kGray{130, 130, 130, 255};
inline constexpr Color kTransparent{0, 0, 0, 0};

}  // namespace polar::render
