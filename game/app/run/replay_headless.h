#pragma once
#include "app/context/app_options.h"
#include "app/hud/sprite_cache.h"
#include "files/assets.h"
#include "polar/render/canvas.h"
#include "polar/tasks.h"

namespace polar::game {

// Plays options.replay off-screen as fast as it runs, saving options.screenshots; with
// options.verify the run stops at the first desync or damaged line with exit code 1, and a replay
// without its end line ends with exit code 1 (unless options.allowIncomplete); options.seek starts it there.
// Returns the process exit code (2 for a replay that cannot be read or started).
int playReplayHeadless(const AppOptions& options, const AssetFs& assets, SpriteCache& sprites,
                       render::Canvas& canvas, TaskSystem& tasks);

}  // namespace polar::game
