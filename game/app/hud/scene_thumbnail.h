#pragma once
#include <string>

#include "app/hud/game_drawing.h"
#include "polar/error.h"
#include "polar/render/canvas.h"

namespace polar::game {

// A scene's picture for the scene screen: the first frame of a game of it (seed 1, before any tick),
// drawn off-screen without the HUD and shrunk by `factor` in each direction, each pixel the mean of
// its factor × factor block. Drawn when a screen opens, never during a draw, and from the scene's own
// files, so a mod's scene gets its own picture without shipping one.
Result<render::Canvas> sceneThumbnail(const AssetFs& assets, SpriteCache& sprites, const std::string& scene,
                                      int factor = 4);

}  // namespace polar::game
