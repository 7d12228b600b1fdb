#include "display.h"

#include <SDL.h>
#include <gtest/gtest.h>

namespace polar::game {
namespace {

using render::Canvas;
using render::Color;

// SDL's "dummy" video driver gives a real window surface without any display, so these tests run
// anywhere (CI has no X11).
class DisplayTest : public ::testing::Test {
  protected:
    void SetUp() override { SDL_SetHint(SDL_HINT_VIDEODRIVER, "dummy"); }
};

std::uint32_t windowPixel(SDL_Window* window, int x, int y) {
    SDL_Surface* s = SDL_GetWindowSurface(window);
    return *reinterpret_cast<const std::uint32_t*>(static_cast<const std::uint8_t*>(s->pixels) +
                                                   y * s->pitch + x * 4) &
           0x00FFFFFFu;
}

TEST(DisplayFit, WholeFactorsWhenTheyFillMostOfTheWindow) {
    auto p = Display::fit(320, 180, 1280, 720);
    EXPECT_EQ(p.width, 1280);
    EXPECT_EQ(p.height, 720);
    EXPECT_EQ(p.x, 0);
    p = Display::fit(320, 180, 1000, 720);  // f = 3.125 → 3, centred, letterboxed
    EXPECT_EQ(p.width, 960);
    EXPECT_EQ(p.height, 540);
    EXPECT_EQ(p.x, 20);
    EXPECT_EQ(p.y, 90);
}

TEST(DisplayFit, FractionalWhenAWholeFactorWouldWasteTooMuch) {
    auto p = Display::fit(1280, 720, 1920, 1080);  // f = 1.5: 1× would leave a third unused
    EXPECT_EQ(p.width, 1920);
    EXPECT_EQ(p.height, 1080);
    p = Display::fit(1280, 720, 640, 480);  // smaller than the canvas: scaled down, letterboxed
    EXPECT_EQ(p.width, 640);
    EXPECT_EQ(p.height, 360);
    EXPECT_EQ(p.y, 60);
    EXPECT_EQ(Display::fit(10, 10, 0, 5).width, 0);
}

TEST_F(DisplayTest, PresentScalesByWholePixelsWithBlackBorders) {
    auto display = Display::open("test", 4, 3, 1);
    ASSERT_TRUE(display.ok()) << display.error().message();
    Display& d = **display;
    SDL_SetWindowSize(d.window(), 10, 8);  // f = min(2.5, 2.67) → k = 2: an 8 × 6 picture at (1, 1)
    Canvas canvas(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            canvas.setPixel(x, y, Color{std::uint8_t(40 * x + 1), std::uint8_t(50 * y + 1), 7, 255});
    d.present(canvas);
    SDL_Surface* s = SDL_GetWindowSurface(d.window());
    ASSERT_EQ(s->w, 10);
    ASSERT_EQ(s->h, 8);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 10; ++x) {
            const bool inside = x >= 1 && x < 9 && y >= 1 && y < 7;
            const std::uint32_t want = inside ? canvas.row((y - 1) / 2)[(x - 1) / 2] & 0x00FFFFFFu : 0u;
            ASSERT_EQ(windowPixel(d.window(), x, y), want) << x << "," << y;
        }
    EXPECT_EQ(d.windowToCanvas(1, 1), Vec2(0.25, 0.25));
    EXPECT_EQ(d.windowToCanvas(8, 6), Vec2(3.75, 2.75));
}

TEST_F(DisplayTest, PresentShrinksIntoASmallWindow) {
    auto display = Display::open("test", 320, 180, 1);
    ASSERT_TRUE(display.ok()) << display.error().message();
    Display& d = **display;
    SDL_SetWindowSize(d.window(), 160, 100);  // f = 0.5: a 160 × 90 picture at (0, 5)
    Canvas canvas(320, 180);
    for (int y = 0; y < 180; ++y)
        for (int x = 0; x < 320; ++x)
            canvas.setPixel(x, y, Color{std::uint8_t(x), std::uint8_t(y), std::uint8_t(x ^ y), 255});
    d.present(canvas);
    ASSERT_EQ(SDL_GetWindowSurface(d.window())->w, 160);
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 160; ++x) {
            const bool inside = y >= 5 && y < 95;
            const std::uint32_t want = inside ? canvas.row(2 * (y - 5))[2 * x] & 0x00FFFFFFu : 0u;
            ASSERT_EQ(windowPixel(d.window(), x, y), want) << x << "," << y;
        }
}

TEST_F(DisplayTest, F11AndAltEnterToggleFullscreen) {
    auto display = Display::open("test", 16, 9, 2);
    ASSERT_TRUE(display.ok()) << display.error().message();
    Display& d = **display;
    SDL_Event event{};
    event.type = SDL_KEYDOWN;
    event.key.keysym.sym = SDLK_a;
    EXPECT_FALSE(d.handleEvent(event));
    EXPECT_FALSE(d.fullscreen());
    event.key.keysym.sym = SDLK_F11;
    EXPECT_TRUE(d.handleEvent(event));
    EXPECT_TRUE(d.fullscreen());
    event.key.keysym.sym = SDLK_RETURN;
    EXPECT_FALSE(d.handleEvent(event));  // Enter without Alt
    event.key.keysym.mod = KMOD_LALT;
    EXPECT_TRUE(d.handleEvent(event));
    EXPECT_FALSE(d.fullscreen());
    event.key.repeat = 1;  // a held key does not flicker
    EXPECT_FALSE(d.handleEvent(event));
}

}  // namespace
}  // namespace polar::game
