#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "app/hud/interpolation.h"
#include "app/hud/particles.h"
#include "app/hud/sprite_cache.h"
#include "polar/render/canvas.h"
#include "polar/render/draw_list.h"
#include "polar/render/view.h"
#include "polar/tasks.h"
#include "rules/game.h"

namespace polar::game {

// The game's logical screen: 640 × 360, shown scaled up by whole numbers (2× at 1280 × 720).
inline constexpr int kScreenWidth = 640;
inline constexpr int kScreenHeight = 360;

struct DrawOptions {
    bool debugOverlay = false;  // the bounds and the pairs hit (the debug panel's text is an overlay)
    std::uint64_t highScore = 0;
    bool hud = true;
    EffectLevels effects;  // the screen's shake and the flashes (the player's options)
    bool backdrop = true;  // the scene's backdrop (backdrop.h); off, the plain dark of old
    // Where the frame is drawn: in bands of rows on this task system (the game's pool), or on the
    // calling thread when null. The picture is the same bytes either way.
    TaskSystem* tasks = nullptr;
};

// Draws one frame of the game: the scene's backdrop, the cave, every object under its interpolated transform
// (the world moved by the screen's shake), bullet trails, the particles and flashes, and the HUD with the
// score pop-ups and the wave's banner; with the debug overlay, every object's world bounds exactly as the
// collision rule sees them and the pairs hit in the last step (debug_panel.h adds the numbers). The frame is
// recorded in a DrawList (one per thread, kept from frame to frame) and drawn on options.tasks.
void drawGame(render::Canvas& canvas, const Game& game, SpriteCache& sprites,
              const Interpolation& interpolation, const Particles& particles, double alpha,
              const DrawOptions& options);

// Draws the outline of a Bound under a world transform as the collision rule sees it
// (polar::boundOutline, shared with `polarcade-bounds view`) and a cross at its centre.
void drawBoundOutline(render::DrawList& list, const render::View& view, const Bound& bound,
                      const Transform& transform, render::Color color);

// Text centred horizontally on the screen.
void drawCentredText(render::Canvas& canvas, const std::string& text, int y, int scale, render::Color color);

}  // namespace polar::game
