// The overlays' one layout rule: boxes stacked from their corners never share a pixel, a box with
// no room left is not placed, and on every screen the frame's overlays (the replay bar, the help
// line and the message over it, the debug panel, the frame time, the notices) are drawn in
// disjoint boxes.
#include "app/hud/overlay_layout.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "app/run/screen_loop.h"
#include "app/screens/title_screen.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;
using platform::Key;

void expectDisjoint(const std::vector<PixelRect>& boxes, const std::string& where) {
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        EXPECT_GE(boxes[i].x, 0) << where;
        EXPECT_GE(boxes[i].y, 0) << where;
        EXPECT_LE(boxes[i].x + boxes[i].width, 640) << where;
        EXPECT_LE(boxes[i].y + boxes[i].height, 360) << where;
        for (std::size_t j = i + 1; j < boxes.size(); ++j)
            EXPECT_FALSE(boxes[i].overlaps(boxes[j])) << where << ": boxes " << i << " and " << j;
    }
}

TEST(OverlayLayout, BoxesStackFromTheirCornersAndNeverOverlap) {
    OverlayLayout layout(640, 360);
    const auto bar = layout.place(Corner::BottomLeft, 1000, 12);  // cut to the screen's width
    ASSERT_TRUE(bar);
    EXPECT_EQ(*bar, (PixelRect{4, 344, 632, 12}));
    const auto panel = layout.place(Corner::BottomLeft, 300, 60);
    ASSERT_TRUE(panel);
    EXPECT_EQ(panel->y + panel->height + OverlayLayout::kGap, bar->y) << "stacked right above the bar";
    const auto right = layout.place(Corner::BottomRight, 100, 10);  // beside the panel, above the bar
    ASSERT_TRUE(right);
    EXPECT_EQ(right->x, 640 - 4 - 100);
    EXPECT_LT(right->y + right->height, bar->y);
    const auto wide = layout.place(Corner::BottomLeft, 632, 20);  // clears both
    ASSERT_TRUE(wide);
    EXPECT_LT(wide->y + wide->height, std::min(panel->y, right->y));
    EXPECT_TRUE(layout.place(Corner::TopRight, 50, 10));
    EXPECT_FALSE(layout.place(Corner::BottomLeft, 632, 300)) << "no room: not placed";
    expectDisjoint(layout.boxes(), "corners");
    EXPECT_EQ(layout.boxes().size(), 5u);
}

// Drives the screens in this process, as polarcade --script does, and looks at the overlays of
// every screen with all of them asked for: the debug panel, the frame time, a notice, and the
// replay bar.
TEST(OverlayLayout, EveryScreenDrawsItsOverlaysInDisjointBoxes) {
    const fs::path folder = polar::testing::freshTestFolder("polar-overlays");
    fs::create_directories(folder / "data/replays");
    fs::copy_file(fs::path(POLAR_REPLAY_DIR) / "short.replay",
                  folder / "data/replays/2026-01-01_12-00-00.replay");
    AppOptions options;
    options.data = (folder / "data").string();
    options.seed = 1;
    AppContext context(options, POLAR_ASSET_DIR);
    ScreenLoop loop(context, nullptr, "scenes/cave.json", [](Session&) { return makeTitleScreen(); });
    ASSERT_TRUE(loop.ready());
    auto press = [&](Key key) {
        ASSERT_FALSE(loop.frame({platform::KeyPressed{key, key}, platform::KeyReleased{key, key}}, 1.0 / 60));
    };
    auto check = [&](const char* screen, std::size_t expectedBoxes) {
        ASSERT_STREQ(loop.stack().top().name(), screen);
        loop.session().notice.tell("A NOTICE LONG ENOUGH TO WRAP: " + std::string(150, 'x'));
        ASSERT_FALSE(loop.frame({}, 1.0 / 60));
        const OverlayLayout layout = loop.drawOverlays();
        expectDisjoint(layout.boxes(), screen);
        EXPECT_EQ(layout.boxes().size(), expectedBoxes) << screen << ": every overlay asked for has its box";
    };
    press(Key::F1);                       // the debug panel on every screen from here on
    loop.session().showFrameTime = true;  // and the frame-time line (Options)
    // A menu's help line is a box of the layout too (+1 beside the panel, the frame time and the
    // notice), and so is a screen's message over it.
    check("title", 4);
    press(Key::Escape);
    check("quit-confirm", 4);
    press(Key::Escape);
    press(Key::Down);
    press(Key::Enter);
    check("scenes", 4);
    press(Key::Escape);
    press(Key::Down);
    press(Key::Enter);
    check("replays", 4);
    press(Key::Delete);
    check("delete-confirm", 4);
    press(Key::Escape);
    press(Key::Enter);
    check("replay", 4);  // + the theatre's bar: its buttons, seek bar and lines
    press(Key::Escape);
    press(Key::Escape);
    press(Key::Down);
    press(Key::Enter);
    check("options", 4);
    // The options' messages: the prompt for a key, then a refusal in red, each over the help line;
    // the refusal goes after four seconds.
    for (int i = 0; i < 11; ++i) press(Key::Down);
    press(Key::Enter);  // turn left's first key
    ASSERT_TRUE(loop.stack().top().message(loop.session()));
    check("options", 5);
    press(Key::Right);  // turn right's key: refused
    ASSERT_TRUE(loop.stack().top().message(loop.session()));
    EXPECT_EQ(loop.stack().top().message(loop.session())->text.rfind("REFUSED", 0), 0u);
    check("options", 5);
    for (int i = 0; i < 240; ++i) ASSERT_FALSE(loop.frame({}, 1.0 / 60));
    EXPECT_FALSE(loop.stack().top().message(loop.session())) << "a refusal does not linger";
    check("options", 4);
    press(Key::Escape);
    press(Key::Down);
    press(Key::Enter);
    check("high-scores", 4);
    press(Key::Escape);
    for (int i = 0; i < 4; ++i) press(Key::Up);
    press(Key::Enter);
    check("playing", 3);
    press(Key::P);
    check("paused", 3);
    fs::remove_all(folder);
}

}  // namespace
}  // namespace polar::game
