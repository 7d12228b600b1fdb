#include "polar/platform/window.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace polar::platform {
namespace {

using render::Canvas;
using render::Color;

// SDL's "dummy" video driver gives a real window surface without any display, so these tests run
// anywhere (CI has no X11). Naming it in SDL_VIDEODRIVER is what makes it count as seen.
class WindowTest : public ::testing::Test {
  protected:
    void SetUp() override { ::setenv("SDL_VIDEODRIVER", "dummy", 1); }
};

std::uint32_t rgb(const Canvas& canvas, int x, int y) {
    return canvas.row(y)[x] & 0x00FFFFFFu;
}

TEST(WindowFit, WholeFactorsWhenTheyFillMostOfTheWindow) {
    auto p = Window::fit(320, 180, 1280, 720);
    EXPECT_EQ(p.width, 1280);
    EXPECT_EQ(p.height, 720);
    EXPECT_EQ(p.x, 0);
    p = Window::fit(320, 180, 1000, 720);  // f = 3.125 → 3, centred, letterboxed
    EXPECT_EQ(p.width, 960);
    EXPECT_EQ(p.height, 540);
    EXPECT_EQ(p.x, 20);
    EXPECT_EQ(p.y, 90);
}

TEST(WindowFit, FractionalWhenAWholeFactorWouldWasteTooMuch) {
    auto p = Window::fit(1280, 720, 1920, 1080);  // f = 1.5: 1× would leave a third unused
    EXPECT_EQ(p.width, 1920);
    EXPECT_EQ(p.height, 1080);
    p = Window::fit(1280, 720, 640, 480);  // smaller than the canvas: scaled down, letterboxed
    EXPECT_EQ(p.width, 640);
    EXPECT_EQ(p.height, 360);
    EXPECT_EQ(p.y, 60);
    EXPECT_EQ(Window::fit(10, 10, 0, 5).width, 0);
}

TEST_F(WindowTest, ADriverAskedForByNameIsADisplay) {
    EXPECT_FALSE(Window::displayProblem().has_value());
}

TEST_F(WindowTest, PresentScalesByWholePixelsWithBlackBorders) {
    auto window = Window::open({"test", 4, 3, 1});
    ASSERT_TRUE(window.ok()) << window.error().message();
    Window& w = **window;
    w.setSize(10, 8);  // f = min(2.5, 2.67) → k = 2: an 8 × 6 picture at (1, 1)
    Canvas canvas(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            canvas.setPixel(x, y, Color{std::uint8_t(40 * x + 1), std::uint8_t(50 * y + 1), 7, 255});
    w.present(canvas);
    const Canvas shown = w.capture();
    ASSERT_EQ(shown.width(), 10);
    ASSERT_EQ(shown.height(), 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 10; ++x) {
            const bool inside = x >= 1 && x < 9 && y >= 1 && y < 7;
            const std::uint32_t want = inside ? rgb(canvas, (x - 1) / 2, (y - 1) / 2) : 0u;
            ASSERT_EQ(rgb(shown, x, y), want) << x << "," << y;
        }
    EXPECT_EQ(w.windowToCanvas(1, 1), Vec2(0.25, 0.25));
    EXPECT_EQ(w.windowToCanvas(8, 6), Vec2(3.75, 2.75));
}

TEST_F(WindowTest, PresentShrinksIntoASmallWindow) {
    auto window = Window::open({"test", 320, 180, 1});
    ASSERT_TRUE(window.ok()) << window.error().message();
    Window& w = **window;
    w.setSize(160, 100);  // f = 0.5: a 160 × 90 picture at (0, 5)
    Canvas canvas(320, 180);
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x)
            canvas.setPixel(x, y, Color{std::uint8_t(x), std::uint8_t(y), std::uint8_t(x ^ y), 255});
    w.present(canvas);
    const Canvas shown = w.capture();
    ASSERT_EQ(shown.width(), 160);
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 160; ++x) {
            const bool inside = y >= 5 && y < 95;
            const std::uint32_t want = inside ? rgb(canvas, 2 * x, 2 * (y - 5)) : 0u;
            ASSERT_EQ(rgb(shown, x, y), want) << x << "," << y;
        }
}

TEST_F(WindowTest, F11AndAltEnterToggleFullscreen) {
    auto window = Window::open({"test", 16, 9, 2});
    ASSERT_TRUE(window.ok()) << window.error().message();
    Window& w = **window;
    EXPECT_EQ(w.width(), 32);
    EXPECT_EQ(w.height(), 18);
    KeyPressed press{Key::A, Key::A, kModNone, false};
    EXPECT_FALSE(w.handleFullscreenKeys(press));
    EXPECT_FALSE(w.fullscreen());
    press.key = Key::F11;
    EXPECT_TRUE(w.handleFullscreenKeys(press));
    EXPECT_TRUE(w.fullscreen());
    press.key = Key::Enter;
    EXPECT_FALSE(w.handleFullscreenKeys(press));  // Enter without Alt
    press.mods = kModAlt;
    EXPECT_TRUE(w.handleFullscreenKeys(press));
    EXPECT_FALSE(w.fullscreen());
    press.repeat = true;  // a held key does not flicker
    EXPECT_FALSE(w.handleFullscreenKeys(press));
    EXPECT_FALSE(w.handleFullscreenKeys(KeyReleased{Key::F11, Key::F11, kModNone}));
}

TEST_F(WindowTest, HeldKeysAndMissingPadsReadAsReleased) {
    auto window = Window::open({"test", 16, 9, 1});
    ASSERT_TRUE(window.ok()) << window.error().message();
    Window& w = **window;
    while (w.pollEvent()) {
    }
    EXPECT_FALSE(w.keyHeld(Key::Space));
    EXPECT_FALSE(w.keyHeld(Key::Unknown));
    EXPECT_FALSE(w.gamepadButton(12345, GamepadButton::A));
    EXPECT_EQ(w.gamepadAxis(12345, GamepadAxis::LeftX), 0.0);
}

}  // namespace
}  // namespace polar::platform
