#include "platform/sdl_input.h"

#include <array>

namespace polar::platform::detail {
namespace {

struct KeyCodes {
    Key key;
    SDL_Scancode scancode;
    SDL_Keycode keycode;
};

// Every named Key with its SDL scancode (position) and keycode (layout meaning), in Key order.
constexpr KeyCodes kKeys[] = {
    {Key::A, SDL_SCANCODE_A, SDLK_a},
    {Key::B, SDL_SCANCODE_B, SDLK_b},
    {Key::C, SDL_SCANCODE_C, SDLK_c},
    {Key::D, SDL_SCANCODE_D, SDLK_d},
    {Key::E, SDL_SCANCODE_E, SDLK_e},
    {Key::F, SDL_SCANCODE_F, SDLK_f},
    {Key::G, SDL_SCANCODE_G, SDLK_g},
    {Key::H, SDL_SCANCODE_H, SDLK_h},
    {Key::I, SDL_SCANCODE_I, SDLK_i},
    {Key::J, SDL_SCANCODE_J, SDLK_j},
    {Key::K, SDL_SCANCODE_K, SDLK_k},
    {Key::L, SDL_SCANCODE_L, SDLK_l},
    {Key::M, SDL_SCANCODE_M, SDLK_m},
    {Key::N, SDL_SCANCODE_N, SDLK_n},
    {Key::O, SDL_SCANCODE_O, SDLK_o},
    {Key::P, SDL_SCANCODE_P, SDLK_p},
    {Key::Q, SDL_SCANCODE_Q, SDLK_q},
    {Key::R, SDL_SCANCODE_R, SDLK_r},
    {Key::S, SDL_SCANCODE_S, SDLK_s},
    {Key::T, SDL_SCANCODE_T, SDLK_t},
    {Key::U, SDL_SCANCODE_U, SDLK_u},
    {Key::V, SDL_SCANCODE_V, SDLK_v},
    {Key::W, SDL_SCANCODE_W, SDLK_w},
    {Key::X, SDL_SCANCODE_X, SDLK_x},
    {Key::Y, SDL_SCANCODE_Y, SDLK_y},
    {Key::Z, SDL_SCANCODE_Z, SDLK_z},
    {Key::Num0, SDL_SCANCODE_0, SDLK_0},
    {Key::Num1, SDL_SCANCODE_1, SDLK_1},
    {Key::Num2, SDL_SCANCODE_2, SDLK_2},
    {Key::Num3, SDL_SCANCODE_3, SDLK_3},
    {Key::Num4, SDL_SCANCODE_4, SDLK_4},
    {Key::Num5, SDL_SCANCODE_5, SDLK_5},
    {Key::Num6, SDL_SCANCODE_6, SDLK_6},
    {Key::Num7, SDL_SCANCODE_7, SDLK_7},
    {Key::Num8, SDL_SCANCODE_8, SDLK_8},
    {Key::Num9, SDL_SCANCODE_9, SDLK_9},
    {Key::Space, SDL_SCANCODE_SPACE, SDLK_SPACE},
    {Key::Enter, SDL_SCANCODE_RETURN, SDLK_RETURN},
    {Key::KeypadEnter, SDL_SCANCODE_KP_ENTER, SDLK_KP_ENTER},
    {Key::Escape, SDL_SCANCODE_ESCAPE, SDLK_ESCAPE},
    {Key::Backspace, SDL_SCANCODE_BACKSPACE, SDLK_BACKSPACE},
    {Key::Tab, SDL_SCANCODE_TAB, SDLK_TAB},
    {Key::Delete, SDL_SCANCODE_DELETE, SDLK_DELETE},
    {Key::Insert, SDL_SCANCODE_INSERT, SDLK_INSERT},
    {Key::Home, SDL_SCANCODE_HOME, SDLK_HOME},
    {Key::End, SDL_SCANCODE_END, SDLK_END},
    {Key::PageUp, SDL_SCANCODE_PAGEUP, SDLK_PAGEUP},
    {Key::PageDown, SDL_SCANCODE_PAGEDOWN, SDLK_PAGEDOWN},
    {Key::Left, SDL_SCANCODE_LEFT, SDLK_LEFT},
    {Key::Right, SDL_SCANCODE_RIGHT, SDLK_RIGHT},
    {Key::Up, SDL_SCANCODE_UP, SDLK_UP},
    {Key::Down, SDL_SCANCODE_DOWN, SDLK_DOWN},
    {Key::F1, SDL_SCANCODE_F1, SDLK_F1},
    {Key::F2, SDL_SCANCODE_F2, SDLK_F2},
    {Key::F3, SDL_SCANCODE_F3, SDLK_F3},
    {Key::F4, SDL_SCANCODE_F4, SDLK_F4},
    {Key::F5, SDL_SCANCODE_F5, SDLK_F5},
    {Key::F6, SDL_SCANCODE_F6, SDLK_F6},
    {Key::F7, SDL_SCANCODE_F7, SDLK_F7},
    {Key::F8, SDL_SCANCODE_F8, SDLK_F8},
    {Key::F9, SDL_SCANCODE_F9, SDLK_F9},
    {Key::F10, SDL_SCANCODE_F10, SDLK_F10},
    {Key::F11, SDL_SCANCODE_F11, SDLK_F11},
    {Key::F12, SDL_SCANCODE_F12, SDLK_F12},
    {Key::LeftShift, SDL_SCANCODE_LSHIFT, SDLK_LSHIFT},
    {Key::RightShift, SDL_SCANCODE_RSHIFT, SDLK_RSHIFT},
    {Key::LeftCtrl, SDL_SCANCODE_LCTRL, SDLK_LCTRL},
    {Key::RightCtrl, SDL_SCANCODE_RCTRL, SDLK_RCTRL},
    {Key::LeftAlt, SDL_SCANCODE_LALT, SDLK_LALT},
    {Key::RightAlt, SDL_SCANCODE_RALT, SDLK_RALT},
    {Key::Minus, SDL_SCANCODE_MINUS, SDLK_MINUS},
    {Key::Equals, SDL_SCANCODE_EQUALS, SDLK_EQUALS},
    {Key::Comma, SDL_SCANCODE_COMMA, SDLK_COMMA},
    {Key::Period, SDL_SCANCODE_PERIOD, SDLK_PERIOD},
    {Key::Slash, SDL_SCANCODE_SLASH, SDLK_SLASH},
};
static_assert(std::size(kKeys) == std::size_t(Key::Count) - 1, "one row per named Key");

constexpr bool inKeyOrder() {
    for (std::size_t i = 0; i < std::size(kKeys); ++i)
        if (std::size_t(kKeys[i].key) != i + 1) return false;
    return true;
}
static_assert(inKeyOrder(), "row i is Key i + 1");

// Scancodes are small dense numbers (< SDL_NUM_SCANCODES): a direct table.
const std::array<Key, SDL_NUM_SCANCODES>& keysByScancode() {
    static const auto table = [] {
        std::array<Key, SDL_NUM_SCANCODES> t{};
        for (const KeyCodes& k : kKeys) t[k.scancode] = k.key;
        return t;
    }();
    return table;
}

}  // namespace

Key keyFromKeycode(SDL_Keycode code) {
    for (const KeyCodes& k : kKeys)
        if (k.keycode == code) return k.key;
    return Key::Unknown;
}

Key keyFromScancode(SDL_Scancode code) {
    return code >= 0 && code < SDL_NUM_SCANCODES ? keysByScancode()[code] : Key::Unknown;
}

SDL_Scancode scancodeOf(Key key) {
    if (key == Key::Unknown || key >= Key::Count) return SDL_SCANCODE_UNKNOWN;
    return kKeys[std::size_t(key) - 1].scancode;
}

std::uint8_t modsFrom(Uint16 sdlMods) {
    std::uint8_t mods = kModNone;
    if (sdlMods & KMOD_SHIFT) mods |= kModShift;
    if (sdlMods & KMOD_CTRL) mods |= kModCtrl;
    if (sdlMods & KMOD_ALT) mods |= kModAlt;
    if (sdlMods & KMOD_GUI) mods |= kModGui;
    return mods;
}

namespace {

// GamepadButton i is SDL button kButtons[i]; GamepadAxis likewise.
constexpr SDL_GameControllerButton kButtons[] = {
    SDL_CONTROLLER_BUTTON_A,
    SDL_CONTROLLER_BUTTON_B,
    SDL_CONTROLLER_BUTTON_X,
    SDL_CONTROLLER_BUTTON_Y,
    SDL_CONTROLLER_BUTTON_BACK,
    SDL_CONTROLLER_BUTTON_GUIDE,
    SDL_CONTROLLER_BUTTON_START,
    SDL_CONTROLLER_BUTTON_LEFTSTICK,
    SDL_CONTROLLER_BUTTON_RIGHTSTICK,
    SDL_CONTROLLER_BUTTON_LEFTSHOULDER,
    SDL_CONTROLLER_BUTTON_RIGHTSHOULDER,
    SDL_CONTROLLER_BUTTON_DPAD_UP,
    SDL_CONTROLLER_BUTTON_DPAD_DOWN,
    SDL_CONTROLLER_BUTTON_DPAD_LEFT,
    SDL_CONTROLLER_BUTTON_DPAD_RIGHT,
};
static_assert(std::size(kButtons) == std::size_t(GamepadButton::Count));

constexpr SDL_GameControllerAxis kAxes[] = {
    SDL_CONTROLLER_AXIS_LEFTX,  SDL_CONTROLLER_AXIS_LEFTY,       SDL_CONTROLLER_AXIS_RIGHTX,
    SDL_CONTROLLER_AXIS_RIGHTY, SDL_CONTROLLER_AXIS_TRIGGERLEFT, SDL_CONTROLLER_AXIS_TRIGGERRIGHT,
};
static_assert(std::size(kAxes) == std::size_t(GamepadAxis::Count));

}  // namespace

std::optional<GamepadButton> gamepadButtonFrom(Uint8 sdlButton) {
    for (std::size_t i = 0; i < std::size(kButtons); ++i)
        if (kButtons[i] == sdlButton) return GamepadButton(i);
    return std::nullopt;
}

SDL_GameControllerButton sdlButtonOf(GamepadButton button) {
    return kButtons[std::size_t(button)];
}

std::optional<GamepadAxis> gamepadAxisFrom(Uint8 sdlAxis) {
    for (std::size_t i = 0; i < std::size(kAxes); ++i)
        if (kAxes[i] == sdlAxis) return GamepadAxis(i);
    return std::nullopt;
}

SDL_GameControllerAxis sdlAxisOf(GamepadAxis axis) {
    return kAxes[std::size_t(axis)];
}

std::optional<MouseButton> mouseButtonFrom(Uint8 sdlButton) {
    switch (sdlButton) {
        case SDL_BUTTON_LEFT:
            return MouseButton::Left;
        case SDL_BUTTON_MIDDLE:
            return MouseButton::Middle;
        case SDL_BUTTON_RIGHT:
            return MouseButton::Right;
        case SDL_BUTTON_X1:
            return MouseButton::X1;
        case SDL_BUTTON_X2:
            return MouseButton::X2;
        default:
            return std::nullopt;
    }
}

}  // namespace polar::platform::detail
