// The rough edges a player met (issue 41), each driven through the path a player's input takes:
// platform events into the ScreenLoop, one frame at a time, as a window or a script delivers them.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "app/run/screen_loop.h"
#include "app/screens/title_screen.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using platform::Event;
using platform::Key;
using platform::KeyPressed;
using platform::KeyReleased;
using platform::TextEntered;

std::string readText(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

class RoughEdges : public ::testing::Test {
  protected:
    void SetUp() override { folder_ = polar::testing::freshTestFolder("polar-rough-edges"); }
    void TearDown() override {
        loop_.reset();
        context_.reset();
        fs::remove_all(folder_);
    }

    // The game's loop over the title, its data folder in the test's folder, seed 1.
    ScreenLoop& open(std::optional<int> lives = std::nullopt, std::vector<std::string> mods = {}) {
        AppOptions options;
        options.data = (folder_ / "data").string();
        options.seed = 1;
        options.lives = lives;
        options.mods = std::move(mods);
        context_.emplace(options, POLAR_ASSET_DIR);
        loop_.emplace(*context_, nullptr, "scenes/cave.json", [](Session&) { return makeTitleScreen(); });
        EXPECT_TRUE(loop_->ready());
        return *loop_;
    }
    void frame(std::vector<Event> events = {}) { ASSERT_FALSE(loop_->frame(events, 1.0 / 60)); }
    void wait(int frames) {
        for (int i = 0; i < frames; ++i) frame();
    }
    void press(Key key) { frame({KeyPressed{key, key}, KeyReleased{key, key}}); }
    const char* top() { return loop_->stack().top().name(); }

    // Play with one life, holding thrust, left and fire, until the game is over (the same game as
    // the screens test's: seed 1 scores before its one life is lost), then on to the name entry.
    // `keepHolding`: the keys stay held into the name entry, as a player's might at death.
    void playToTheNameEntry(bool keepHolding = false) {
        open(1);
        press(Key::Enter);
        ASSERT_STREQ(top(), "playing");
        // Space fires; F is held too, a letter key as a player's other hand might rest on.
        frame({KeyPressed{Key::Up, Key::Up}, KeyPressed{Key::Left, Key::Left},
               KeyPressed{Key::Space, Key::Space}, KeyPressed{Key::F, Key::F}});
        for (int i = 0; i < 60 * 60 && std::string(top()) == "playing"; ++i) frame();
        ASSERT_STREQ(top(), "game-over");
        if (!keepHolding)
            frame({KeyReleased{Key::Up, Key::Up}, KeyReleased{Key::Left, Key::Left},
                   KeyReleased{Key::Space, Key::Space}, KeyReleased{Key::F, Key::F}});
        wait(100);
        press(Key::Enter);
        ASSERT_STREQ(top(), "name-entry");
    }

    fs::path folder_;
    std::optional<AppContext> context_;
    std::optional<ScreenLoop> loop_;
};

// Esc on the name entry keeps the score under the letters typed so far, and shows the table.
TEST_F(RoughEdges, EscOnTheNameEntryKeepsTheScoreUnderTheLettersTyped) {
    ASSERT_NO_FATAL_FAILURE(playToTheNameEntry());
    const int score = loop_->session().games.player->score();
    ASSERT_GT(score, 0);
    frame({KeyPressed{Key::J, Key::J}, TextEntered{"j"}});
    frame({KeyPressed{Key::O, Key::O}, TextEntered{"o"}});
    EXPECT_NE(loop_->stack().top().helpLine(loop_->session()).find("ESC KEEPS IT AS JO"), std::string::npos)
        << loop_->stack().top().helpLine(loop_->session());
    press(Key::Escape);
    EXPECT_STREQ(top(), "high-scores") << "the table, with the score in it";
    const std::string saved = readText(folder_ / "data/highscores.json");
    const std::size_t entry = saved.find("\"name\": \"JO\"");
    ASSERT_NE(entry, std::string::npos) << saved;
    EXPECT_EQ(saved.find("\"score\": " + std::to_string(score) + ",", entry), saved.find("\"score\"", entry))
        << saved;
    press(Key::Escape);
    EXPECT_STREQ(top(), "title");
}

// With nothing typed, Esc keeps the score under the last name the player entered.
TEST_F(RoughEdges, EscWithNothingTypedKeepsTheLastNameUsed) {
    fs::create_directories(folder_ / "data");
    std::ofstream(folder_ / "data/highscores.json")
        << "{\"format\": 2, \"last_name\": \"ZED\", \"tables\": []}\n";
    ASSERT_NO_FATAL_FAILURE(playToTheNameEntry());
    press(Key::Escape);
    EXPECT_STREQ(top(), "high-scores");
    EXPECT_NE(readText(folder_ / "data/highscores.json").find("\"name\": \"ZED\""), std::string::npos);
}

// Enter on the last letter saves the name and shows the table with the new entry in it.
TEST_F(RoughEdges, EnterOnTheNameShowsTheTable) {
    ASSERT_NO_FATAL_FAILURE(playToTheNameEntry());
    frame({KeyPressed{Key::A, Key::A}, TextEntered{"a"}});
    frame({KeyPressed{Key::B, Key::B}, TextEntered{"b"}});
    frame({KeyPressed{Key::C, Key::C}, TextEntered{"c"}});
    press(Key::Enter);
    EXPECT_STREQ(top(), "high-scores");
    EXPECT_NE(readText(folder_ / "data/highscores.json").find("\"name\": \"ABC\""), std::string::npos);
}

// Keys held when the game ended repeat into the name entry: their repeats type nothing.
TEST_F(RoughEdges, KeysHeldAtDeathAreNotTypedIntoTheName) {
    ASSERT_NO_FATAL_FAILURE(playToTheNameEntry(true));
    for (int i = 0; i < 5; ++i) {
        frame({KeyPressed{Key::F, Key::F, platform::kModNone, true}, TextEntered{"f"}});
        frame({KeyPressed{Key::G, Key::G, platform::kModNone, true}, TextEntered{"g"}});
    }
    frame({KeyReleased{Key::F, Key::F}, KeyReleased{Key::G, Key::G}});
    frame({KeyPressed{Key::F, Key::F}, TextEntered{"f"}});  // pressed again: typed
    press(Key::Enter);
    press(Key::Enter);
    EXPECT_STREQ(top(), "high-scores");
    const std::string saved = readText(folder_ / "data/highscores.json");
    EXPECT_NE(saved.find("\"name\": \"FAA\""), std::string::npos) << saved;
}

// Enter on a volume raises it a step and stops at 100 %: it never jumps back to 0.
TEST_F(RoughEdges, EnterOnAVolumeStopsAtTheTop) {
    open();
    press(Key::Down);
    press(Key::Down);
    press(Key::Down);
    press(Key::Enter);
    ASSERT_STREQ(top(), "options");
    EXPECT_EQ(loop_->session().preferences.masterVolume, 80);
    for (int i = 0; i < 4; ++i) press(Key::Enter);
    EXPECT_EQ(loop_->session().preferences.masterVolume, 100);
    press(Key::Left);
    EXPECT_EQ(loop_->session().preferences.masterVolume, 90);
}

// The title's hint names fire's key as bound (remapped on the Options screen, by keys), then the
// pad's buttons once a pad is used, then the touch controls once the page says a phone is in use.
TEST_F(RoughEdges, HintsFollowTheBindingsAndTheDevice) {
    std::optional<Device> page;
    open();
    context_->options.deviceOfPage = [&page] { return page; };
    auto hint = [&] { return loop_->stack().top().helpLine(loop_->session()); };
    EXPECT_NE(hint().find("SPACE FIRES"), std::string::npos) << hint();
    press(Key::Down);
    press(Key::Down);
    press(Key::Down);
    press(Key::Enter);
    ASSERT_STREQ(top(), "options");
    // The rows: 4 volumes and toggles, fullscreen, scaling, frame time, shake, flashes, hold
    // fire, speed (11), then two keys for each of turn left, turn right, thrust, then fire's first.
    for (int i = 0; i < 11 + 6; ++i) press(Key::Down);
    press(Key::Enter);
    press(Key::F);
    EXPECT_EQ(loop_->session().input.bindings().keys(BoundAction::Fire)[0], Key::F);
    press(Key::Escape);
    ASSERT_STREQ(top(), "title");
    EXPECT_EQ(hint().find("SPACE FIRES"), std::string::npos) << hint();
    EXPECT_NE(hint().find("F FIRES"), std::string::npos) << hint();
    frame({platform::GamepadButtonPressed{1, platform::GamepadButton::DpadDown},
           platform::GamepadButtonReleased{1, platform::GamepadButton::DpadDown}});
    EXPECT_NE(hint().find("A FIRES"), std::string::npos) << hint();
    page = Device::Touch;
    frame();
    EXPECT_NE(hint().find("TOUCH"), std::string::npos) << hint();
    press(Key::Down);  // a touch screen's controls send keys: the page alone says what is in use
    EXPECT_NE(hint().find("TOUCH"), std::string::npos) << hint();
}

// F5 when the edit was already reloaded by itself says the bounds are current, never "nothing".
TEST_F(RoughEdges, F5AfterAnAutomaticReloadSaysTheBoundsAreCurrent) {
    const fs::path mod = folder_ / "mod";
    fs::create_directories(mod / "sprites");
    const fs::path bounds = mod / "sprites/rock-large-1.bounds.json";
    fs::copy_file(fs::path(POLAR_ASSET_DIR) / "sprites/rock-large-1.bounds.json", bounds);
    open(std::nullopt, {mod.string()});
    wait(5);
    std::ofstream(bounds, std::ios::binary) << "{\"format\": 1, \"radii\": [{\"samples\": [[0, 20]]}]}\n";
    fs::last_write_time(bounds, fs::file_time_type::clock::now() + std::chrono::seconds(5));
    wait(HotReload::kLookEvery + 1);
    ASSERT_NE(context_->hotReload.notice().find("reloaded"), std::string::npos)
        << context_->hotReload.notice();
    press(Key::F5);
    const std::string notice = context_->hotReload.notice();
    EXPECT_EQ(notice.rfind("F5: the bounds are already current", 0), 0u) << notice;
    EXPECT_NE(notice.find("rock-large-1.bounds.json was reloaded by itself"), std::string::npos) << notice;
}

// Hold fire: one press starts firing, the next stops it.
TEST_F(RoughEdges, HoldFireFiresFromOnePressToTheNext) {
    open();
    Settings settings;
    settings.holdFire = true;
    loop_->session().follow(settings);
    press(Key::Enter);
    ASSERT_STREQ(top(), "playing");
    auto shotsIn = [&](int frames) {
        int shots = 0;
        for (int i = 0; i < frames; ++i) {
            frame();
            for (const GameEvent& e : loop_->session().games.player->events())
                shots += e.type == GameEvent::Shot;
        }
        return shots;
    };
    EXPECT_EQ(shotsIn(30), 0);
    press(Key::Space);
    EXPECT_GE(shotsIn(60), 4) << "firing with no key held";
    press(Key::Space);
    shotsIn(2);
    EXPECT_EQ(shotsIn(60), 0) << "stopped by the second press";
}

// The game-speed assist starts the next game at that speed and records it; its score goes to a
// table of its own.
TEST_F(RoughEdges, TheSpeedAssistIsRecordedAndKeptApart) {
    open();
    Settings settings;
    settings.gameSpeed = 70;
    loop_->session().follow(settings);
    press(Key::Enter);
    ASSERT_STREQ(top(), "playing");
    EXPECT_EQ(loop_->session().games.player->speed(), 70);
    EXPECT_EQ(loop_->session().scores.selected().speed, 70);
    wait(30);
    press(Key::Escape);
    ASSERT_STREQ(top(), "paused");
    for (int i = 0; i < 3; ++i) press(Key::Down);  // QUIT TO TITLE
    press(Key::Enter);
    ASSERT_STREQ(top(), "title");
    int replays = 0;
    for (const auto& entry : fs::directory_iterator(folder_ / "data/replays")) {
        const std::string text = readText(entry.path());
        EXPECT_NE(text.find("\nspeed 70\n"), std::string::npos) << text.substr(0, 400);
        EXPECT_NE(text.find("\nrules " + std::to_string(kRulesVersion) + "\n"), std::string::npos);
        ++replays;
    }
    EXPECT_EQ(replays, 1);
}

// Presentation never feeds the rules: the player's game hashes the same, tick for tick, with every
// effect at full and with the shake and flashes off, while the pictures differ.
TEST_F(RoughEdges, TheStateHashIsTheSameWithEveryEffectOnOrOff) {
    std::vector<std::uint64_t> hashes[2];
    std::size_t differingFrames = 0;
    std::vector<std::vector<std::uint32_t>> pictures[2];
    for (int run = 0; run < 2; ++run) {
        loop_.reset();
        context_.reset();
        fs::remove_all(folder_ / "data");
        open();
        Settings settings;
        settings.screenShake = run == 0 ? 100 : 0;
        settings.flashes = run == 0 ? 100 : 0;
        loop_->session().follow(settings);
        press(Key::Enter);
        frame({KeyPressed{Key::Left, Key::Left}, KeyPressed{Key::Space, Key::Space}});
        for (int i = 0; i < 600; ++i) {
            if (i % 120 == 0)
                frame({KeyPressed{Key::Up, Key::Up}});
            else if (i % 120 == 10)
                frame({KeyReleased{Key::Up, Key::Up}});
            else
                frame();
            ASSERT_TRUE(loop_->session().games.player);
            hashes[run].push_back(loop_->session().games.player->hash());
            const render::Canvas& canvas = context_->canvas;
            std::vector<std::uint32_t> picture;
            for (int y = 0; y < canvas.height(); y += 2)
                for (int x = 0; x < canvas.width(); x += 2) picture.push_back(canvas.pixel(x, y).argb());
            pictures[run].push_back(std::move(picture));
        }
    }
    ASSERT_EQ(hashes[0].size(), hashes[1].size());
    for (std::size_t t = 0; t < hashes[0].size(); ++t) ASSERT_EQ(hashes[0][t], hashes[1][t]) << "frame " << t;
    for (std::size_t t = 0; t < pictures[0].size(); ++t) differingFrames += pictures[0][t] != pictures[1][t];
    EXPECT_GT(differingFrames, 10u) << "the effects' settings changed the picture";
}

}  // namespace
}  // namespace polar::game
