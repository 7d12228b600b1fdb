#pragma once
#include <string>
#include <vector>

#include "files/hot_reload.h"
#include "polar/render/canvas.h"

namespace polar::game {

// Draws hot reload's state over a frame, in the bitmap font: every bounds file whose edit is
// invalid with the loader's file:line:column message (red, until it is fixed), and for a few
// seconds the last notice ("reloaded …"). Draws nothing when there is nothing to say.
void drawHotReloadStatus(render::Canvas& canvas, const HotReload& reload);

// `text` cut into lines of at most `width` characters, at spaces where possible.
std::vector<std::string> wrapText(const std::string& text, std::size_t width);

}  // namespace polar::game
