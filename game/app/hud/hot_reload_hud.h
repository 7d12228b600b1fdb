#pragma once
#include <string>
#include <vector>

#include "app/hud/overlay_layout.h"
#include "files/hot_reload.h"
#include "polar/render/canvas.h"

namespace polar::game {

// Draws hot reload's state over a frame through the overlay layout, across the screen from the
// bottom: every bounds file whose edit is invalid with the loader's file:line:column message (red,
// until it is fixed), and for a few seconds the last notice ("reloaded …"). Draws nothing when
// there is nothing to say.
void drawHotReloadStatus(render::Canvas& canvas, OverlayLayout& layout, const HotReload& reload);

// `text` cut into lines of at most `width` characters, at spaces where possible.
std::vector<std::string> wrapText(const std::string& text, std::size_t width);

}  // namespace polar::game
