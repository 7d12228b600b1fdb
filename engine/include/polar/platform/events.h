#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "polar/math.h"

namespace polar::platform {

// A key, named by what a US keyboard prints on it. Key events carry two of these: `key`, what the
// player's layout makes of the key (a menu that says "press P" wants this one), and `position`,
// which key it is physically (WASD movement wants this one, so it stays under the left hand on any
// layout). Keys with no name here are Unknown.
// clang-format off
enum class Key : std::uint8_t {
    Unknown,
    A, B, C, D, E, F, G, H, I, J, K, L, M, N, O, P, Q, R, S, T, U, V, W, X, Y, Z,
    Num0, Num1, Num2, Num3, Num4, Num5, Num6, Num7, Num8, Num9,
    Space, Enter, KeypadEnter, Escape, Backspace, Tab, Delete, Insert, Home, End, PageUp, PageDown,
    Left, Right, Up, Down,
    F1, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12,
    LeftShift, RightShift, LeftCtrl, RightCtrl, LeftAlt, RightAlt,
    Minus, Equals, Comma, Period, Slash,
    Count  // the number of keys, for tables indexed by Key
};
// clang-format on

// The key's name as a script or a help line writes it: "a" … "z", "0" … "9", "space", "enter",
// "keypad-enter", "escape", "backspace", "tab", "delete", "insert", "home", "end", "page-up",
// "page-down", "left", "right", "up", "down", "f1" … "f12", "left-shift", "right-shift",
// "left-ctrl", "right-ctrl", "left-alt", "right-alt", "minus", "equals", "comma", "period",
// "slash"; "unknown" for Key::Unknown.
const char* keyName(Key key);
// The Key of a name keyName gives (case-insensitive), or nothing.
std::optional<Key> keyFromName(std::string_view name);

// Modifier keys held when a key went down, as bits.
enum KeyMods : std::uint8_t {
    kModNone = 0,
    kModShift = 1 << 0,  // either Shift
    kModCtrl = 1 << 1,   // either Ctrl
    kModAlt = 1 << 2,    // either Alt
    kModGui = 1 << 3,    // either Windows/Command key
};

enum class MouseButton : std::uint8_t { Left, Middle, Right, X1, X2 };

// Buttons by their place on an Xbox-style pad (A at the bottom of the four face buttons).
// clang-format off
enum class GamepadButton : std::uint8_t {
    A, B, X, Y, Back, Guide, Start, LeftStick, RightStick, LeftShoulder, RightShoulder,
    DpadUp, DpadDown, DpadLeft, DpadRight,
    Count
};
// clang-format on

// Sticks run from −1 (left, up) to +1 (right, down); triggers from 0 (released) to +1.
enum class GamepadAxis : std::uint8_t { LeftX, LeftY, RightX, RightY, LeftTrigger, RightTrigger, Count };

// A gamepad, from when it is connected until it is disconnected; never reused for another pad.
using GamepadId = std::int32_t;

// The events a Window delivers (Window::pollEvent). Positions are in window pixels, y down, with
// `canvas` the same point on the canvas last presented (Window::windowToCanvas).
struct QuitRequested {};
struct KeyPressed {
    Key key = Key::Unknown;       // by the player's layout
    Key position = Key::Unknown;  // by where the key is (its US-layout name)
    std::uint8_t mods = kModNone;
    bool repeat = false;  // sent again because the key is held
};
struct KeyReleased {
    Key key = Key::Unknown;
    Key position = Key::Unknown;
    std::uint8_t mods = kModNone;
};
struct TextEntered {
    std::string utf8;  // what the keys typed, after the layout and any input method
};
struct MouseButtonPressed {
    MouseButton button = MouseButton::Left;
    int x = 0, y = 0;
    Vec2 canvas = Vec2::Zero();
};
struct MouseButtonReleased {
    MouseButton button = MouseButton::Left;
    int x = 0, y = 0;
    Vec2 canvas = Vec2::Zero();
};
struct MouseMoved {
    int x = 0, y = 0;
    Vec2 canvas = Vec2::Zero();
};
struct MouseWheelScrolled {
    double dx = 0, dy = 0;  // notches; dy > 0 away from the player
};
struct GamepadConnected {
    GamepadId pad = 0;
    std::string name;
};
struct GamepadDisconnected {
    GamepadId pad = 0;
};
struct GamepadButtonPressed {
    GamepadId pad = 0;
    GamepadButton button = GamepadButton::A;
};
struct GamepadButtonReleased {
    GamepadId pad = 0;
    GamepadButton button = GamepadButton::A;
};
struct GamepadAxisMoved {
    GamepadId pad = 0;
    GamepadAxis axis = GamepadAxis::LeftX;
    double value = 0;  // see GamepadAxis for the range
};
struct WindowResized {
    int width = 0, height = 0;  // the window's new size in pixels
};
// The window lost the keyboard focus, or (in a browser) its page was hidden or left: a game in
// progress should pause, since the player is no longer looking.
struct WindowFocusLost {};

using Event =
    std::variant<QuitRequested, KeyPressed, KeyReleased, TextEntered, MouseButtonPressed, MouseButtonReleased,
                 MouseMoved, MouseWheelScrolled, GamepadConnected, GamepadDisconnected, GamepadButtonPressed,
                 GamepadButtonReleased, GamepadAxisMoved, WindowResized, WindowFocusLost>;

}  // namespace polar::platform
