#include "polar/platform/image_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "golden.h"
#include "polar/platform/png_io.h"

namespace polar::render {
namespace {

namespace fs = std::filesystem;

// A fresh, empty folder for one test.
fs::path scratchFolder(const std::string& name) {
    fs::path dir =
        fs::temp_directory_path() / ("polar-render-test-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out << bytes;
}

TEST(ImageFile, SaveThenLoadIsExact) {
    const fs::path dir = scratchFolder("roundtrip");
    Canvas canvas(37, 23);
    testing::drawCheckerboard(canvas);
    canvas.setPixel(3, 4, Color{1, 2, 3, 255});
    const std::string path = (dir / "picture.png").string();
    ASSERT_FALSE(savePng(canvas, path));
    Result<Canvas> back = loadCanvas(path);
    ASSERT_TRUE(back.ok()) << back.error().message();
    ASSERT_EQ(back->width(), 37);
    ASSERT_EQ(back->height(), 23);
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x) ASSERT_EQ(back->row(y)[x], canvas.row(y)[x]);
    // Only the picture is left in the folder: no temporary file.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}

TEST(ImageFile, LoadImagePremultipliesTranslucentPixels) {
    const fs::path dir = scratchFolder("premultiply");
    Canvas canvas(2, 1);
    canvas.setPixel(0, 0, Color{200, 100, 50, 128});
    canvas.setPixel(1, 0, Color{200, 100, 50, 0});
    const std::string path = (dir / "translucent.png").string();
    ASSERT_FALSE(savePng(canvas, path));
    Result<Image> image = loadImage(path);
    ASSERT_TRUE(image.ok()) << image.error().message();
    // round(200·128/255) = 100, round(100·128/255) = 50, round(50·128/255) = 25
    EXPECT_EQ(image->premultiplied()[0], 0x80643219u);
    EXPECT_EQ(image->premultiplied()[1], 0u);
    // Back to straight alpha: round(100·255/128) = 199, round(50·255/128) = 100, round(25·255/128) = 50.
    EXPECT_EQ(image->pixel(0, 0), (Color{199, 100, 50, 128}));
    fs::remove_all(dir);
}

TEST(ImageFile, SaveReplacesAnExistingFileWhole) {
    const fs::path dir = scratchFolder("replace");
    const std::string path = (dir / "shot.png").string();
    writeBytes(path, "old contents");
    Canvas canvas(8, 8);
    canvas.clear(kRed);
    ASSERT_FALSE(savePng(canvas, path));
    Result<Canvas> back = loadCanvas(path);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->pixel(7, 7), kRed);
    fs::remove_all(dir);
}

TEST(ImageFile, SaveIntoAMissingFolderIsAnErrorNamingTheFile) {
    const fs::path dir = scratchFolder("missing");
    const std::string path = (dir / "no" / "such" / "folder" / "out.png").string();
    Canvas canvas(4, 4);
    auto error = savePng(canvas, path);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->file, path);
    EXPECT_NE(error->message().find("cannot"), std::string::npos) << error->message();
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 0);
    fs::remove_all(dir);
}

TEST(ImageFile, FailedRenameLeavesWhatWasThereAndNoTemporaryFile) {
    // The target is a folder holding a file: the PNG is written to the temporary file, the rename
    // over the folder fails, and the folder, its file and nothing else remain.
    const fs::path dir = scratchFolder("rename");
    const fs::path target = dir / "shot.png";
    fs::create_directories(target);
    writeBytes(target / "inside.txt", "precious");
    Canvas canvas(4, 4);
    auto error = savePng(canvas, target.string());
    ASSERT_TRUE(error);
    EXPECT_EQ(error->file, target.string());
    EXPECT_TRUE(fs::is_directory(target));
    std::ifstream in(target / "inside.txt");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(text, "precious");
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    fs::remove_all(dir);
}

TEST(ImageFile, MissingFileIsAnErrorNamingIt) {
    Result<Image> image = loadImage("/nonexistent/folder/ship.png");
    ASSERT_FALSE(image.ok());
    EXPECT_EQ(image.error().file, "/nonexistent/folder/ship.png");
    EXPECT_EQ(image.error().message(), "/nonexistent/folder/ship.png: no such file; expected an image file");
}

TEST(ImageFile, CorruptFilesAreErrorsNotCrashes) {
    const fs::path dir = scratchFolder("corrupt");
    // A real PNG cut short, a PNG signature followed by garbage, text, an empty file, 5 bytes that
    // start like a WebP file, and a PNG signature alone.
    Canvas canvas(16, 16);
    testing::drawCheckerboard(canvas);
    const std::string good = (dir / "good.png").string();
    ASSERT_FALSE(savePng(canvas, good));
    std::ifstream in(good, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    writeBytes(dir / "truncated.png", bytes.substr(0, bytes.size() / 2));
    writeBytes(dir / "garbage.png", std::string("\x89PNG\r\n\x1a\n", 8) + std::string(200, '\x5a'));
    writeBytes(dir / "text.png", "this is not an image\n");
    writeBytes(dir / "empty.png", "");
    writeBytes(dir / "riff.png", "RIFF\x10");                                // shorter than a WebP header
    writeBytes(dir / "signature.png", std::string("\x89PNG\r\n\x1a\n", 8));  // and nothing else
    for (const char* name :
         {"truncated.png", "garbage.png", "text.png", "empty.png", "riff.png", "signature.png"}) {
        const std::string path = (dir / name).string();
        Result<Image> image = loadImage(path);
        ASSERT_FALSE(image.ok()) << name;
        EXPECT_EQ(image.error().file, path);
        EXPECT_NE(image.error().message().find("cannot decode"), std::string::npos)
            << image.error().message();
    }
    Result<Image> folder = loadImage(dir.string());
    ASSERT_FALSE(folder.ok());
    EXPECT_NE(folder.error().message().find("not a regular file"), std::string::npos);
    fs::remove_all(dir);
}

TEST(PngIo, AnRgbaImageSavedIsTheImageLoaded) {
    const fs::path dir = scratchFolder("round-trip");
    const RgbaImage image{3, 2, {0xFF102030u, 0x80405060u, 0u, 0xFFFFFFFFu, 0x01020304u, 0xFF000000u}};
    const std::string path = (dir / "image.png").string();
    ASSERT_FALSE(savePng(image, path));
    Result<RgbaImage> back = loadPng(path);
    ASSERT_TRUE(back.ok()) << back.error().message();
    EXPECT_EQ(back->width, 3);
    EXPECT_EQ(back->height, 2);
    EXPECT_EQ(back->pixels, image.pixels);
    fs::remove_all(dir);
}

}  // namespace
}  // namespace polar::render
