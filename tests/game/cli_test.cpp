// Runs the built polarcade executable as a player or a CI job would.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "polar/platform/png_io.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace {

namespace fs = std::filesystem;
using polar::testing::run;
using polar::testing::runShell;
using polar::testing::shellQuote;

class PolarcadeCli : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-cli"); }
    void TearDown() override { fs::remove_all(folder_); }
    fs::path folder_;
};

TEST_F(PolarcadeCli, HeadlessRunWritesARealFrame) {
    auto r =
        run(POLARCADE_EXE,
            {"--headless", "--ticks", "600", "--screenshot", "600:out.png", "--screenshot", "1:first.png"},
            folder_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    polar::Result<polar::RgbaImage> frame = polar::loadPng((folder_ / "out.png").string());
    ASSERT_TRUE(frame.ok());
    EXPECT_EQ(frame->width, 640);
    EXPECT_EQ(frame->height, 360);
    polar::Result<polar::RgbaImage> first = polar::loadPng((folder_ / "first.png").string());
    ASSERT_TRUE(first.ok());
    EXPECT_NE(first->pixels, frame->pixels) << "the game moved between tick 1 and tick 600";
}

TEST_F(PolarcadeCli, HeadlessFramesAreTheSameEveryRun) {
    ASSERT_EQ(
        run(POLARCADE_EXE, {"--headless", "--ticks", "200", "--screenshot", "200:a.png"}, folder_).exitCode,
        0);
    ASSERT_EQ(
        run(POLARCADE_EXE, {"--headless", "--ticks", "200", "--screenshot", "200:b.png"}, folder_).exitCode,
        0);
    EXPECT_EQ(polar::testing::readFile(folder_ / "a.png"), polar::testing::readFile(folder_ / "b.png"));
}

// --stats prints the engine's per-effect table: one line per effect with its calls, and the totals.
TEST_F(PolarcadeCli, StatsPrintsCallsAndTimePerEffect) {
    auto r = run(POLARCADE_EXE, {"--headless", "--ticks", "120", "--stats"}, folder_);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("per-effect statistics over 120 steps"), std::string::npos) << r.out;
    for (const char* effect : {"physics", "collisions", "response", "containers"})
        EXPECT_NE(r.out.find(std::string("\n") + effect + " "), std::string::npos) << effect << "\n" << r.out;
    EXPECT_NE(r.out.find("pair tests"), std::string::npos) << r.out;
    auto quiet = run(POLARCADE_EXE, {"--headless", "--ticks", "120"}, folder_);
    EXPECT_EQ(quiet.out.find("per-effect"), std::string::npos) << "only with --stats";
}

// --threads N: the step's thread count, shown by --stats; the game plays the same on any number.
TEST_F(PolarcadeCli, ThreadsAreShownByStatsAndChangeNothing) {
    auto three =
        run(POLARCADE_EXE,
            {"--headless", "--ticks", "300", "--stats", "--threads", "3", "--screenshot", "300:three.png"},
            folder_);
    ASSERT_EQ(three.exitCode, 0) << three.err;
    EXPECT_NE(three.out.find("per-effect statistics over 300 steps on 3 threads"), std::string::npos)
        << three.out;
    auto one =
        run(POLARCADE_EXE,
            {"--headless", "--ticks", "300", "--stats", "--threads", "1", "--screenshot", "300:one.png"},
            folder_);
    ASSERT_EQ(one.exitCode, 0) << one.err;
    EXPECT_NE(one.out.find("on 1 thread:"), std::string::npos) << one.out;
    EXPECT_EQ(polar::testing::readFile(folder_ / "one.png"), polar::testing::readFile(folder_ / "three.png"));
    EXPECT_EQ(run(POLARCADE_EXE, {"--headless", "--threads", "0"}, folder_).exitCode, 2);
}

TEST_F(PolarcadeCli, NoDisplayFallsBackToAHeadlessAttractDemo) {
    // No DISPLAY, no WAYLAND_DISPLAY: a plain start must not hang in an invisible window.
    std::string env =
        "env -u DISPLAY -u WAYLAND_DISPLAY -u SDL_VIDEODRIVER XDG_DATA_HOME=" + shellQuote(folder_.string()) +
        " HOME=" + shellQuote(folder_.string()) + " timeout 120 ";
    auto r = runShell(env + shellQuote(POLARCADE_EXE) + " --mute");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_EQ(r.out.rfind("polarcade: no display found", 0), 0u) << r.out;
    std::size_t at = r.out.find("saved a screenshot of the attract demo to ");
    ASSERT_NE(at, std::string::npos) << r.out;
    std::string path = r.out.substr(at + 42);
    path = path.substr(0, path.find('\n'));
    EXPECT_TRUE(polar::loadPng(path).ok()) << path;
    EXPECT_EQ(path.rfind(folder_.string(), 0), 0u) << "saved in the player's data folder";
}

TEST_F(PolarcadeCli, BadFlagsGetOneClearLineAndExitTwo) {
    auto r = run(POLARCADE_EXE, {"--bogus"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("--bogus"), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;

    r = run(POLARCADE_EXE, {"--headless", "--screenshot", "soon:x.png"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err,
              "polarcade: --screenshot soon:x.png: expected TICK:FILE.png with TICK a whole number from 0 to "
              "18446744073709551615, got soon\n");
    r = run(POLARCADE_EXE, {"--headless", "--screenshot", "x.png"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err, "polarcade: --screenshot x.png: expected TICK:FILE.png, e.g. 600:out.png\n");

    r = run(POLARCADE_EXE, {"--headless", "--scene", "no-such-scene"});
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_EQ(r.err.rfind("no-such-scene: no such scene file or scene name; expected a scene name (cave", 0),
              0u)
        << r.err;

    r = run(POLARCADE_EXE, {"--headless", "--ticks", "-5"});
    EXPECT_EQ(r.exitCode, 2);
}

TEST_F(PolarcadeCli, ABrokenSceneIsReportedWithItsPlace) {
    std::ofstream(folder_ / "broken.json") << "{\"format\": 1,\n \"effects\": [\"physics\", \"gravity\"]}";
    auto r = run(POLARCADE_EXE, {"--headless", "--scene", "broken.json"}, folder_);
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("broken.json:2:25: unknown effect \"gravity\"; expected one of"), std::string::npos)
        << r.err;
}

TEST_F(PolarcadeCli, HelpExitsZero) {
    auto r = run(POLARCADE_EXE, {"--help"});
    EXPECT_EQ(r.exitCode, 0);
    EXPECT_NE(r.out.find("--headless"), std::string::npos);
    EXPECT_NE(r.out.find("--screenshot"), std::string::npos);
}

}  // namespace
