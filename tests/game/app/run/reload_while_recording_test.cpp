// Hot reload in the middle of a recorded game: the recording stops at once, the player is told on
// screen which file and why, and no .replay.part is left behind for the next start.
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
using platform::Key;

std::vector<std::string> filesIn(const fs::path& folder) {
    std::vector<std::string> names;
    std::error_code ec;
    for (const auto& entry : fs::directory_iterator(folder, ec))
        names.push_back(entry.path().filename().string());
    return names;
}

TEST(ReloadWhileRecording, StopsTheRecordingVisiblyAndLeavesNoPart) {
    const fs::path folder = polar::testing::freshTestFolder("polar-reload-recording");
    const fs::path mod = folder / "mod";
    fs::create_directories(mod / "sprites");
    const fs::path bounds = mod / "sprites/rock-large-1.bounds.json";
    fs::copy_file(fs::path(POLAR_ASSET_DIR) / "sprites/rock-large-1.bounds.json", bounds);
    AppOptions options;
    options.data = (folder / "data").string();
    options.seed = 1;
    options.mods = {mod.string()};
    AppContext context(options, POLAR_ASSET_DIR);
    ScreenLoop loop(context, nullptr, "scenes/cave.json", [](Session&) { return makeTitleScreen(); });
    ASSERT_TRUE(loop.ready());
    auto frame = [&](std::vector<platform::Event> events = {}) {
        ASSERT_FALSE(loop.frame(events, 1.0 / 60));
    };
    frame({platform::KeyPressed{Key::Enter, Key::Enter}});
    ASSERT_STREQ(loop.stack().top().name(), "playing");
    for (int i = 0; i < 30; ++i) frame();
    ASSERT_TRUE(loop.session().recorder.recording());
    const std::vector<std::string> during = filesIn(folder / "data/replays");
    ASSERT_EQ(during.size(), 1u);
    EXPECT_NE(during[0].find(".replay.part"), std::string::npos);

    std::ofstream(bounds, std::ios::binary) << "{\"format\": 1, \"radii\": [{\"samples\": [[0, 20]]}]}\n";
    fs::last_write_time(bounds, fs::file_time_type::clock::now() + std::chrono::seconds(5));
    frame({platform::KeyPressed{Key::F5, Key::F5}});  // F5: look now
    ASSERT_TRUE(loop.session().games.player->modified()) << "the edit reached the player's game";
    EXPECT_FALSE(loop.session().recorder.recording());
    EXPECT_TRUE(filesIn(folder / "data/replays").empty()) << "no .part is left for the next start";
    EXPECT_TRUE(loop.session().notice.fresh());
    EXPECT_NE(loop.session().notice.text().find("RECORDING STOPPED"), std::string::npos)
        << loop.session().notice.text();
    EXPECT_NE(loop.session().notice.text().find("rock-large-1.bounds.json was reloaded"), std::string::npos)
        << loop.session().notice.text();
    for (int i = 0; i < 10; ++i) frame();  // the game goes on, unrecorded
    EXPECT_STREQ(loop.stack().top().name(), "playing");
    fs::remove_all(folder);
}

}  // namespace
}  // namespace polar::game
