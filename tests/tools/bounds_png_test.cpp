// polarcade-bounds gen on the PNG files a paint program may write (tests/data/png/): transparency
// from tRNS is honoured, and a broken file is one line on stderr, exit code 2, never a crash.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <utility>

#include "run_command.h"
#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

using Outcome = polar::testing::CommandOutcome;

class BoundsPng : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bounds-png"); }
    void TearDown() override { fs::remove_all(folder_); }

    // A copy of tests/data/png/NAME in the test's folder.
    void copyPng(const std::string& name, const std::string& as) const {
        fs::copy_file(std::string(POLAR_TEST_DATA) + "/png/" + name, folder_ / as);
    }
    Outcome run(const std::string& args) const {
        return polar::testing::runShell(polar::testing::shellQuote(POLAR_BOUNDS_EXE) + " " + args, folder_);
    }

    fs::path folder_;
};

// The sprite is a disc of radius 8 about the centre of a 24×24 image, grey 60, on white that tRNS
// makes transparent. Were the white opaque, the outline would be the square, its corners 17 px out.
TEST_F(BoundsPng, GenOnGreyWithTrnsFitsOnlyTheOpaquePixels) {
    copyPng("sprite-grey-trns.png", "grey.png");
    copyPng("sprite-rgba.png", "rgba.png");
    int discPixels = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 24; ++x) {
            const double dx = x + 0.5 - 12, dy = y + 0.5 - 12;
            discPixels += dx * dx + dy * dy <= 64;
        }
    Outcome grey = run("gen grey.png");
    ASSERT_EQ(grey.exitCode, 0) << grey.err;
    EXPECT_EQ(grey.err, "");
    EXPECT_NE(grey.out.find(", " + std::to_string(discPixels) + " opaque pixels;"), std::string::npos)
        << grey.out;
    Outcome rgba = run("gen rgba.png");
    ASSERT_EQ(rgba.exitCode, 0) << rgba.err;
    // The same outline as from the sprite with an alpha channel, sample for sample.
    const std::string greyBounds = polar::testing::readFile(folder_ / "grey.bounds.json");
    ASSERT_FALSE(greyBounds.empty());
    EXPECT_EQ(greyBounds, polar::testing::readFile(folder_ / "rgba.bounds.json"));
    // And every sample near the disc (radius 8; the polygon's corners stand a little outside it),
    // well inside the 12 px to the image's edges that an opaque background would give.
    std::size_t at = greyBounds.find("\"samples\"");
    ASSERT_NE(at, std::string::npos) << greyBounds;
    int samples = 0;
    while ((at = greyBounds.find('[', at + 1)) != std::string::npos) {
        double angle = 0, radius = 0;
        if (std::sscanf(greyBounds.c_str() + at, "[%lf, %lf]", &angle, &radius) != 2) continue;
        EXPECT_LT(radius, 10.0) << "sample at " << angle << " degrees";
        EXPECT_GT(radius, 7.0) << "sample at " << angle << " degrees";
        ++samples;
    }
    EXPECT_GE(samples, 8);
}

// The sprite of tests/data/images/ in every lossless format: the same bounds file, byte for byte,
// as from a PNG of the same pixels (the format's rule applied: keyed formats lose the half alpha,
// formats without alpha are opaque, TIFF, SVG and XCF are equal once premultiplied). At threshold
// 200 the half-transparent quarter is outside the PNG's bounds, and inside those of a keyed or
// opaque file.
TEST_F(BoundsPng, GenGivesThePngsBoundsForEveryLosslessFormat) {
    const std::string images = std::string(POLAR_TEST_DATA) + "/images/";
    auto bounds = [&](const std::string& file, const std::string& as) {
        fs::copy_file(images + file, folder_ / as);
        Outcome r = run("gen --threshold 200 " + as);  // the half-transparent quarter is outside
        EXPECT_EQ(r.exitCode, 0) << file << ": " << r.err;
        EXPECT_EQ(r.err, "") << file;
        return polar::testing::readFile(folder_ / (fs::path(as).stem().string() + ".bounds.json"));
    };
    const std::string png = bounds("sprite.png", "sprite.png");
    ASSERT_FALSE(png.empty());
    for (const char* file : {"sprite.tga", "sprite-rle.tga", "sprite.tif", "sprite.webp", "sprite.qoi",
                             "sprite-32.bmp", "sprite.svg", "sprite.xcf"})
        EXPECT_EQ(bounds(file, std::string("copy-") + file), png) << file;
    // Keyed: the half-transparent quarter is opaque in these; the same as a PNG of those pixels.
    const std::string gif = bounds("sprite.gif", "keyed.gif");
    EXPECT_NE(gif, png);
    EXPECT_EQ(bounds("sprite.xpm", "keyed.xpm"), gif);
    EXPECT_EQ(bounds("gif-named.png", "gif-named.png"), gif);
    // No alpha: the whole square, from each.
    const std::string bmp = bounds("sprite.bmp", "opaque.bmp");
    EXPECT_EQ(bounds("sprite.pcx", "opaque.pcx"), bmp);
    EXPECT_EQ(bounds("sprite.ppm", "opaque.ppm"), bmp);
}

// Each broken file: exit code 2, nothing on stdout, one line on stderr naming the file.
TEST_F(BoundsPng, GenOnABrokenPngPrintsOneLine) {
    const std::pair<const char*, const char*> cases[] = {
        {"bad-crc.png",
         "cannot decode the image: the IDAT chunk at byte 47 is damaged (its checksum differs)"},
        {"bad-adler.png",
         "cannot decode the image: its compressed pixel data is damaged (incorrect data check)"},
        {"bad-adler-split.png",
         "cannot decode the image: its compressed pixel data is damaged (incorrect data check)"},
        {"truncated.png", "cannot decode the image: the file ends at byte 102, inside the IDAT chunk"},
        // A cut-off GIF named .png: read as the GIF it is, SDL_image's reason after the file name.
        {"not-a-png.png", "cannot decode the GIF image (SDL_image: "},
        {"empty.png", "cannot decode the image: the file is empty"},
    };
    for (const auto& [name, what] : cases) {
        copyPng(std::string("broken/") + name, name);
        Outcome r = run(std::string("gen ") + name);
        EXPECT_EQ(r.exitCode, 2) << name << ": " << r.err;
        EXPECT_EQ(r.out, "") << name;
        EXPECT_EQ(r.err.rfind(std::string(name) + ": " + what, 0), 0u) << r.err;
        ASSERT_FALSE(r.err.empty());
        EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << name << " printed more than one line:\n" << r.err;
        EXPECT_FALSE(fs::exists(
            folder_ / (std::string(name).substr(0, std::string(name).size() - 4) + ".bounds.json")));
    }
}

}  // namespace
}  // namespace polar
