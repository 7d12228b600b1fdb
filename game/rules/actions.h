#pragma once
#include <cstdint>

namespace polar::game {

// What the player asks for during one simulation tick. Input devices are turned into these, and
// replays record exactly these, one byte per tick.
enum Action : std::uint8_t {
    kTurnLeft = 1u << 0,
    kTurnRight = 1u << 1,
    kThrust = 1u << 2,
    kFire = 1u << 3,
};
using Actions = std::uint8_t;

inline constexpr Actions kAllActions = kTurnLeft | kTurnRight | kThrust | kFire;

}  // namespace polar::game
