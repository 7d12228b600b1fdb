#include "app/input/settings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using platform::GamepadButton;
using platform::Key;

class SettingsFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = polar::testing::freshTestFolder("polar-settings");
        path_ = (folder_ / "settings.json").string();
    }
    void TearDown() override { fs::remove_all(folder_); }
    void write(const std::string& text) { std::ofstream(path_, std::ios::binary) << text; }
    static std::string read(const std::string& path) {
        std::ifstream in(path, std::ios::binary);
        std::ostringstream out;
        out << in.rdbuf();
        return out.str();
    }
    // Loads `text` as settings.json and returns the problem's message; checks that the defaults are
    // used, the file is kept byte for byte as settings.json.bad and a save writes a fresh file.
    std::string problemOf(const std::string& text) {
        write(text);
        SettingsFile file = SettingsFile::load(path_);
        EXPECT_EQ(file.settings(), Settings{});
        EXPECT_FALSE(fs::exists(path_));
        EXPECT_EQ(read(path_ + ".bad"), text);
        std::optional<std::string> message = file.takeProblem();
        EXPECT_EQ(file.takeProblem(), std::nullopt);  // once
        EXPECT_EQ(file.save(Settings{}), std::nullopt);
        EXPECT_EQ(read(path_ + ".bad"), text);
        EXPECT_TRUE(parseSettings({path_, read(path_)}).ok());
        return message.value_or("(no problem)");
    }
    // The message for a file whose one line `line` (after "format") is bad.
    std::string problemOfKey(const std::string& line) {
        return problemOf("{\n  \"format\": 1,\n  " + line + "\n}\n");
    }

    fs::path folder_;
    std::string path_;
};

Settings changed() {
    Settings s;
    s.masterVolume = 35;
    s.effectsVolume = 0;
    s.musicVolume = 100;
    s.mute = true;
    s.fullscreen = true;
    s.windowWidth = 1000;
    s.windowHeight = 600;
    s.windowX = -20;
    s.windowY = 40;
    s.scaleMode = ScaleMode::Integer;
    s.showFrameTime = true;
    s.screenShake = 50;
    s.flashes = 0;
    s.holdFire = true;
    s.gameSpeed = 70;
    EXPECT_EQ(s.bindings.bindKey(BoundAction::Fire, 1, Key::F), std::nullopt);
    s.bindings.clearKey(BoundAction::Thrust, 1);
    EXPECT_EQ(s.bindings.bindButton(BoundAction::Thrust, 1, GamepadButton::RightShoulder), std::nullopt);
    s.bindings.clearButton(BoundAction::Pause, 0);
    return s;
}

TEST_F(SettingsFileTest, MissingFileGivesTheDefaultsAndNoProblem) {
    SettingsFile file = SettingsFile::load(path_);
    EXPECT_EQ(file.settings(), Settings{});
    EXPECT_EQ(file.takeProblem(), std::nullopt);
    EXPECT_FALSE(fs::exists(path_));
}

TEST_F(SettingsFileTest, RoundTripKeepsEverySetting) {
    const Settings s = changed();
    ASSERT_NE(s, Settings{});
    SettingsFile file = SettingsFile::load(path_);
    ASSERT_EQ(file.save(s), std::nullopt);
    SettingsFile again = SettingsFile::load(path_);
    EXPECT_EQ(again.takeProblem(), std::nullopt);
    EXPECT_EQ(again.settings(), s);
    EXPECT_EQ(settingsToJson(again.settings()), read(path_));
    // The defaults round-trip too, and a window with no position stays unplaced.
    ASSERT_EQ(file.save(Settings{}), std::nullopt);
    EXPECT_EQ(SettingsFile::load(path_).settings(), Settings{});
}

TEST_F(SettingsFileTest, SaveWritesAtomicallyAndAFailedWriteKeepsTheOldFile) {
    SettingsFile file = SettingsFile::load(path_);
    ASSERT_EQ(file.save(changed()), std::nullopt);
    const std::string before = read(path_);
    Settings louder = changed();
    louder.masterVolume = 90;
    std::optional<Error> error =
        file.save(louder, [](AtomicWriteStep step) { return step == AtomicWriteStep::kWrite; });
    ASSERT_TRUE(error.has_value());
    EXPECT_EQ(read(path_), before);
    EXPECT_EQ(file.save(louder), std::nullopt);
    EXPECT_EQ(SettingsFile::load(path_).settings().masterVolume, 90);
}

TEST_F(SettingsFileTest, KeysLeftOutKeepTheirDefaults) {
    write("{\"format\": 1, \"music_volume\": 5}");
    Settings expected;
    expected.musicVolume = 5;
    EXPECT_EQ(SettingsFile::load(path_).settings(), expected);
}

TEST_F(SettingsFileTest, WrongType) {
    EXPECT_EQ(problemOfKey("\"mute\": \"yes\""),
              path_ +
                  ":3:11: found a string; expected true or false; the defaults are used "
                  "and the file is kept as " +
                  path_ + ".bad");
}

TEST_F(SettingsFileTest, UnknownKey) {
    EXPECT_EQ(
        problemOfKey("\"volume\": 50"),
        path_ +
            ":3:3: unknown key \"volume\"; expected one of \"format\", \"master_volume\", "
            "\"effects_volume\", \"music_volume\", \"mute\", \"fullscreen\", \"window\", \"scaling\", "
            "\"show_frame_time\", \"screen_shake\", \"flashes\", \"hold_fire\", \"game_speed\", \"keys\", "
            "\"pad\"; the defaults are used and the file is kept as " +
            path_ + ".bad");
}

TEST_F(SettingsFileTest, OutOfRangeValues) {
    EXPECT_EQ(
        problemOfKey("\"master_volume\": 101"),
        path_ +
            ":3:20: volume 101 is out of range; expected a whole percent from 0 to 100; the defaults are "
            "used and the file is kept as " +
            path_ + ".bad");
    fs::remove(path_ + ".bad");
    std::string m = problemOfKey("\"window\": {\"width\": 20, \"height\": 600}");
    EXPECT_NE(m.find(":3:23: 20 is out of range; expected a whole number of pixels from 160 to 16384"),
              std::string::npos)
        << m;
    fs::remove(path_ + ".bad");
    m = problemOfKey("\"game_speed\": 45");
    EXPECT_NE(m.find(":3:17: 45 is out of range; expected a whole percent from 50 to 100"), std::string::npos)
        << m;
    fs::remove(path_ + ".bad");
    m = problemOfKey("\"screen_shake\": 120");
    EXPECT_NE(m.find(":3:19: 120 is out of range; expected a whole percent from 0 to 100"), std::string::npos)
        << m;
}

TEST_F(SettingsFileTest, BadBindings) {
    std::string m = problemOfKey("\"keys\": {\"fire\": [\"space\", \"w\"], \"thrust\": [\"w\"]}");
    EXPECT_NE(m.find(":3:47: w already gives fire; expected each key bound to one action"), std::string::npos)
        << m;
    fs::remove(path_ + ".bad");
    m = problemOfKey("\"keys\": {\"fire\": [\"banana\"]}");
    EXPECT_NE(m.find(":3:21: unknown key \"banana\"; expected a key name such as \"a\""), std::string::npos)
        << m;
    fs::remove(path_ + ".bad");
    m = problemOfKey("\"pad\": {\"jump\": [\"a\"]}");
    EXPECT_NE(m.find(":3:11: unknown key \"jump\""), std::string::npos) << m;
}

TEST_F(SettingsFileTest, TruncatedFile) {
    std::string m = problemOf("{\n  \"format\": 1,\n  \"master_volume\": 4");
    EXPECT_EQ(m.rfind(path_ + ":3:", 0), 0u) << m;
    EXPECT_NE(m.find("kept as " + path_ + ".bad"), std::string::npos) << m;
}

TEST_F(SettingsFileTest, WrongFormatNumber) {
    std::string m = problemOf("{\"format\": 2}");
    EXPECT_NE(m.find(":1:12: unsupported format; expected \"format\": 1"), std::string::npos) << m;
}

TEST_F(SettingsFileTest, UnreadableFileIsSetAsideAndNeverOverwritten) {
    fs::create_directories(path_);  // a folder where the file should be: it exists, it cannot be read
    std::ofstream(fs::path(path_) / "keep.txt") << "mine";
    SettingsFile file = SettingsFile::load(path_);
    EXPECT_EQ(file.settings(), Settings{});
    EXPECT_EQ(file.takeProblem(), path_ +
                                      ": cannot be read; expected a readable settings file; "
                                      "the defaults are used and the file is kept as " +
                                      path_ + ".bad");
    EXPECT_EQ(read(path_ + ".bad/keep.txt"), "mine");
    EXPECT_EQ(file.save(changed()), std::nullopt);
    EXPECT_EQ(SettingsFile::load(path_).settings(), changed());
}

TEST_F(SettingsFileTest, AnEarlierBadFileIsNotOverwritten) {
    write("{\"format\": 1, \"mute\": 3}");
    SettingsFile::load(path_);
    write("{\"format\": 1, \"mute\": 4}");
    SettingsFile second = SettingsFile::load(path_);
    EXPECT_EQ(read(path_ + ".bad"), "{\"format\": 1, \"mute\": 3}");
    EXPECT_EQ(read(path_ + ".bad-2"), "{\"format\": 1, \"mute\": 4}");
    EXPECT_EQ(second.setAside(), path_ + ".bad-2");
}

// The window's ranges (settings.h): each side 160 to 16384, each offset within ±65536; both ends
// are accepted and one past either is refused at the value.
TEST_F(SettingsFileTest, WindowSizesAndPlacesAtTheirBoundaries) {
    write(R"({"format": 1, "window": {"width": 160, "height": 16384, "x": -65536, "y": 65536}})");
    SettingsFile edges = SettingsFile::load(path_);
    ASSERT_EQ(edges.takeProblem(), std::nullopt);
    EXPECT_EQ(edges.settings().windowWidth, 160);
    EXPECT_EQ(edges.settings().windowHeight, 16384);
    EXPECT_EQ(edges.settings().windowX, -65536);
    EXPECT_EQ(edges.settings().windowY, 65536);
    fs::remove(path_);
    struct Case {
        const char* window;
        const char* message;
    };
    for (const Case& c : std::initializer_list<Case>{
             {R"({"width": 159, "height": 600})",
              ":3:23: 159 is out of range; expected a whole number of pixels from 160 to 16384"},
             {R"({"width": 800, "height": 159})", ":3:38: 159 is out of range"},
             {R"({"width": 16385, "height": 600})", ":3:23: 16385 is out of range"},
             {R"({"width": 800, "height": 16385})", ":3:38: 16385 is out of range"},
             {R"({"x": -65537, "y": 0})",
              ":3:19: -65537 is out of range; expected a whole number of pixels from -65536 to 65536"},
             {R"({"x": 65537, "y": 0})", ":3:19: 65537 is out of range"},
             {R"({"x": 0, "y": -65537})", ":3:27: -65537 is out of range"},
             {R"({"x": 0, "y": 65537})", ":3:27: 65537 is out of range"},
             {R"({"x": 10})", ":3:13: a window position needs both x and y"},
             {R"({"y": 10})", ":3:13: a window position needs both x and y"}}) {
        std::string m = problemOfKey(std::string("\"window\": ") + c.window);
        EXPECT_NE(m.find(c.message), std::string::npos) << c.window << "\n" << m;
        fs::remove(path_ + ".bad");
    }
}

// Bindings from the file (bindings.h): up to two keys and two buttons an action, each key and each
// button giving one action, the menus' keys and the pad's way back never bound; an action the
// table leaves out has nothing bound.
TEST_F(SettingsFileTest, EachKeyAndButtonIsBoundOnceAndTheMenusKeepTheirs) {
    struct Case {
        const char* line;
        const char* message;
    };
    for (const Case& c : std::initializer_list<Case>{
             {R"("keys": {"fire": ["space", "f", "g"]})",
              ":3:20: 3 keys for one action; expected an array of up to 2 key names"},
             {R"("keys": {"fire": ["f", "f"]})", ":3:26: f is already in the other slot"},
             {R"("keys": {"thrust": ["up"], "fire": ["up"]})", ": up already gives thrust"},
             {R"("keys": {"fire": ["f"], "thrust": ["f"]})", ":3:38: f already gives fire"},
             {R"("pad": {"pause": ["x"], "fire": ["x"]})", ":3:36: x already gives pause"},
             {R"("pad": {"fire": ["a", "b", "x"]})", ":3:19: 3 buttons for one action"},
             {R"("pad": {"fire": ["x"], "pause": ["x"]})", ": x already gives fire"},
             {R"("pad": {"fire": ["guide"]})", ":3:20: guide is the way back"},
             {R"("pad": {"fire": ["back"]})", ":3:20: back is the way back"},
             {R"("keys": {"fire": ["escape"]})", ":3:21: Esc is the way back"},
             {R"("keys": {"fire": ["enter"]})", ":3:21: Enter confirms in the menus"},
             {R"("keys": {"fire": ["keypad-enter"]})", ":3:21: Enter confirms in the menus"},
             {R"("keys": {"fire": ["f1"]})", ":3:21: F1 shows the debug panel"},
             {R"("keys": {"fire": ["f5"]})", ":3:21: F5 reloads the bounds files"},
             {R"("keys": {"fire": ["f11"]})", ":3:21: F11 toggles fullscreen"},
             {R"("mute": true, "mute": false)", ":3:17: duplicate key \"mute\""}}) {
        std::string m = problemOfKey(c.line);
        EXPECT_NE(m.find(c.message), std::string::npos) << c.line << "\n" << m;
        fs::remove(path_ + ".bad");
    }
    write(R"({"format": 1, "keys": {"fire": ["f", "g"]}, "pad": {"pause": ["x", "y"]}})");
    SettingsFile file = SettingsFile::load(path_);
    ASSERT_EQ(file.takeProblem(), std::nullopt);
    const Bindings& b = file.settings().bindings;
    EXPECT_EQ(b.keys(BoundAction::Fire), (Bindings::Keys{Key::F, Key::G}));
    for (BoundAction a :
         {BoundAction::TurnLeft, BoundAction::TurnRight, BoundAction::Thrust, BoundAction::Pause})
        EXPECT_EQ(b.keys(a), (Bindings::Keys{Key::Unknown, Key::Unknown})) << boundActionName(a);
    EXPECT_EQ(b.buttons(BoundAction::Pause), (Bindings::Buttons{GamepadButton::X, GamepadButton::Y}));
    EXPECT_EQ(b.buttons(BoundAction::Fire), (Bindings::Buttons{GamepadButton::Count, GamepadButton::Count}));
    EXPECT_EQ(b.actionOfKey(Key::Space), std::nullopt) << "a table given replaces the defaults whole";
}

}  // namespace
}  // namespace polar::game
