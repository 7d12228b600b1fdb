#pragma once
#include <array>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "app/hud/overlay_layout.h"
#include "files/hot_reload.h"
#include "polar/render/canvas.h"
#include "polar/world.h"

namespace polar::game {

// What a frame shows over the screens. Each is optional; the ones listed first claim their room
// first (overlay_layout.h), so the replay bar never moves for a notice.
struct OverlayContent {
    std::vector<OverlayLine> bar;        // the top screen's bar (the replay bar), across the bottom
    std::string help;                    // the top screen's line of controls, centred near the bottom
    std::optional<OverlayLine> message;  // the top screen's message (a prompt, a refusal), over the help
    int barControls = 0;                 // rows above the bar's lines for the screen's own controls
    std::function<void(render::Canvas&, const PixelRect&)> drawBarControls;  // draws them there
    bool frameTime = false;             // the frame-time line (from `fps`), top right
    const World* debugWorld = nullptr;  // with the debug overlay on: the world the panel describes
    double fps = 0;
    const std::array<double, kEffectCount>* effectMs = nullptr;
    const HotReload* reload = nullptr;  // its problems and its last notice
    std::string notice;                 // the session's notice, while it is fresh
};

// Where a screen's help line sits: its text's top row.
int helpLineRow(int canvasHeight);

// The bar's box: as wide as the screen at the bottom, and the first box placed, so it is known
// before a frame is drawn (the theatre hit-tests its seek bar there). `controls` rows on top of
// `lines` lines of text; the controls' rectangle is its top part, inside the padding.
PixelRect barBox(int canvasWidth, int canvasHeight, std::size_t lines, int controls);
PixelRect barControlsRect(const PixelRect& box, int controls);

// Draws the overlays, each in the box the layout gives it; returns the layout with every box
// placed (the boxes never share a pixel; tests hold that on every screen).
OverlayLayout drawOverlays(render::Canvas& canvas, const OverlayContent& content);

}  // namespace polar::game
