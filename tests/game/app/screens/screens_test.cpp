// Every screen, driven as a player drives it but from scripts of events (polarcade --script):
// keyboard, game controller and mouse reach each screen by the path a window's events take, and
// each screen's picture is compared with its golden screenshot.
//
// The goldens live in tests/game/golden/ (the title's and the theatre's in assets/docs/, shown in
// the README) and are compared pixel for pixel. After an intended
// change to a screen's picture, rewrite them with
// POLAR_UPDATE_GOLDEN=1 build/bin/polar-game-tests --gtest_filter='Screens*' and look at them.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "polar/platform/png_io.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

const fs::path kGolden = POLAR_GAME_GOLDEN_DIR;

class Screens : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-screens"); }
    void TearDown() override { fs::remove_all(folder_); }

    // Runs the game on `script` with its data folder in the test's folder, seed 1.
    polar::testing::CommandOutcome play(const std::string& script,
                                        std::vector<std::string> extra = {}) const {
        std::ofstream(folder_ / "script.txt", std::ios::binary) << script;
        std::vector<std::string> args = {"--script", "script.txt", "--data", "data", "--seed", "1"};
        args.insert(args.end(), extra.begin(), extra.end());
        return polar::testing::run(POLARCADE_EXE, args, folder_);
    }
    // Two of the golden replays in the data folder, as if played on two days.
    void keepReplays() const {
        fs::create_directories(folder_ / "data/replays");
        fs::copy_file(fs::path(POLAR_REPLAY_DIR) / "short.replay",
                      folder_ / "data/replays/2026-01-01_12-00-00.replay");
        fs::copy_file(fs::path(POLAR_REPLAY_DIR) / "game-over.replay",
                      folder_ / "data/replays/2026-01-02_12-00-00.replay");
    }
    // Compares the screenshot `name`.png with golden/screen-NAME.png pixel for pixel, or rewrites it.
    // The title's golden is the README's picture of the title menu, assets/docs/title-menu.png, and
    // the theatre's with a marker under the pointer its picture of the theatre, replay-theatre.png.
    void expectGolden(const std::string& name) const {
        const fs::path shot = folder_ / (name + ".png");
        const fs::path golden = name == "title" ? fs::path(POLAR_ASSET_DIR) / "docs/title-menu.png"
                                : name == "theatre-marker"
                                    ? fs::path(POLAR_ASSET_DIR) / "docs/replay-theatre.png"
                                    : kGolden / ("screen-" + name + ".png");
        if (const char* update = std::getenv("POLAR_UPDATE_GOLDEN"); update && std::string(update) == "1") {
            fs::create_directories(golden.parent_path());
            fs::copy_file(shot, golden, fs::copy_options::overwrite_existing);
            return;
        }
        Result<RgbaImage> actual = loadPng(shot.string());
        Result<RgbaImage> expected = loadPng(golden.string());
        ASSERT_TRUE(actual.ok()) << actual.error().message();
        ASSERT_TRUE(expected.ok()) << expected.error().message() << " (POLAR_UPDATE_GOLDEN=1 writes it)";
        ASSERT_EQ(actual->width, expected->width);
        ASSERT_EQ(actual->height, expected->height);
        std::size_t differing = 0, first = 0;
        for (std::size_t i = 0; i < actual->pixels.size(); ++i)
            if (actual->pixels[i] != expected->pixels[i] && differing++ == 0) first = i;
        const fs::path failed = fs::temp_directory_path() / ("failed-screen-" + name + ".png");
        if (differing) fs::copy_file(shot, failed, fs::copy_options::overwrite_existing);
        EXPECT_EQ(differing, 0u) << name << ": first at (" << first % actual->width << ", "
                                 << first / actual->width << "); the picture is in " << failed;
    }
    std::string read(const fs::path& file) const {
        std::ifstream in(folder_ / file, std::ios::binary);
        return std::string(std::istreambuf_iterator<char>(in), {});
    }

    fs::path folder_;
};

// The keyboard through the menus: each screen reached, shown and left by its keys.
TEST_F(Screens, TheKeyboardReachesEveryMenuScreen) {
    keepReplays();
    const auto run = play(R"(wait 30
expect title
screenshot title.png
key down
key enter
expect scenes
screenshot scenes.png
key escape
key down
key enter
expect replays
screenshot replays.png
key enter
expect replay
wait 120
screenshot replay.png
key escape
expect replays
key escape
key down
key enter
expect options
screenshot options.png
key escape
expect title
key down
key enter
expect high-scores
screenshot high-scores.png
key escape
expect title
key escape
expect quit-confirm
screenshot quit-confirm.png
key escape
expect title
key up up up up
expect title
key enter
expect playing
wait 60
screenshot playing.png
key p
expect paused
screenshot paused.png
key down down
key enter
expect options
key escape
expect paused
key escape
expect playing
key escape
key down down down
key enter
expect title
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    for (const char* name : {"title", "scenes", "replays", "replay", "options", "high-scores", "quit-confirm",
                             "playing", "paused"})
        expectGolden(name);
}

// A game to its end: game over, the name typed (Backspace takes a letter back), the table saved
// and shown with the new entry marked.
TEST_F(Screens, GameOverAndTheNameEntryTakeTypedLetters) {
    const auto run = play(R"(key enter
down up
down left
down space
wait 390
up up
up left
up space
expect game-over
wait 100
screenshot game-over.png
key enter
expect name-entry
key b
type B
key o
type O
type X
key backspace
type B
screenshot name-entry.png
key enter
expect high-scores
screenshot high-scores-new.png
key escape
expect title
)",
                          {"--lives", "1"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("game-over");
    expectGolden("name-entry");
    expectGolden("high-scores-new");
    EXPECT_NE(read("data/highscores.json").find("\"BOB\""), std::string::npos)
        << read("data/highscores.json");
}

// A key held at death repeats into the name entry (a window sends each repeat with its letter):
// the script's "repeat" sends exactly that, and nothing is typed; Esc then keeps the score.
TEST_F(Screens, HeldKeysAreNotTypedAndEscKeepsTheScore) {
    const auto run = play(R"(key enter
down up
down left
down space
down f
wait 390
expect game-over
wait 100
key enter
expect name-entry
repeat f
repeat f
repeat g
key escape
expect high-scores
)",
                          {"--lives", "1"});
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_NE(read("data/highscores.json").find("\"name\": \"AAA\""), std::string::npos)
        << read("data/highscores.json");
}

// The mouse: hover moves the focus, a click activates the row under it, the wheel scrolls.
TEST_F(Screens, TheMouseHoversClicksAndScrolls) {
    keepReplays();
    // The title's rows are 22 pixels from y 136: PLAY, SCENES, REPLAYS, OPTIONS, HIGH SCORES, QUIT.
    const auto run = play(R"(move 320 214
screenshot hover.png
click 320 190
expect replays
wheel -3
click 320 99
expect replay
key escape
key escape
click 320 146
expect playing
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("hover");
}

// A game controller: the d-pad and the stick move the focus, A activates, B goes back, Start
// pauses. The title keeps its focus while a screen is over it.
TEST_F(Screens, AGamepadDrivesTheMenus) {
    const auto run = play(R"(pad dpad-down
pad a
expect scenes
pad b
expect title
stick 0 1
stick 0 0
pad a
expect replays
pad b
pad dpad-up
pad dpad-up
pad a
expect playing
pad start
expect paused
pad b
expect playing
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
}

// Back on the title asks first; Yes leaves with exit code 0, before the script's end.
TEST_F(Screens, QuitAsksFirst) {
    const auto run =
        play("key escape\nexpect quit-confirm\nkey down\nkey enter\nexpect nothing-after-quit\n");
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("nothing-after-quit"), std::string::npos);
}

// The theatre watches the newest replay (game-over.replay, 2308 ticks; its first markers are the
// first points at tick 48 and a life lost at 535). Each script opens it, lets it read the replay
// ahead (four frames), restarts it (Home: tick 0, playing; one tick passes) and pauses (tick 1).
const char* const kOpenTheatre = R"(key down down
key enter
expect replays
key enter
expect replay
wait 10
key home
key space
expect-tick 1
)";

// The keyboard: a tick forward and back, 5 seconds either way, marker to marker, the speed.
TEST_F(Screens, TheTheatreSeeksStepsAndJumpsByKeys) {
    keepReplays();
    const auto run = play(std::string(kOpenTheatre) + R"(key period period period
expect-tick 4
key comma
expect-tick 3
key right
expect-tick 303
key left
expect-tick 3
key page-down
expect-tick 48
key page-down
expect-tick 535
screenshot theatre.png
key page-up
expect-tick 48
key page-up
expect-tick 48
key up up
key space
wait 60
expect-tick 292
key escape
expect replays
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("theatre");
}

// The mouse: a click on the seek bar, a drag along it, a click near a marker lands on it, the
// transport buttons; x is a canvas column, the bar's track runs from column 6 to 633 at row 328.
TEST_F(Screens, TheTheatreScrubsAndJumpsByMouse) {
    keepReplays();
    const auto run = play(std::string(kOpenTheatre) + R"(click 320 328
expect-tick 1158
press 100 328
move 200 328
expect-tick 716
release 300 328
expect-tick 1084
move 18 328
screenshot theatre-marker.png
click 18 328
expect-tick 48
click 285 312
wait 30
expect-tick 79
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    expectGolden("theatre-marker");
}

// A game controller: A plays and pauses, Y and X step, the d-pad jumps 5 s, the shoulders go
// marker to marker.
TEST_F(Screens, TheTheatreAnswersAGamepad) {
    keepReplays();
    const auto run = play(std::string(kOpenTheatre) + R"(pad y
pad y
pad x
expect-tick 2
pad dpad-right
expect-tick 302
pad left-shoulder
expect-tick 48
pad right-shoulder
expect-tick 535
pad a
wait 9
pad a
expect-tick 545
pad b
expect replays
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
}

// H hides the bar and End goes to the last tick: the picture is then the verifier's golden frame
// of short.replay at tick 600, byte for byte (the browser test checks the same in the page).
TEST_F(Screens, TheTheatreHiddenAtTheEndDrawsTheVerifiersFrame) {
    keepReplays();
    const auto run = play(R"(key down down
key enter
expect replays
key down
key enter
expect replay
wait 3
key h
key end
expect-tick 600
screenshot end.png
)");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(read("end.png"), polar::testing::readFile(std::string(POLAR_REPLAY_DIR) + "/short-600.png"));
}

// The list: a replay is deleted only after Yes, and exported as a copy into the downloads folder.
TEST_F(Screens, TheReplayListDeletesAfterAskingAndExports) {
    keepReplays();
    const fs::path downloads = folder_ / "downloads";
    fs::create_directories(downloads);
    ::setenv("XDG_DOWNLOAD_DIR", downloads.c_str(), 1);
    const auto run = play(R"(key down down
key enter
expect replays
wait 3
screenshot replay-list.png
key delete
expect delete-confirm
screenshot delete-confirm.png
key enter
expect replays
key down
key e
key x
expect delete-confirm
key down
key enter
expect replays
)");
    ::unsetenv("XDG_DOWNLOAD_DIR");
    ASSERT_EQ(run.exitCode, 0) << run.err;
    EXPECT_TRUE(fs::exists(folder_ / "data/replays/2026-01-02_12-00-00.replay")) << "No keeps it";
    EXPECT_FALSE(fs::exists(folder_ / "data/replays/2026-01-01_12-00-00.replay")) << "Yes deletes it";
    EXPECT_EQ(read("downloads/polarcade-2026-01-01_12-00-00.replay"),
              polar::testing::readFile(std::string(POLAR_REPLAY_DIR) + "/short.replay"));
    EXPECT_NE(run.err.find("EXPORTED TO " + (downloads / "polarcade-2026-01-01_12-00-00.replay").string()),
              std::string::npos)
        << run.err;
    expectGolden("replay-list");
    expectGolden("delete-confirm");
}

// polarcade --replay DIR opens the theatre's list of that folder; back leaves the game.
TEST_F(Screens, AReplayFolderOpensItsList) {
    fs::create_directories(folder_ / "elsewhere");
    fs::copy_file(fs::path(POLAR_REPLAY_DIR) / "short.replay", folder_ / "elsewhere/short.replay");
    std::ofstream(folder_ / "script.txt", std::ios::binary)
        << "expect replays\nwait 2\nkey enter\nexpect replay\nwait 5\nexpect-tick 5\nkey escape\n"
           "expect replays\nkey escape\nexpect nothing-after-quit\n";
    const auto run = polar::testing::run(
        POLARCADE_EXE, {"--script", "script.txt", "--data", "data", "--replay", "elsewhere"}, folder_);
    EXPECT_EQ(run.exitCode, 0) << run.err;
    EXPECT_EQ(run.err.find("nothing-after-quit"), std::string::npos) << run.err;
}

TEST_F(Screens, AScriptMistakeNamesItsLineAndColumn) {
    auto run = play("wait 2\nkey enter flap\n");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("script.txt:2:11: unknown key \"flap\""), std::string::npos) << run.err;
    run = play("wait 2\nexpect playing\n");
    EXPECT_EQ(run.exitCode, 2);
    EXPECT_NE(run.err.find("script.txt:2:1: the screen on top is \"title\"; expected \"playing\""),
              std::string::npos)
        << run.err;
    run = play("jump 3\n");
    EXPECT_NE(run.err.find("script.txt:1:1: unknown command \"jump\""), std::string::npos) << run.err;
}

}  // namespace
}  // namespace polar::game
