// polarcade-bounds view as a modder runs it: the picture shows the outline where the collision rule
// puts it (both rules, under scale, rotation and mirroring), bad input is one message and exit 2,
// and nothing the modder had is overwritten.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "polar/platform/png_io.h"
#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

constexpr std::uint32_t kOutline = 0xffffd650;  // the first radii's outline colour (255, 214, 80)

struct Outcome {
    int exitCode = -1;
    std::string out, err;
};

// Where the tool says it put the sprite's origin, and its zoom (canvas pixels per world unit).
struct Placement {
    double zoom = 0, x = 0, y = 0;
};

class BoundsView : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bounds-view"); }
    void TearDown() override { fs::remove_all(folder_); }

    static std::string read(const fs::path& p) {
        std::ifstream in(p, std::ios::binary);
        std::ostringstream text;
        text << in.rdbuf();
        return text.str();
    }
    void write(const std::string& name, const std::string& text) const {
        std::ofstream(folder_ / name, std::ios::binary) << text;
    }
    Outcome run(const std::string& args) const {
        std::string command = "cd '" + folder_.string() + "' && '" + std::string(POLAR_BOUNDS_EXE) + "' " +
                              args + " >stdout.txt 2>stderr.txt";
        int status = std::system(command.c_str());
        Outcome r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(folder_ / "stdout.txt"),
                  read(folder_ / "stderr.txt")};
        fs::remove(folder_ / "stdout.txt");
        fs::remove(folder_ / "stderr.txt");
        return r;
    }
    static Placement placement(const std::string& out) {
        std::smatch m;
        std::regex pattern("zoom ([0-9.]+), sprite origin at canvas \\(([0-9.-]+), ([0-9.-]+)\\)");
        EXPECT_TRUE(std::regex_search(out, m, pattern)) << out;
        if (m.size() < 4) return {};
        return {std::stod(m[1]), std::stod(m[2]), std::stod(m[3])};
    }
    RgbaImage picture(const std::string& name) const {
        Result<RgbaImage> image = loadPng((folder_ / name).string());
        EXPECT_TRUE(image.ok()) << (image.ok() ? "" : image.error().message());
        return image.ok() ? *image : RgbaImage{};
    }

    fs::path folder_;
};

// True when a pixel of the outline's colour lies within one pixel of the canvas point of world
// point (wx, wy): the outline is one pixel thick and drawn through pixel centres.
bool outlineNear(const RgbaImage& image, const Placement& p, double wx, double wy) {
    double cx = p.x + p.zoom * wx, cy = p.y - p.zoom * wy;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            int x = static_cast<int>(std::floor(cx)) + dx, y = static_cast<int>(std::floor(cy)) + dy;
            if (x >= 0 && y >= 0 && x < image.width && y < image.height && image.at(x, y) == kOutline)
                return true;
        }
    return false;
}

// Bound-space point at `degrees`, `radius` from the origin.
double px(double degrees, double radius) {
    return radius * std::cos(degrees * M_PI / 180);
}
double py(double degrees, double radius) {
    return radius * std::sin(degrees * M_PI / 180);
}

// Long toward +x, short elsewhere; the 45° bisectors are where the nearest rule steps.
const char* kNearest = R"({"format": 1, "radii": [{"interpolate": false,
  "samples": [[0, 20], [90, 10], [180, 10], [270, 10]]}]})";
const char* kChord = R"({"format": 1, "radii": [{"interpolate": true,
  "samples": [[0, 20], [90, 10], [180, 10], [270, 10]]}]})";

TEST_F(BoundsView, HelpNamesTheOptions) {
    Outcome r = run("view --help");
    EXPECT_EQ(r.exitCode, 0);
    for (const char* option : {"--sprite", "--scale", "--rotate", "--flip", "--output"})
        EXPECT_NE(r.out.find(option), std::string::npos) << option;
}

TEST_F(BoundsView, NearestRuleIsArcsWithStepsAtTheBisectors) {
    write("shape.bounds.json", kNearest);
    Outcome r = run("view shape.bounds.json -o view.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("wrote view.png"), std::string::npos) << r.out;
    Placement p = placement(r.out);
    RgbaImage image = picture("view.png");
    EXPECT_GE(p.zoom, 4) << "a 40-pixel shape is zoomed to be readable";
    // The arc of radius 20 around 0°, radius 10 elsewhere.
    for (double a : {-40.0, -20.0, 10.0, 30.0, 40.0}) {
        EXPECT_TRUE(outlineNear(image, p, px(a, 20), py(a, 20))) << a;
        EXPECT_FALSE(outlineNear(image, p, px(a, 15), py(a, 15))) << a;
    }
    for (double a : {60.0, 100.0, 150.0, 200.0, 250.0, 300.0})
        EXPECT_TRUE(outlineNear(image, p, px(a, 10), py(a, 10))) << a;
    // The radial step on the 45° bisector, from radius 20 down to 10.
    for (double radius : {12.0, 15.0, 18.0})
        EXPECT_TRUE(outlineNear(image, p, px(45, radius), py(45, radius))) << radius;
}

TEST_F(BoundsView, ChordRuleIsStraightEdges) {
    write("shape.bounds.json", kChord);
    Outcome r = run("view shape.bounds.json -o view.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Placement p = placement(r.out);
    RgbaImage image = picture("view.png");
    // The edge from (20, 0) to (0, 10): x/20 + y/10 = 1; at 10° its radius is 1/(cos/20 + sin/10).
    for (double a : {10.0, 30.0, 60.0}) {
        double r10 = 1 / (std::cos(a * M_PI / 180) / 20 + std::sin(a * M_PI / 180) / 10);
        EXPECT_TRUE(outlineNear(image, p, px(a, r10), py(a, r10))) << a;
    }
    EXPECT_FALSE(outlineNear(image, p, px(10, 20), py(10, 20))) << "no arc: that is the nearest rule";
}

TEST_F(BoundsView, ScaleRotationAndFlipMoveTheOutlineAsTheGameWould) {
    write("shape.bounds.json", kNearest);
    // Rotated 90° counter-clockwise: the long side points up.
    Outcome r = run("view shape.bounds.json --rotate 90 -o up.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Placement p = placement(r.out);
    RgbaImage image = picture("up.png");
    EXPECT_TRUE(outlineNear(image, p, px(100, 20), py(100, 20)));
    EXPECT_FALSE(outlineNear(image, p, px(10, 20), py(10, 20)));
    // Mirrored: the long side points left.
    r = run("view shape.bounds.json --flip -o left.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    p = placement(r.out);
    image = picture("left.png");
    EXPECT_TRUE(outlineNear(image, p, px(170, 20), py(170, 20)));
    EXPECT_FALSE(outlineNear(image, p, px(10, 20), py(10, 20)));
    // Scaled by 3: radius 60 in the world.
    r = run("view shape.bounds.json --scale 3 -o big.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    p = placement(r.out);
    image = picture("big.png");
    EXPECT_TRUE(outlineNear(image, p, px(20, 60), py(20, 60)));
    EXPECT_TRUE(outlineNear(image, p, px(120, 30), py(120, 30)));
    EXPECT_FALSE(outlineNear(image, p, px(20, 20), py(20, 20)));
}

TEST_F(BoundsView, TheSpriteIsDrawnUnderTheOutline) {
    write("shape.bounds.json", kNearest);
    RgbaImage red{8, 8, std::vector<std::uint32_t>(64, 0xffff0000)};
    ASSERT_FALSE(savePng(red, (folder_ / "shape.png").string()).has_value());
    Outcome r = run("view shape.bounds.json -o view.png");  // found beside the bounds file
    ASSERT_EQ(r.exitCode, 0) << r.err;
    Placement p = placement(r.out);
    RgbaImage image = picture("view.png");
    EXPECT_EQ(image.at(static_cast<int>(p.x + p.zoom * 2.5), static_cast<int>(p.y - p.zoom * 1.5)),
              0xffff0000u)
        << "a sprite pixel between the axes and the spokes";
    EXPECT_EQ(image.at(static_cast<int>(p.x + p.zoom * 6), static_cast<int>(p.y - p.zoom * 6)) == 0xffff0000u,
              false)
        << "outside the 8 × 8 sprite";
}

TEST_F(BoundsView, BadInputIsOneMessageAndNothingIsOverwritten) {
    write("bad.bounds.json", "{\"format\": 1,\n \"radii\": [{\"samples\": [[0, -5]]}]}");
    write("old.png", "the modder's old picture");
    Outcome r = run("view bad.bounds.json -o old.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("bad.bounds.json:2:", 0), 0u) << r.err;
    EXPECT_NE(r.err.find("radius -5 is not positive"), std::string::npos) << r.err;
    EXPECT_EQ(read(folder_ / "old.png"), "the modder's old picture");

    write("shape.bounds.json", kNearest);
    for (const char* args : {"--scale 0", "--scale -2", "--rotate nan"}) {
        r = run(std::string("view shape.bounds.json ") + args + " -o old.png");
        EXPECT_EQ(r.exitCode, 2) << args;
        EXPECT_NE(r.err, "") << args;
    }
    r = run("view shape.bounds.json -o shape.bounds.json");
    EXPECT_EQ(r.exitCode, 2) << "not a .png";
    EXPECT_EQ(read(folder_ / "shape.bounds.json"), kNearest);
    RgbaImage red{8, 8, std::vector<std::uint32_t>(64, 0xffff0000)};
    ASSERT_FALSE(savePng(red, (folder_ / "shape.png").string()).has_value());
    std::string sprite = read(folder_ / "shape.png");
    r = run("view shape.bounds.json -o ./shape.png");
    EXPECT_EQ(r.exitCode, 2) << "would overwrite the sprite";
    EXPECT_NE(r.err.find("would overwrite"), std::string::npos) << r.err;
    EXPECT_EQ(read(folder_ / "shape.png"), sprite);
    r = run("view missing.bounds.json -o view.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_FALSE(fs::exists(folder_ / "view.png"));
    r = run("view shape.bounds.json -o no/such/folder/view.png");
    EXPECT_EQ(r.exitCode, 2);
    for (const auto& entry : fs::directory_iterator(folder_))
        EXPECT_EQ(entry.path().string().find(".tmp"), std::string::npos)
            << "no temporary file left: " << entry.path();
}

TEST_F(BoundsView, EveryCommittedSpriteCanBeViewed) {
    for (const auto& entry : fs::directory_iterator(fs::path(POLAR_ASSET_DIR) / "sprites")) {
        std::string name = entry.path().filename().string();
        if (name.size() < 12 || name.substr(name.size() - 12) != ".bounds.json") continue;
        Outcome r = run("view -q '" + entry.path().string() + "' -o view.png");
        EXPECT_EQ(r.exitCode, 0) << name << ": " << r.err;
        RgbaImage image = picture("view.png");
        int outline = 0;  // in the drawing: below the header, left of the key
        for (int y = 60; y < image.height; ++y)
            for (int x = 0; x < 640; ++x) outline += image.at(x, y) == kOutline;
        EXPECT_GT(outline, 100) << name;
    }
}

}  // namespace
}  // namespace polar
