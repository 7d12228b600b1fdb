#include "platform/sdl_input.h"

#include <gtest/gtest.h>

namespace polar::platform::detail {
namespace {

TEST(SdlInput, EveryKeyHasAPositionThatMapsBack) {
    for (int k = 1; k < int(Key::Count); ++k) {
        const Key key = Key(k);
        const SDL_Scancode code = scancodeOf(key);
        ASSERT_NE(code, SDL_SCANCODE_UNKNOWN) << k;
        EXPECT_EQ(keyFromScancode(code), key) << k;
    }
    EXPECT_EQ(scancodeOf(Key::Unknown), SDL_SCANCODE_UNKNOWN);
    EXPECT_EQ(keyFromScancode(SDL_SCANCODE_UNKNOWN), Key::Unknown);
    EXPECT_EQ(keyFromScancode(SDL_SCANCODE_KP_7), Key::Unknown);  // no name for it
    EXPECT_EQ(keyFromKeycode(SDLK_KP_ENTER), Key::KeypadEnter);
    EXPECT_EQ(keyFromKeycode(SDLK_RETURN), Key::Enter);
    EXPECT_EQ(keyFromKeycode(SDLK_w), Key::W);
    EXPECT_EQ(keyFromKeycode(SDLK_1), Key::Num1);
    EXPECT_EQ(keyFromKeycode(SDLK_F11), Key::F11);
    EXPECT_EQ(keyFromKeycode(SDLK_ESCAPE), Key::Escape);
    EXPECT_EQ(keyFromKeycode(SDLK_LEFT), Key::Left);
    EXPECT_EQ(keyFromKeycode(SDLK_RALT), Key::RightAlt);
    EXPECT_EQ(keyFromKeycode(SDLK_SLASH), Key::Slash);
    EXPECT_EQ(keyFromKeycode(SDLK_KP_7), Key::Unknown);
}

TEST(SdlInput, ModifiersOnEitherSideCount) {
    EXPECT_EQ(modsFrom(KMOD_NONE), kModNone);
    EXPECT_EQ(modsFrom(KMOD_LALT), kModAlt);
    EXPECT_EQ(modsFrom(KMOD_RALT | KMOD_LSHIFT), kModAlt | kModShift);
    EXPECT_EQ(modsFrom(KMOD_RCTRL | KMOD_LGUI | KMOD_NUM),
              kModCtrl | kModGui);  // Num Lock is no modifier here
}

TEST(SdlInput, GamepadCodesRoundTrip) {
    for (int b = 0; b < int(GamepadButton::Count); ++b)
        EXPECT_EQ(gamepadButtonFrom(Uint8(sdlButtonOf(GamepadButton(b)))), GamepadButton(b));
    for (int a = 0; a < int(GamepadAxis::Count); ++a)
        EXPECT_EQ(gamepadAxisFrom(Uint8(sdlAxisOf(GamepadAxis(a)))), GamepadAxis(a));
    EXPECT_EQ(gamepadButtonFrom(SDL_CONTROLLER_BUTTON_MISC1), std::nullopt);
    EXPECT_EQ(sdlButtonOf(GamepadButton::Start), SDL_CONTROLLER_BUTTON_START);
    EXPECT_EQ(sdlAxisOf(GamepadAxis::RightTrigger), SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
}

TEST(SdlInput, AxisReadingsKeepTheirOrder) {
    // raw / 32768 is exact, so "raw < −12000" and "value < −12000/32768" agree for every reading.
    for (int raw = -32768; raw <= 32767; ++raw) {
        ASSERT_EQ(axisValue(Sint16(raw)) < -12000.0 / 32768.0, raw < -12000) << raw;
        ASSERT_EQ(axisValue(Sint16(raw)) > 8000.0 / 32768.0, raw > 8000) << raw;
    }
    EXPECT_EQ(axisValue(-32768), -1.0);
}

}  // namespace
}  // namespace polar::platform::detail
