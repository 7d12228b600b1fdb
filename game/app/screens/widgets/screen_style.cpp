#include "app/screens/widgets/screen_style.h"

#include "app/hud/game_drawing.h"
#include "polar/render/shapes.h"

namespace polar::game {

void drawBand(render::Canvas& canvas, int top, int height) {
    render::fillRect(canvas, 0, top, canvas.width(), height, render::Color{0, 0, 0, 170});
}

void drawPanel(render::Canvas& canvas, int x, int y, int width, int height) {
    render::fillRect(canvas, x, y, width, height, render::Color{11, 13, 22, 255});
    render::drawRect(canvas, x, y, width, height, kDimColor);
}

void drawHeading(render::Canvas& canvas, const std::string& text, int y) {
    drawCentredText(canvas, text, y, 3, kGold);
}

}  // namespace polar::game
