// polarcade-bounds as a modder runs it: exit codes, exact file:line:column messages, warnings, files
// written. Each test runs the real executable in a fresh folder.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "polar/bounds_file.h"
#include "polar/platform/png_io.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar {
namespace {

namespace fs = std::filesystem;

using Outcome = polar::testing::CommandOutcome;

class BoundsCli : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-bounds-cli"); }
    void TearDown() override { fs::remove_all(folder_); }

    static std::string read(const fs::path& p) { return polar::testing::readFile(p); }
    void write(const std::string& name, const std::string& text) const {
        fs::create_directories((folder_ / name).parent_path());
        std::ofstream(folder_ / name, std::ios::binary) << text;
    }
    // A copy of a committed sprite, by name.
    void copySprite(const std::string& sprite, const std::string& as) const {
        fs::create_directories((folder_ / as).parent_path());
        fs::copy_file(std::string(POLAR_ASSET_DIR) + "/sprites/" + sprite + ".png", folder_ / as);
    }

    // Runs `polarcade-bounds args` inside the folder.
    Outcome run(const std::string& args) const {
        return polar::testing::runShell(polar::testing::shellQuote(POLAR_BOUNDS_EXE) + " " + args, folder_);
    }

    // `check FILE` must fail with exactly this one-line message and exit code 2.
    void expectError(const std::string& file, const std::string& message) const {
        Outcome r = run("check " + file);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(r.err, message + "\n");
        EXPECT_EQ(r.out, "");
    }

    fs::path folder_;
};

// ---------------------------------------------------------------------------------------------- help

TEST_F(BoundsCli, HelpOnTheToolAndEverySubcommand) {
    for (const char* args : {"--help", "gen --help", "check --help"}) {
        Outcome r = run(args);
        EXPECT_EQ(r.exitCode, 0) << args;
        EXPECT_NE(r.out.find("Usage:"), std::string::npos) << args;
    }
    EXPECT_NE(run("gen --help").out.find("--container"), std::string::npos);
    EXPECT_NE(run("check --help").out.find("file:line:column"), std::string::npos);
}

TEST_F(BoundsCli, ABadCommandLineExitsTwo) {
    EXPECT_EQ(run("").exitCode, 2);
    EXPECT_EQ(run("frobnicate").exitCode, 2);
    EXPECT_EQ(run("gen").exitCode, 2);
    EXPECT_EQ(run("check").exitCode, 2);
    Outcome r = run("gen x.png --radii 99");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--radii"), std::string::npos) << r.err;
}

// ------------------------------------------------------- check: one test per error kind of the loader

TEST_F(BoundsCli, CheckSyntaxError) {
    write("a.bounds.json", "{\"format\": 1, \"radii\": [{\"samples\": [[0, 30] [90, 24]]}]}\n");
    expectError("a.bounds.json",
                "a.bounds.json:1:46: syntax error while parsing array - unexpected '['; expected ']'");
}

TEST_F(BoundsCli, CheckNonFiniteNumber) {
    write("a.bounds.json", "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, 30], [90, 1e999]]}]\n}\n");
    expectError("a.bounds.json",
                "a.bounds.json:3:40: a non-finite number (too large for a double); expected a finite number");
}

TEST_F(BoundsCli, CheckWrongType) {
    write("a.bounds.json", "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, \"30\"]]}]\n}\n");
    expectError("a.bounds.json", "a.bounds.json:3:30: found a string; expected a radius in sprite pixels");
    write("b.bounds.json", "{\n  \"format\": 1,\n  \"radii\": {\"samples\": []}\n}\n");
    expectError("b.bounds.json", "b.bounds.json:3:12: found an object; expected an array of radii objects");
}

TEST_F(BoundsCli, CheckRadiusNotPositive) {
    write("a.bounds.json", "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, 30], [90, 0]]}]\n}\n");
    expectError("a.bounds.json", "a.bounds.json:3:35: radius 0 is not positive; expected a radius > 0");
    write("b.bounds.json", "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, -2.5]]}]\n}\n");
    expectError("b.bounds.json", "b.bounds.json:3:26: radius -2.5 is not positive; expected a radius > 0");
}

TEST_F(BoundsCli, CheckSameAngleModulo360) {
    write("a.bounds.json",
          "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, 30], [90, 20],\n    [360, 25]]}]\n}\n");
    expectError(
        "a.bounds.json",
        "a.bounds.json:4:5: angle 360 is the same direction as 0 (sample 1) modulo 360; expected one sample "
        "per direction");
}

TEST_F(BoundsCli, CheckInterpolateWithFewerThanThreeSamples) {
    write(
        "a.bounds.json",
        "{\n  \"format\": 1,\n  \"radii\": [{\"interpolate\": true, \"samples\": [[0, 30], [90, 20]]}]\n}\n");
    expectError(
        "a.bounds.json",
        "a.bounds.json:3:46: interpolate needs at least 3 samples, found 2; expected 3 or more samples, or "
        "\"interpolate\": false");
}

TEST_F(BoundsCli, CheckGapOf180DegreesOrMore) {
    write("a.bounds.json",
          "{\n  \"format\": 1,\n  \"radii\": [{\"interpolate\": true,\n"
          "             \"samples\": [[0, 30], [90, 20], [270, 25]]}]\n}\n");
    expectError("a.bounds.json",
                "a.bounds.json:4:35: a gap of 180 degrees from angle 90 to the next sample at 270; expected "
                "gaps under "
                "180 degrees between neighbouring samples, so the straight-edge outline stays star-shaped");
}

TEST_F(BoundsCli, CheckUnknownKey) {
    write("a.bounds.json",
          "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, 30]], \"radious\": 3}]\n}\n");
    expectError("a.bounds.json",
                "a.bounds.json:3:36: unknown key \"radious\"; expected one of \"centre\", \"interpolate\", "
                "\"samples\"");
}

TEST_F(BoundsCli, CheckDuplicateKey) {
    write("a.bounds.json", "{\n  \"format\": 1,\n  \"radii\": [],\n  \"radii\": []\n}\n");
    expectError("a.bounds.json",
                "a.bounds.json:4:3: duplicate key \"radii\"; expected each key once in an object");
}

TEST_F(BoundsCli, CheckMissingFile) {
    expectError(
        "missing.bounds.json",
        "missing.bounds.json: cannot read the bounds file; expected an existing, readable .bounds.json file");
}

TEST_F(BoundsCli, CheckUnsupportedOrMissingFormat) {
    write("a.bounds.json", "{\n  \"format\": 2,\n  \"radii\": []\n}\n");
    expectError("a.bounds.json", "a.bounds.json:2:13: unsupported format 2; expected \"format\": 1");
    write("b.bounds.json", "{\n  \"radii\": []\n}\n");
    expectError(
        "b.bounds.json",
        "b.bounds.json:1:1: missing key \"format\"; expected \"format\": 1 at the top of a bounds file");
}

// Scene files go through the game's scene loader: the error kinds only a scene can have.
TEST_F(BoundsCli, CheckSceneDuplicateObjectName) {
    write("scene.json",
          "{\n  \"format\": 1,\n  \"objects\": [\n"
          "    {\"name\": \"rock\", \"bounds\": {\"radii\": [{\"samples\": [[0, 5]]}]}},\n"
          "    {\"name\": \"rock\", \"bounds\": {\"radii\": [{\"samples\": [[0, 5]]}]}}\n  ]\n}\n");
    expectError(
        "scene.json",
        "scene.json:5:14: duplicate object name \"rock\" (first used on line 4); expected a name no other "
        "object has");
}

TEST_F(BoundsCli, CheckSceneEmptyObjectName) {
    write("scene.json",
          "{\n  \"format\": 1,\n  \"objects\": [\n"
          "    {\"name\": \"\", \"bounds\": {\"radii\": [{\"samples\": [[0, 5]]}]}}\n  ]\n}\n");
    expectError("scene.json", "scene.json:4:14: an empty object name; expected a unique, non-empty name");
}

TEST_F(BoundsCli, CheckSceneUnknownFlag) {
    write("scene.json",
          "{\n  \"format\": 1,\n  \"effects\": [\"physics\", \"collisions\"],\n  \"objects\": [\n"
          "    {\"name\": \"a\", \"flags\": [\"physics\", \"ghostly\"], \"bounds\": {\"radii\": "
          "[{\"samples\": [[0, 5]]}]}}\n  ]\n}\n");
    expectError(
        "scene.json",
        "scene.json:5:40: unknown flag \"ghostly\"; expected one of \"physics\", \"collisions\", \"ghost\", "
        "\"container\", \"ignore_containers\", \"fast\"");
}

TEST_F(BoundsCli, CheckSceneMissingBoundsFile) {
    write("scene.json",
          "{\n  \"format\": 1,\n  \"objects\": [\n    {\"name\": \"a\", \"bounds\": "
          "\"nowhere.bounds.json\"}\n  ]\n}\n");
    expectError(
        "scene.json",
        "scene.json:4:29: cannot read bounds file \"nowhere.bounds.json\"; expected an existing .bounds.json "
        "file, relative to this scene");
}

TEST_F(BoundsCli, CheckReportsEveryBadFileAndStillExitsTwo) {
    write("good.bounds.json", "{\"format\": 1, \"radii\": [{\"samples\": [[0, 3]]}]}");
    write("bad.bounds.json", "{\"format\": 1, \"radii\": [{\"samples\": [[0, 0]]}]}");
    Outcome r = run("check bad.bounds.json good.bounds.json missing.bounds.json");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("bad.bounds.json:1:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("missing.bounds.json: cannot read"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("good.bounds.json: ok"), std::string::npos) << r.out;
}

// ------------------------------------------------------------------------------------- check: warnings

TEST_F(BoundsCli, CheckCommittedBoundsPassWithoutWarnings) {
    Outcome r = run("check '" + std::string(POLAR_ASSET_DIR) + "/sprites/'*.bounds.json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("rock-large-1.bounds.json: ok (1 radii"), std::string::npos) << r.out;
}

TEST_F(BoundsCli, WarnsAboutACentreOutsideTheSprite) {
    copySprite("rock-small-1", "rock.png");  // 18 × 18
    // Just right of the image, with its one sample back on the rock's edge.
    write("rock.bounds.json",
          "{\n  \"format\": 1,\n  \"radii\": [{\"centre\": [9.5, 0], \"samples\": [[180, 2]]}]\n}\n");
    Outcome r = run("check rock.bounds.json");
    EXPECT_EQ(r.exitCode, 0) << "a warning is not an error";
    EXPECT_NE(
        r.err.find("rock.bounds.json:3:24: warning: the centre [9.5, 0.0] lies outside the 18x18 sprite; "
                   "expected a centre within [-9.0, 9.0] x [-9.0, 9.0]"),
        std::string::npos)
        << r.err;
    EXPECT_NE(r.out.find("rock.bounds.json: ok (1 radii, 1 samples; checked against rock.png, 1 warning)"),
              std::string::npos)
        << r.out;
}

TEST_F(BoundsCli, WarnsAboutASampleFarOutsideOrDeepInside) {
    copySprite("rock-large-1", "rock.png");  // 56 × 56, about 25 px across from its centre
    write("rock.bounds.json",
          "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [\n"
          "    [0, 26], [90, 60], [180, 26],\n    [270, 5]]}]\n}\n");
    Outcome r = run("check rock.bounds.json");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find("rock.bounds.json:4:14: warning: sample 2 [90.0, 60.0] lies "), std::string::npos)
        << r.err;
    EXPECT_NE(
        r.err.find(" px outside the sprite's opaque area; expected a sample point within 15.0 px of the "
                   "sprite's edge\n"),
        std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find("rock.bounds.json:5:5: warning: sample 4 [270.0, 5.0] lies "), std::string::npos)
        << r.err;
    EXPECT_NE(r.err.find(" px inside the sprite's opaque area"), std::string::npos) << r.err;
    EXPECT_EQ(r.err.find("sample 1 "), std::string::npos) << "samples near the edge are fine: " << r.err;
    EXPECT_EQ(r.err.find("sample 3 "), std::string::npos) << r.err;
}

TEST_F(BoundsCli, FindsTheSpriteInASiblingSpritesFolder) {
    copySprite("rock-small-1", "mod/sprites/rock.png");
    write("mod/bounds/rock.bounds.json",
          "{\"format\": 1, \"radii\": [{\"centre\": [30, 0], \"samples\": [[0, 1]]}]}");
    Outcome r = run("check mod/bounds/rock.bounds.json");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.err.find("mod/bounds/rock.bounds.json:1:"), std::string::npos) << r.err;
    EXPECT_NE(r.out.find("checked against mod/sprites/rock.png"), std::string::npos) << r.out;
}

TEST_F(BoundsCli, WithoutASpriteOnlyTheFileIsChecked) {
    write("alone.bounds.json", "{\"format\": 1, \"radii\": [{\"centre\": [300, 0], \"samples\": [[0, 1]]}]}");
    Outcome r = run("check alone.bounds.json");
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_EQ(r.err, "");
    EXPECT_NE(r.out.find("no sprite found beside it"), std::string::npos) << r.out;
    // --sprite names one explicitly.
    copySprite("bullet", "shot.png");
    r = run("check alone.bounds.json --sprite shot.png");
    EXPECT_NE(r.err.find("warning: the centre [300.0, 0.0] lies outside the 5x5 sprite"), std::string::npos)
        << r.err;
}

// ------------------------------------------------------------------------------------------------ gen

TEST_F(BoundsCli, GenWritesBesideTheSpriteAndTheResultChecksClean) {
    copySprite("rock-medium-2", "rock.png");
    Outcome r = run("gen rock.png -n 12");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("rock.png: 32x32, threshold 127, enclosing"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("12 samples"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("worst miss 0.000 px"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("wrote rock.bounds.json\n"), std::string::npos) << r.out;
    Result<BoundsPtr> loaded = loadBounds((folder_ / "rock.bounds.json").string(), diskReader());
    ASSERT_TRUE(loaded.ok());
    EXPECT_EQ((**loaded)[0].samples().size(), 12u);
    Outcome check = run("check rock.bounds.json");
    EXPECT_EQ(check.exitCode, 0);
    EXPECT_EQ(check.err, "") << "generated bounds raise no warnings";
    EXPECT_FALSE(fs::exists(folder_ / "rock.bounds.json.tmp"));
}

TEST_F(BoundsCli, GenOptions) {
    copySprite("comet", "comet.png");
    Outcome r = run("gen comet.png --radii 2 -o out/../comet-split.json");
    ASSERT_EQ(r.exitCode, 2) << "the folder out/ does not exist: " << r.out;
    fs::create_directories(folder_ / "out");
    r = run("gen comet.png --radii 2 -o out/../comet-split.json");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("radii 2:"), std::string::npos) << r.out;
    EXPECT_EQ(loadBounds((folder_ / "comet-split.json").string(), diskReader()).value()->size(), 2u);
    r = run("gen comet.png --centre 1.5,-2 -q");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out, "wrote comet.bounds.json\n");
    EXPECT_EQ((*loadBounds((folder_ / "comet.bounds.json").string(), diskReader()).value())[0].centre(),
              Vec2(1.5, -2));
}

TEST_F(BoundsCli, GenContainer) {
    // A small cave: opaque rock around an elliptical hollow.
    RgbaImage cave{120, 80, {}};
    for (int y = 0; y < 80; ++y)
        for (int x = 0; x < 120; ++x) {
            double ex = (x + 0.5 - 60) / 50, ey = (y + 0.5 - 40) / 30;
            cave.pixels.push_back(ex * ex + ey * ey < 1 ? 0x00000000u : 0xff604050u);
        }
    ASSERT_FALSE(savePng(cave, (folder_ / "cave.png").string()));
    Outcome r = run("gen cave.png --container -n 24");
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("container (outline inside the free space)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("24 samples"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("worst miss 0.000 px"), std::string::npos) << r.out;
    Outcome check = run("check cave.bounds.json");
    EXPECT_EQ(check.exitCode, 0);
    EXPECT_EQ(check.err, "") << "container bounds lie along the walls: no warnings";
    r = run("gen cave.png --container --centre 0,35");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err,
              "cave.png: the centre (0, 35) lies on an opaque pixel; expected a container's "
              "centre in its free space (--centre X,Y)\n");
}

TEST_F(BoundsCli, GenBadInputIsOneClearLine) {
    Outcome r = run("gen missing.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "missing.png: no such file; expected an image file\n");
    write("broken.png", "not a png at all");
    r = run("gen broken.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("broken.png: cannot decode the image", 0), 0u) << r.err;
    copySprite("bullet", "shot.png");
    r = run("gen shot.png --centre 1,two");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err,
              "polarcade-bounds: --centre: expected X,Y with two finite numbers, e.g. 1.5,-2, got 1,two; see "
              "polarcade-bounds --help\n");
    r = run("gen shot.png -n 2");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("shot.png: -n 2 is too few samples; expected at least 3 samples"), std::string::npos)
        << r.err;
    EXPECT_FALSE(fs::exists(folder_ / "shot.bounds.json")) << "nothing is written on an error";
}

TEST_F(BoundsCli, GenKeepsTheOldFileWhenTheSpriteHasNothingOpaque) {
    RgbaImage empty{8, 8, std::vector<std::uint32_t>(64, 0)};
    ASSERT_FALSE(savePng(empty, (folder_ / "ghost.png").string()));
    write("ghost.bounds.json", "{\"format\": 1, \"radii\": [{\"samples\": [[0, 3]]}]}");
    Outcome r = run("gen ghost.png");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(
        r.err,
        "ghost.png: no opaque pixels (alpha above 127); expected a sprite with an opaque shape to enclose\n");
    EXPECT_EQ(read(folder_ / "ghost.bounds.json"), "{\"format\": 1, \"radii\": [{\"samples\": [[0, 3]]}]}");
}

}  // namespace
}  // namespace polar
