#pragma once
#include <string>

#include "polar/render/canvas.h"
#include "polar/render/color.h"

namespace polar::game {

// The colours every screen draws its words in, and the dark band menus sit on.
inline constexpr render::Color kTitleColor{255, 214, 120, 255};
inline constexpr render::Color kTextColor{220, 228, 255, 255};
inline constexpr render::Color kDimColor{150, 160, 200, 255};
inline constexpr render::Color kWarnColor{255, 120, 110, 255};

// `text` in capitals, as the screens write names ("cave" → "CAVE").
std::string upperCase(std::string text);

// A translucent band across the screen from `top`, `height` rows tall, for text over a game.
void drawBand(render::Canvas& canvas, int top, int height);
// A screen's heading: big, centred, at `y`.
void drawHeading(render::Canvas& canvas, const std::string& text, int y);
// The line of keys at the bottom of a screen ("ENTER OPEN   ESC BACK").
void drawHelpLine(render::Canvas& canvas, const std::string& text);

}  // namespace polar::game
