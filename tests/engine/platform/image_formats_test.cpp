// loadRgbaImage on every format the platform reads: one sprite of known pixels (opaque,
// transparent and half-transparent quarters), saved in each format by tests/data/images/
// make_images.py, decoded and compared pixel by pixel with the rule for its format; and broken
// files (cut off, wrong signatures, huge declared sizes), each refused in one line, printing nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

#include "platform/image_decoders.h"
#include "platform/image_format.h"
#include "polar/platform/image_file.h"
#include "polar/platform/png_io.h"
#include "polar/render/image.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

const std::string kImageDir = std::string(POLAR_TEST_DATA) + "/images/";

// How a format's pixels relate to the sprite's (make_images.py writes each file by its rule).
enum class Rule {
    exact,               // alpha kept: every pixel as in sprite.png
    premultipliedExact,  // alpha kept, colours premultiplied on the way (TIFF, SVG, XCF): equal premultiplied
    keyed,   // a colour key: transparent where the sprite is, every other pixel opaque, colours kept
    opaque,  // no alpha: every pixel opaque, colours kept (the transparent quarter is black)
    near,    // no alpha, lossy (JPEG at quality 100, no chroma subsampling): opaque, colours within 6
};

std::uint32_t applyRule(std::uint32_t pixel, Rule rule) {
    const std::uint32_t alpha = pixel >> 24;
    switch (rule) {
        case Rule::exact:
        case Rule::premultipliedExact:
            return pixel;
        case Rule::keyed:
            return alpha == 0 ? pixel : pixel | 0xff000000u;
        case Rule::opaque:
        case Rule::near:
            return pixel | 0xff000000u;
    }
    return pixel;
}

int channelDifference(std::uint32_t a, std::uint32_t b) {
    int worst = 0;
    for (int shift = 0; shift < 32; shift += 8)
        worst = std::max(worst, std::abs(int((a >> shift) & 0xff) - int((b >> shift) & 0xff)));
    return worst;
}

struct FormatCase {
    const char* file;
    ImageFormat format;
    Rule rule;
};

class ImageFormats : public ::testing::TestWithParam<FormatCase> {};

TEST_P(ImageFormats, DecodesTheSpriteByItsFormatsRule) {
    const FormatCase& c = GetParam();
    Result<RgbaImage> truth = loadPng(kImageDir + "sprite.png");
    ASSERT_TRUE(truth.ok()) << truth.error().message();
    const std::string path = kImageDir + c.file;
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(imageFormatOf(bytes), c.format) << c.file;
    ::testing::internal::CaptureStderr();
    Result<RgbaImage> image = loadRgbaImage(path);
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width, 16);
    ASSERT_EQ(image->height, 16);
    for (int y = 0; y < 16; ++y)
        for (int x = 0; x < 16; ++x) {
            const std::uint32_t want = applyRule(truth->at(x, y), c.rule);
            const std::uint32_t got = image->at(x, y);
            if ((want >> 24) == 0 && (got >> 24) == 0) continue;  // a transparent pixel has no colour
            if (c.rule == Rule::premultipliedExact)
                EXPECT_EQ(render::premultiply(render::Color::fromArgb(got)),
                          render::premultiply(render::Color::fromArgb(want)))
                    << c.file << " at " << x << "," << y;
            else if (c.rule == Rule::near)
                EXPECT_LE(channelDifference(got, want), 6) << c.file << " at " << x << "," << y;
            else
                EXPECT_EQ(got, want) << c.file << " at " << x << "," << y << std::hex << ": want " << want
                                     << ", got " << got;
        }
}

INSTANTIATE_TEST_SUITE_P(
    EveryFormat, ImageFormats,
    ::testing::Values(FormatCase{"sprite.png", ImageFormat::png, Rule::exact},
                      FormatCase{"sprite.tga", ImageFormat::tga, Rule::exact},
                      FormatCase{"sprite-rle.tga", ImageFormat::tga, Rule::exact},
                      FormatCase{"sprite.tif", ImageFormat::tiff, Rule::premultipliedExact},
                      FormatCase{"sprite.webp", ImageFormat::webp, Rule::exact},
                      FormatCase{"sprite.qoi", ImageFormat::qoi, Rule::exact},
                      FormatCase{"sprite.xcf", ImageFormat::xcf, Rule::premultipliedExact},
                      FormatCase{"sprite-32.bmp", ImageFormat::bmp, Rule::exact},
                      FormatCase{"sprite.svg", ImageFormat::svg, Rule::premultipliedExact},
                      FormatCase{"sprite.bmp", ImageFormat::bmp, Rule::opaque},
                      FormatCase{"sprite.pcx", ImageFormat::pcx, Rule::opaque},
                      FormatCase{"sprite.ppm", ImageFormat::pnm, Rule::opaque},
                      FormatCase{"sprite.jpg", ImageFormat::jpeg, Rule::near},
                      FormatCase{"sprite.gif", ImageFormat::gif, Rule::keyed},
                      FormatCase{"sprite.xpm", ImageFormat::xpm, Rule::keyed},
                      FormatCase{"gif-named.png", ImageFormat::gif, Rule::keyed}),
    [](const ::testing::TestParamInfo<FormatCase>& info) {
        std::string name = info.param.file;
        for (char& ch : name)
            if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
        return name;
    });

// The premultiplied Image the game draws is the same for every exact format, TIFF included
// (libtiff's premultiplied colours are divided back, and premultiply to the same values again).
TEST(ImageFormatsPremultiplied, EveryExactFormatGivesThePngsImage) {
    Result<render::Image> truth = render::loadImage(kImageDir + "sprite.png");
    ASSERT_TRUE(truth.ok()) << truth.error().message();
    for (const char* file :
         {"sprite.tga", "sprite.tif", "sprite.webp", "sprite.qoi", "sprite-32.bmp", "sprite.xcf"}) {
        Result<render::Image> image = render::loadImage(kImageDir + file);
        ASSERT_TRUE(image.ok()) << image.error().message();
        ASSERT_EQ(image->width(), truth->width());
        ASSERT_EQ(image->height(), truth->height());
        const std::size_t count = std::size_t(truth->width()) * truth->height();
        for (std::size_t i = 0; i < count; ++i)
            ASSERT_EQ(image->premultiplied()[i], truth->premultiplied()[i]) << file << " at pixel " << i;
    }
}

// An XCF (version 0, uncompressed) of one visible RGBA layer at 0,0 holding `argb`, row by row.
std::string xcfOf(int width, int height, const std::vector<std::uint32_t>& argb) {
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    auto prop = [&](std::uint32_t id, const std::string& data) {
        return be32(id) + be32(data.size()) + data;
    };
    std::string file = std::string("gimp xcf file\0", 14) + be32(width) + be32(height) + be32(0) +
                       prop(17, std::string(1, '\0')) + prop(0, "");
    const std::size_t layer = file.size() + 12;  // after the layer list and the (empty) channel list
    file += be32(layer) + be32(0) + be32(0);
    file += be32(width) + be32(height) + be32(1) + be32(2) + std::string("L\0", 2) + prop(8, be32(1)) +
            prop(15, be32(0) + be32(0)) + prop(0, "");
    file += be32(file.size() + 8) + be32(0);  // the hierarchy, just after; no mask
    file += be32(width) + be32(height) + be32(4) + be32(file.size() + 20) + be32(0);
    const int across = (width + 63) / 64, down = (height + 63) / 64;
    file += be32(width) + be32(height);
    std::size_t tile = file.size() + 4 * (across * down + 1);
    std::string tiles;
    for (int ty = 0; ty < down; ++ty)
        for (int tx = 0; tx < across; ++tx) {
            file += be32(tile);
            for (int y = ty * 64; y < std::min(height, ty * 64 + 64); ++y)
                for (int x = tx * 64; x < std::min(width, tx * 64 + 64); ++x) {
                    const std::uint32_t p = argb[std::size_t(y) * width + x];
                    tiles += {char(p >> 16), char(p >> 8), char(p), char(p >> 24)};  // R, G, B, A
                    tile += 4;
                }
        }
    return file + be32(0) + tiles;
}

// SDL2_image blends an XCF's layers onto a transparent image, which premultiplies its translucent
// pixels by SDL's rounding; the decoder undoes it. Every grey at every alpha: once premultiplied,
// within 1 of what was saved, the alpha exact (but alpha 1, which SDL's blend may take to 0).
TEST(ImageFormatsXcf, EveryColourAtEveryAlphaComesBackWithinOneOncePremultiplied) {
    std::vector<std::uint32_t> saved;
    for (std::uint32_t a = 0; a < 256; ++a)
        for (std::uint32_t c = 0; c < 256; ++c) saved.push_back(a << 24 | c * 0x010101u);
    Result<RgbaImage> image = decodeImageBytes("every-alpha.xcf", xcfOf(256, 256, saved));
    ASSERT_TRUE(image.ok()) << image.error().message();
    ASSERT_EQ(image->width, 256);
    ASSERT_EQ(image->height, 256);
    int exact = 0, translucent = 0, worst = 0;
    for (std::size_t i = 0; i < saved.size(); ++i) {
        const std::uint32_t a = saved[i] >> 24, got = image->pixels[i];
        if (a <= 1) {
            EXPECT_LE(got >> 24, a) << "at " << i;
            continue;
        }
        const std::uint32_t want = render::premultiply(render::Color::fromArgb(saved[i]));
        const std::uint32_t back = render::premultiply(render::Color::fromArgb(got));
        ASSERT_EQ(back >> 24, a) << "at " << i;
        const int difference = channelDifference(back, want);
        worst = std::max(worst, difference);
        exact += difference == 0 && a < 255;
        translucent += a < 255;
    }
    EXPECT_LE(worst, 1);
    std::printf("XCF: %d of %d translucent pixels exact once premultiplied, the rest within %d\n", exact,
                translucent, worst);
}

class BrokenImages : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() / ("polar-broken-images-" + std::to_string(::getpid()));
        fs::remove_all(folder_);
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }

    static std::string fileBytes(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    }
    std::string write(const std::string& name, const std::string& bytes) const {
        const std::string path = (folder_ / name).string();
        std::ofstream(path, std::ios::binary) << bytes;
        return path;
    }
    // Loads `path`, which must be refused in one line naming it, containing `what`, with nothing
    // printed and in well under a second.
    static void expectRefused(const std::string& path, const std::string& what) {
        ::testing::internal::CaptureStderr();
        const auto start = std::chrono::steady_clock::now();
        Result<RgbaImage> image = loadRgbaImage(path);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << path;
        ASSERT_FALSE(image.ok()) << path << " loaded";
        const std::string message = image.error().message();
        EXPECT_EQ(message.rfind(path + ": ", 0), 0u) << message;
        EXPECT_NE(message.find(what), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_LT(seconds, 2.0) << path;
    }

    fs::path folder_;
};

TEST_F(BrokenImages, CutOffFilesAreRefusedInOneLine) {
    // Each format's sprite cut at its header and at half its length. (A cut PNM, PCX, BMP or TGA may
    // still decode, its missing rows as SDL2_image fills them; those cuts are only required not to
    // crash or print.)
    for (const char* file :
         {"sprite.tga", "sprite.tif", "sprite.webp", "sprite.qoi", "sprite-32.bmp", "sprite.bmp",
          "sprite.pcx", "sprite.ppm", "sprite.jpg", "sprite.gif", "sprite.xpm", "sprite.svg", "sprite.xcf"}) {
        const std::string bytes = fileBytes(kImageDir + file);
        const std::string header = write(std::string("header-") + file, bytes.substr(0, 12));
        expectRefused(header, "cannot decode");
        const std::string half = write(std::string("half-") + file, bytes.substr(0, bytes.size() / 2));
        ::testing::internal::CaptureStderr();
        Result<RgbaImage> image = loadRgbaImage(half);
        EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << half;
        if (!image.ok()) {
            EXPECT_EQ(image.error().message().find('\n'), std::string::npos);
        }
    }
    for (const char* file : {"sprite.tif", "sprite.webp", "sprite.jpg", "sprite.gif"}) {
        const std::string bytes = fileBytes(kImageDir + file);
        expectRefused(write(std::string("half-") + file, bytes.substr(0, bytes.size() / 2)),
                      "cannot decode the");
    }
}

TEST_F(BrokenImages, WrongSignaturesAreRefusedInOneLine) {
    const std::string garbage(300, '\x5a');
    expectRefused(write("gif.png", "GIF89a" + garbage), "cannot decode the GIF image (SDL_image: ");
    expectRefused(write("jpeg.bmp", "\xff\xd8\xff" + garbage), "cannot decode the JPEG image (SDL_image: ");
    expectRefused(write("tiff.gif", std::string("II*\0", 4) + garbage),
                  "cannot decode the TIFF image (SDL_image: ");
    expectRefused(write("webp.png", std::string("RIFF\x10\0\0\0WEBP", 12) + garbage),
                  "cannot decode the WebP image");
    expectRefused(write("text.tga", "this is not an image\n"),
                  "cannot decode the image: its first bytes are those of no image format read here");
    expectRefused(write("avif.png", std::string("\0\0\0\x1c"
                                                "ftypavif",
                                                12) +
                                        garbage),
                  "it is a AVIF image, which is not read here");
    expectRefused(write("empty.gif", ""), "the file is empty");
    // A pixel of a colour the table does not define, which SDL2_image 2.6's XPM reader crashes on
    // (the fuzzer's find, tests/fuzz/corpus/image/xpm-unknown-colour), and a pixel row one short.
    expectRefused(write("unknown-colour.xpm",
                        fileBytes(std::string(POLAR_TEST_DATA) + "/../fuzz/corpus/image/xpm-unknown-colour")),
                  "cannot decode the XPM image: pixel row 13 uses a colour its table does not define");
    std::string xpm = fileBytes(kImageDir + "sprite.xpm");
    const std::size_t row = xpm.rfind("\"........XXXXXXXX\"");
    ASSERT_NE(row, std::string::npos);
    xpm.erase(row + 1, 1);
    expectRefused(write("short-row.xpm", xpm), "cannot decode the XPM image: pixel row 16 has 15 characters");
}

// SDL2_image 2.6's XPM reader knows no comments: a '"' inside one starts a string, and what it then
// takes for pixel rows holds characters its colour table does not define, which it crashes on
// (the fuzzer's find, tests/fuzz/corpus/image/xpm-quote-in-comment). The check reads the strings
// as it does; a row is the W·CPP characters after its '"', then 3 more are skipped.
TEST_F(BrokenImages, XpmStringsAreReadAsSdlImageReadsThem) {
    const std::string corpus = std::string(POLAR_TEST_DATA) + "/../fuzz/corpus/image/";
    expectRefused(write("quote-in-comment.xpm", fileBytes(corpus + "xpm-quote-in-comment")),
                  "cannot decode the XPM image: pixel row 1 has 2 characters where its header says 16");
    const std::string xpm = fileBytes(kImageDir + "sprite.xpm");
    const std::size_t pixels = xpm.find("/* pixels */");
    ASSERT_NE(pixels, std::string::npos);
    std::string quoted = xpm;
    quoted.replace(pixels, 12, "/* \"pixels\" */");
    expectRefused(write("quoted-comment.xpm", quoted),
                  "cannot decode the XPM image: pixel row 1 has 6 characters where its header says 16");
    std::string joined = xpm;  // two rows in one line: the reader skips the second's opening '"'
    const std::size_t row = joined.rfind("\",\n\"");
    ASSERT_NE(row, std::string::npos);
    joined.erase(row + 1, 2);
    expectRefused(write("joined-rows.xpm", joined), "cannot decode the XPM image: pixel row 16 ");
    std::string shortColour = xpm;  // a colour line of its key alone
    const std::size_t colour = shortColour.find("\"X c ");
    ASSERT_NE(colour, std::string::npos);
    shortColour.replace(colour + 2, shortColour.find('"', colour + 1) - colour - 2, "");
    expectRefused(write("short-colour.xpm", shortColour),
                  "cannot decode the XPM image: colour line 3 has no colour after its key");
    std::string cut = xpm.substr(0, xpm.rfind('"') + 1);  // ends at the last row's closing '"'
    expectRefused(write("cut-after-row.xpm", cut),
                  "cannot decode the XPM image: it ends right after pixel row 16");
}

// SDL2_image 2.6's GIF reader walks LZW prefixes onto a fixed stack without a bound; codes that
// link its table in a loop make it write past the stack (the fuzzer's find,
// tests/fuzz/corpus/image/gif-lzw-loop: an invalid free). The image is decoded as it decodes it
// first; every committed GIF still loads.
TEST_F(BrokenImages, GifLzwLoopsAreRefused) {
    const std::string corpus = std::string(POLAR_TEST_DATA) + "/../fuzz/corpus/image/";
    expectRefused(write("lzw-loop.gif", fileBytes(corpus + "gif-lzw-loop")),
                  "cannot decode the GIF image: its LZW codes loop back on themselves");
    for (const char* file : {"sprite.gif", "gif-named.png"}) {
        Result<RgbaImage> image = loadRgbaImage(kImageDir + file);
        EXPECT_TRUE(image.ok()) << image.error().message();
    }
}

// SDL2_image logs some XCF faults (an unknown depth) to stderr and returns a blank image: the
// message is kept, and the file refused with it.
TEST_F(BrokenImages, XcfFaultsSdlImageLogsAreRefusedWithItsMessage) {
    std::string xcf = fileBytes(kImageDir + "sprite.xcf");
    const std::size_t hierarchy = xcf.find(std::string("\0\0\0\x10\0\0\0\x10\0\0\0\x04", 12));
    ASSERT_NE(hierarchy, std::string::npos);
    xcf[hierarchy + 11] = '\x09';  // 9 bytes a pixel
    expectRefused(write("depth-9.xcf", xcf),
                  "cannot decode the GIMP XCF image (SDL_image: Unknown Gimp image bpp (9));");
}

// SDL2_image 2.6's XCF reader allocates what the file's numbers say: a tile the distance to the
// next one's offset (the fuzzer's find, tests/fuzz/corpus/image/xcf-tile-past-end: 2.5 GB), a
// name whose length is negative as an int (xcf-negative-name-length: 3.8 GB), a colour map of up
// to 2³² entries; frees an emptied colour map twice; and reads an indexed image's colour map
// through NULL when there is none (it crashes). The check follows the file as it does.
TEST_F(BrokenImages, XcfStructureIsFollowedAsSdlImageFollowsIt) {
    const std::string corpus = std::string(POLAR_TEST_DATA) + "/../fuzz/corpus/image/";
    expectRefused(write("tile-past-end.xcf", fileBytes(corpus + "xcf-tile-past-end")),
                  "cannot decode the GIMP XCF image: tile 1 of a layer would be ");
    expectRefused(write("negative-name-length.xcf", fileBytes(corpus + "xcf-negative-name-length")),
                  "name of 3838464055 bytes runs past the file's end");
    const std::string xcf = fileBytes(kImageDir + "sprite.xcf");
    auto be32 = [](std::uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    expectRefused(
        write("huge-colour-map.xcf",
              xcf.substr(0, 26) + be32(1) + be32(4) + be32(0xfffffff0) + xcf.substr(26)),
        "cannot decode the GIMP XCF image: its colour map of 4294967280 entries runs past the file's end");
    // A map of 80 entries, then one of none: the reader reallocs the first to 0 bytes, which frees
    // it, and frees it again (xcf-empty-colour-map: a double free).
    expectRefused(write("empty-colour-map.xcf", fileBytes(corpus + "xcf-empty-colour-map")),
                  "cannot decode the GIMP XCF image: it has a colour map of no entries");
    std::string indexed = xcf;
    indexed.replace(22, 4, be32(2));  // an indexed image, its layer one byte a pixel, no colour map
    const std::size_t hierarchy = indexed.find(be32(16) + be32(16) + be32(4));
    ASSERT_NE(hierarchy, std::string::npos);
    indexed[hierarchy + 11] = '\x01';
    expectRefused(write("indexed-without-map.xcf", indexed),
                  "cannot decode the GIMP XCF image: it is an indexed image without a colour map");
    // A layer without PROP_OFFSETS or PROP_VISIBLE is placed and shown by uninitialised memory
    // (xcf-layer-without-offsets: a read far out of bounds in SDL's blit).
    expectRefused(write("layer-without-offsets.xcf", fileBytes(corpus + "xcf-layer-without-offsets")),
                  "cannot decode the GIMP XCF image: a layer has no PROP_OFFSETS");
    std::string hidden = xcf;
    const std::size_t visible = hidden.find(be32(8) + be32(4) + be32(1));
    ASSERT_NE(visible, std::string::npos);
    hidden.replace(visible, 4, be32(9));  // PROP_LINKED in its place
    expectRefused(write("layer-without-visible.xcf", hidden),
                  "cannot decode the GIMP XCF image: a layer has no PROP_VISIBLE");
}

TEST_F(BrokenImages, HugeDeclaredSizesAreRefusedBeforeDecoding) {
    auto little16 = [](unsigned v) { return std::string{char(v & 0xff), char(v >> 8)}; };
    auto little32 = [&](unsigned v) { return little16(v & 0xffff) + little16(v >> 16); };
    auto big32 = [](unsigned v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
    const std::string pixels(64, '\0');
    // 40000 pixels a side, each in its header's own field.
    expectRefused(
        write("huge.bmp", "BM" + little32(0) + little32(0) + little32(54) + little32(40) + little32(40000) +
                              little32(40000) + little16(1) + little16(24) + pixels),
        "image is 40000×40000 pixels; expected at most 32767 pixels a side");
    expectRefused(write("huge.gif", "GIF89a" + little16(40000) + little16(3) + pixels),
                  "image is 40000×3 pixels");
    // SDL2_image allocates a GIF's first image at its own size, not the screen's (the fuzzer's
    // find, tests/fuzz/corpus/image/gif-image-larger-than-screen: 8291×28494, 945 MB, which the
    // fuzzer skips once it is known): skipped bytes, an extension and an image given up (code size
    // 13) before it.
    expectRefused(
        write("huge-image.gif", "GIF89a" + little16(16) + little16(16) + std::string(3, '\0') + "xy!" +
                                    std::string("\xf9\x04\0\0\0\0\0", 7) + "," + little16(0) + little16(0) +
                                    little16(9) + little16(9) + std::string(1, '\0') + "\x0d," + little16(0) +
                                    little16(0) + little16(40000) + little16(300) + std::string(1, '\0') +
                                    "\x08" + pixels),
        "image is 40000×300 pixels");
    const std::string larger =
        fileBytes(std::string(POLAR_TEST_DATA) + "/../fuzz/corpus/image/gif-image-larger-than-screen");
    const std::optional<DeclaredSize> frame = declaredSize(ImageFormat::gif, larger);
    ASSERT_TRUE(frame.has_value());
    EXPECT_EQ(frame->width, 8291);  // its screen says 2586×48
    EXPECT_EQ(frame->height, 28494);
    expectRefused(
        write("huge.qoi", "qoif" + big32(40000) + big32(40000) + "\x04" + std::string(1, '\0') + pixels),
        "image is 40000×40000 pixels");
    expectRefused(write("huge.ppm", "P6\n# big\n40000 40000\n255\n" + pixels), "image is 40000×40000 pixels");
    // Any one byte ends a number, as SDL2_image reads them (the fuzzer's find: tests/fuzz/corpus/image/
    // pnm-letter-after-width); an XV thumbnail's sides follow its #END_OF_COMMENTS line.
    // Read from the header before any decoder allocates (a decoder's too-large image says the same).
    const std::string letter = "P6\n77777777R7w7HID/\n" + pixels;
    const std::string xv = "P7 332\n#XVVERSION:Version 2.28\n#END_OF_COMMENTS\n40000 3 255\n" + pixels;
    for (const auto& [bytes, width, height] : {std::tuple{letter, 77777777, 7}, std::tuple{xv, 40000, 3}}) {
        const std::optional<DeclaredSize> size = declaredSize(imageFormatOf(bytes), bytes);
        ASSERT_TRUE(size.has_value()) << bytes.substr(0, 20);
        EXPECT_EQ(size->width, width);
        EXPECT_EQ(size->height, height);
    }
    expectRefused(write("letter.ppm", letter), "image is 77777777×7 pixels");
    expectRefused(write("huge.xv", xv), "image is 40000×3 pixels");
    expectRefused(write("huge.tga", std::string("\0\0\x02", 3) + std::string(9, '\0') + little16(40000) +
                                        little16(40000) + "\x20\x28" + pixels),
                  "image is 40000×40000 pixels");
    expectRefused(
        write("huge.jpg", std::string("\xff\xd8\xff\xc0\0\x11\x08", 7) + "\x9c\x40\x9c\x40" + pixels),
        "image is 40000×40000 pixels");
    expectRefused(write("huge.webp", "RIFF" + little32(100) + "WEBPVP8X" + little32(10) + little32(0) +
                                         std::string("\x3f\x9c\0\x3f\x9c\0", 6) + pixels),
                  "image is 40000×40000 pixels");
    expectRefused(write("huge.svg",
                        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"40000\" height=\"10\">\n"
                        "<rect width=\"1\" height=\"1\"/></svg>\n"),
                  "image is 40000×10 pixels");
    expectRefused(write("huge-inches.svg", "<svg viewBox=\"0 0 10 10\" width=\"400in\">\n</svg>\n"),
                  "image is 38400×10 pixels");
    expectRefused(write("huge.tif", std::string("II*\0", 4) + little32(8) + little16(2) + little16(256) +
                                        little16(4) + little32(1) + little32(40000) + little16(257) +
                                        little16(4) + little32(1) + little32(40000) + little32(0) + pixels),
                  "image is 40000×40000 pixels");
}

}  // namespace
}  // namespace polar
