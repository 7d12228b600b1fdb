#include "app/screens/widgets/screen_style.h"

#include "app/hud/game_drawing.h"
#include "polar/render/shapes.h"

namespace polar::game {

void drawBand(render::Canvas& canvas, int top, int height) {
    render::fillRect(canvas, 0, top, canvas.width(), height, render::Color{0, 0, 0, 170});
}

void drawHeading(render::Canvas& canvas, const std::string& text, int y) {
    drawCentredText(canvas, text, y, 3, kGold);
}

void drawHelpLine(render::Canvas& canvas, const std::string& text) {
    drawCentredText(canvas, text, canvas.height() - 40, 1, kDimColor);
}

}  // namespace polar::game
