#pragma once
// Translations between SDL's input codes and the platform's own (events.h). Private to the
// platform layer: nothing outside engine/src/platform sees an SDL type.
#include <SDL.h>

#include <optional>

#include "polar/platform/events.h"

namespace polar::platform::detail {

// The Key a layout-mapped SDL keycode stands for (Unknown for keys events.h has no name for).
Key keyFromKeycode(SDL_Keycode code);
// The Key at a physical position (SDL scancode).
Key keyFromScancode(SDL_Scancode code);
// The physical position of a Key (SDL_SCANCODE_UNKNOWN for Key::Unknown).
SDL_Scancode scancodeOf(Key key);
// KeyMods bits from SDL's modifier state.
std::uint8_t modsFrom(Uint16 sdlMods);

std::optional<GamepadButton> gamepadButtonFrom(Uint8 sdlButton);
SDL_GameControllerButton sdlButtonOf(GamepadButton button);
std::optional<GamepadAxis> gamepadAxisFrom(Uint8 sdlAxis);
SDL_GameControllerAxis sdlAxisOf(GamepadAxis axis);
// An SDL axis reading (−32768 … 32767) as raw / 32768: exact in a double, so thresholds compare
// the same way on either scale.
inline double axisValue(Sint16 raw) {
    return raw / 32768.0;
}
std::optional<MouseButton> mouseButtonFrom(Uint8 sdlButton);

}  // namespace polar::platform::detail
