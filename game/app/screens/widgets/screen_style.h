#pragma once
#include <string>

#include "app/hud/lettering.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"

namespace polar::game {

// A translucent band across the screen from `top`, `height` rows tall, for text over a game.
void drawBand(render::Canvas& canvas, int top, int height);
// An opaque panel with a thin border, for a question asked over another screen.
void drawPanel(render::Canvas& canvas, int x, int y, int width, int height);
// A screen's heading: big, centred, at `y`.
void drawHeading(render::Canvas& canvas, const std::string& text, int y);

}  // namespace polar::game
