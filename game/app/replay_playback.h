#pragma once
#include "app/app.h"
#include "app/draw.h"
#include "files/assets.h"
#include "polar/render/canvas.h"

namespace polar::game {

// Plays options.replay: in a window at the replay's tick rate (P pauses, → and ← step while paused,
// ↑/↓ change the speed, F1 shows the bounds, Esc quits), or with options.headless off-screen as
// fast as it runs, saving options.screenshots; options.seek starts it at that tick (ReplaySeek).
// Every tick is checked against the recording; the first desync is reported, and with
// options.verify the run stops there with exit code 1. Returns the process exit code (2 for a
// replay that cannot be read or started). The replay's world steps on `tasks`.
int playReplay(const AppOptions& options, const AssetFs& assets, SpriteCache& sprites, render::Canvas& canvas,
               TaskSystem& tasks);

}  // namespace polar::game
