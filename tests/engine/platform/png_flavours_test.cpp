// loadPng against the PNG specification: the committed set in tests/data/png/ (written by
// make_pngs.py there) holds one 11×7 image for every colour type and bit depth, plain and Adam7,
// each with transparent pixels. The expected pixels are computed here from the rules the images
// were made by, and the decoding rules of the specification, not read from another decoder.
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "polar/platform/png_io.h"

namespace polar {
namespace {

const std::string kPngDir = std::string(POLAR_TEST_DATA) + "/png/";

constexpr int kWidth = 11;
constexpr int kHeight = 7;
constexpr int kP[4] = {4099, 9973, 30011, 1237};
constexpr int kQ[4] = {0, 7, 13, 3};

enum class ColourType { grey = 0, rgb = 2, palette = 3, greyAlpha = 4, rgba = 6 };

struct Flavour {
    ColourType type;
    int depth;
    bool interlaced;
};

std::string fileName(const Flavour& f) {
    const char* names[] = {"grey", "", "rgb", "palette", "grey-alpha", "", "rgba"};
    return std::string(names[int(f.type)]) + "-" + std::to_string(f.depth) + (f.interlaced ? "-adam7" : "") +
           ".png";
}

bool onBorder(int x, int y) {
    return x == 0 || y == 0 || x == kWidth - 1 || y == kHeight - 1;
}

// The stored sample of channel c (R, G, B, A; grey is 0) at (x, y): (i·P[c] + Q[c]) mod (2ⁿ − 1),
// with i = 11·y + x, so never the largest value 2ⁿ − 1 (white, the tRNS colour).
int storedSample(int x, int y, int c, int depth) {
    const int i = y * kWidth + x;
    return (i * kP[c] + kQ[c]) % ((1 << depth) - 1);
}

// An n-bit sample as 8 bits, as the specification rescales: round(v·255 / (2ⁿ − 1)). Below 16 bits
// the division is exact (255 is a multiple of 1, 3, 15 and 255); at 16 bits there are no ties,
// since 510·v is even and 65535·(2k + 1) is odd.
int to8(int v, int depth) {
    const int top = (1 << depth) - 1;
    return (v * 255 + top / 2) / top;
}

int paletteEntries(int depth) {
    return depth == 8 ? 181 : 1 << depth;
}

std::uint32_t argb(int r, int g, int b, int a) {
    return std::uint32_t(a) << 24 | std::uint32_t(r) << 16 | std::uint32_t(g) << 8 | std::uint32_t(b);
}

// What pixel (x, y) of a flavour must decode to, as straight-alpha ARGB.
std::uint32_t expectedPixel(const Flavour& f, int x, int y) {
    if (f.type == ColourType::palette) {
        const int index = onBorder(x, y) ? 0 : 1 + (y * kWidth + x) * kP[0] % (paletteEntries(f.depth) - 1);
        // tRNS: entry 0 alpha 0, entry 1 alpha 128 (from 2 bits up); the entries after it are opaque.
        const int alpha = index == 0 ? 0 : (index == 1 && f.depth >= 2) ? 128 : 255;
        return argb((index * 53 + 11) % 256, (index * 101 + 23) % 256, (index * 197 + 5) % 256, alpha);
    }
    const int colours = (f.type == ColourType::grey || f.type == ColourType::greyAlpha) ? 1 : 3;
    const bool keyed = f.type == ColourType::grey || f.type == ColourType::rgb;
    const int white = (1 << f.depth) - 1;
    int v[3] = {};
    for (int c = 0; c < colours; ++c) v[c] = keyed && onBorder(x, y) ? white : storedSample(x, y, c, f.depth);
    if (f.depth == 16 && x == 1 && y == 1)  // off the tRNS colour (white) in the low byte only
        for (int c = 0; c < colours; ++c) v[c] = c == colours - 1 ? 0xFFFE : 0xFFFF;
    if (f.depth == 16 && x == 2 && y == 1)  // 511/257 = 1.99: rounds to 2, its high byte is 1
        for (int c = 0; c < colours; ++c) v[c] = 0x01FF;
    int alpha = 255;
    if (keyed) {
        // tRNS names white: that colour, compared at full depth, is transparent.
        bool isKey = true;
        for (int c = 0; c < colours; ++c) isKey = isKey && v[c] == white;
        if (isKey) alpha = 0;
    } else {
        alpha = onBorder(x, y) ? 0 : to8(storedSample(x, y, 3, f.depth), f.depth);
    }
    if (colours == 1) {
        const int g = to8(v[0], f.depth);
        return argb(g, g, g, alpha);
    }
    return argb(to8(v[0], f.depth), to8(v[1], f.depth), to8(v[2], f.depth), alpha);
}

std::vector<Flavour> allFlavours() {
    std::vector<Flavour> all;
    const std::pair<ColourType, std::vector<int>> allowed[] = {
        {ColourType::grey, {1, 2, 4, 8, 16}}, {ColourType::rgb, {8, 16}},
        {ColourType::palette, {1, 2, 4, 8}},  {ColourType::greyAlpha, {8, 16}},
        {ColourType::rgba, {8, 16}},
    };
    for (const auto& [type, depths] : allowed)
        for (int depth : depths)
            for (bool interlaced : {false, true}) all.push_back({type, depth, interlaced});
    return all;
}

class PngFlavour : public ::testing::TestWithParam<Flavour> {};

TEST_P(PngFlavour, DecodesAsTheSpecificationSays) {
    const Flavour f = GetParam();
    const std::string path = kPngDir + fileName(f);
    ::testing::internal::CaptureStderr();
    Result<RgbaImage> image = loadPng(path);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width, kWidth);
    ASSERT_EQ(image->height, kHeight);
    int transparent = 0;
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            const std::uint32_t expected = expectedPixel(f, x, y);
            EXPECT_EQ(image->pixels[std::size_t(y) * kWidth + x], expected)
                << fileName(f) << " at (" << x << ", " << y << "): got " << std::hex
                << image->pixels[std::size_t(y) * kWidth + x] << ", expected " << expected;
            transparent += (expected >> 24) == 0;
        }
    // The border is transparent; with tRNS nothing else is (an alpha channel at 16 bits may round an
    // interior alpha under 129/65535 to 0 too).
    const int border = 2 * kWidth + 2 * kHeight - 4;
    if (f.type == ColourType::greyAlpha || f.type == ColourType::rgba)
        EXPECT_GE(transparent, border);
    else
        EXPECT_EQ(transparent, border);
}

INSTANTIATE_TEST_SUITE_P(EveryColourTypeAndBitDepth, PngFlavour, ::testing::ValuesIn(allFlavours()),
                         [](const ::testing::TestParamInfo<Flavour>& info) {
                             std::string name = fileName(info.param);
                             name = name.substr(0, name.size() - 4);
                             for (char& c : name)
                                 if (c == '-') c = '_';
                             return name;
                         });

TEST(PngFlavours, SixteenBitSamplesRoundToNearest) {
    EXPECT_EQ(to8(0x01FF, 16), 2);       // round(1.988); the high byte would be 1
    EXPECT_EQ(to8(0x0080, 16), 0);       // round(0.498)
    EXPECT_EQ(to8(0x0081, 16), 1);       // round(0.502)
    EXPECT_EQ(to8(257 * 200, 16), 200);  // 8-bit values widened by 257 come back exact
    Result<RgbaImage> image = loadPng(kPngDir + "grey-16.png");
    ASSERT_TRUE(image.ok()) << image.error().message();
    EXPECT_EQ(image->pixels[1 * kWidth + 2], argb(2, 2, 2, 255));
    EXPECT_EQ(image->pixels[1 * kWidth + 1], argb(255, 255, 255, 255));  // 0xFFFE: not the tRNS colour
}

TEST(PngFlavours, GreyWithTrnsLoadsLikeTheSameSpriteWithAlpha) {
    Result<RgbaImage> grey = loadPng(kPngDir + "sprite-grey-trns.png");
    Result<RgbaImage> rgba = loadPng(kPngDir + "sprite-rgba.png");
    ASSERT_TRUE(grey.ok()) << grey.error().message();
    ASSERT_TRUE(rgba.ok()) << rgba.error().message();
    ASSERT_EQ(grey->width, 24);
    ASSERT_EQ(grey->height, 24);
    int opaque = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            // A disc of radius 8 about (12, 12), by pixel centres, grey 60; the white around it is tRNS.
            const double dx = x + 0.5 - 12, dy = y + 0.5 - 12;
            const bool inDisc = dx * dx + dy * dy <= 64;
            opaque += inDisc;
            EXPECT_EQ(grey->pixels[std::size_t(y) * 24 + x],
                      inDisc ? argb(60, 60, 60, 255) : argb(255, 255, 255, 0))
                << x << ", " << y;
        }
    EXPECT_GT(opaque, 150);
    EXPECT_LT(opaque, 24 * 24 - 150);
    EXPECT_EQ(grey->pixels, rgba->pixels);
}

// A broken file is one Error naming it and what is wrong; libpng prints nothing.
TEST(PngFlavours, BrokenFilesAreOneErrorEachAndNothingOnStderr) {
    const std::pair<const char*, const char*> cases[] = {
        {"bad-crc.png",
         "cannot decode the image: the IDAT chunk at byte 47 is damaged (its checksum differs); "
         "expected a valid PNG image"},
        {"bad-adler.png",
         "cannot decode the image: its compressed pixel data is damaged (incorrect data check); "
         "expected a valid PNG image"},
        {"bad-adler-split.png",
         "cannot decode the image: its compressed pixel data is damaged (incorrect data "
         "check); expected a valid PNG image"},
        {"truncated.png",
         "cannot decode the image: the file ends at byte 102, inside the IDAT chunk that starts "
         "at byte 47; expected a complete PNG image (was it cut off?)"},
        {"not-a-png.png", "cannot decode the image: it is a GIF image, not a PNG; expected a PNG image"},
        {"empty.png", "cannot decode the image: the file is empty; expected a PNG image"},
        {"too-wide.png", "image is 40000×1 pixels; expected at most 32767 pixels a side"},
    };
    for (const auto& [name, what] : cases) {
        const std::string path = kPngDir + "broken/" + name;
        ::testing::internal::CaptureStderr();
        Result<RgbaImage> image = loadPng(path);
        EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << name;
        ASSERT_FALSE(image.ok()) << name;
        EXPECT_EQ(image.error().file, path);
        EXPECT_EQ(image.error().message(), path + ": " + what);
    }
}

}  // namespace
}  // namespace polar
