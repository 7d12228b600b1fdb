#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "files/assets.h"
#include "polar/error.h"

namespace polar::bench {

// The demo pilot's game of `ticks` ticks with `lives` lives, recorded into `path` by the game's own
// ReplayWriter, as the game records a player. More lives than a player gets keep the pilot flying.
std::optional<Error> recordDemo(const std::string& path, const game::AssetFs& assets, std::uint64_t seed,
                                int ticks, int lives);

}  // namespace polar::bench
