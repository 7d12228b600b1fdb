#pragma once
#include <string>

#include "app/hud/lettering.h"
#include "polar/render/canvas.h"
#include "polar/render/color.h"

namespace polar::game {

// A translucent band across the screen from `top`, `height` rows tall, for text over a game.
void drawBand(render::Canvas& canvas, int top, int height);
// A screen's heading: big, centred, at `y`.
void drawHeading(render::Canvas& canvas, const std::string& text, int y);
// The line of keys at the bottom of a screen ("ENTER OPEN   ESC BACK").
void drawHelpLine(render::Canvas& canvas, const std::string& text);

}  // namespace polar::game
