#pragma once
// Between a game and its replay: the files the game read, the header that records it, the config
// that starts it again.
#include <string>
#include <string_view>
#include <vector>

#include "files/assets.h"
#include "polar/error.h"
#include "replay/replay_format.h"
#include "rules/game.h"

namespace polar::game {

// The hash an asset stamp records for a file's bytes.
std::uint64_t stampHash(std::string_view bytes);
// Creates a game as Game::create does and stamps every file it reads. Absolute paths are named as
// logical paths when they lie in `assets` (its mods or its root), otherwise relative to `anchor`'s
// folder (the replay file).
Result<Game> createStampedGame(const Game::Config& config, const AssetFs* assets, const std::string& anchor,
                               std::vector<AssetStamp>& stamps);
// The header for recording `game` (just created, with those stamps) into the file `replayPath`.
ReplayHeader headerFor(const Game& game, const std::string& replayPath, std::vector<std::string> mods,
                       std::vector<AssetStamp> stamps);
// The game config a replay starts from: its scene (resolved against the replay's folder), seed and
// tuning, read through `assets`.
Game::Config configFor(const Replay& replay, const AssetFs& assets);

}  // namespace polar::game
