#include "app/screens/screen_style.h"

#include <cctype>

#include "app/draw.h"
#include "polar/render/shapes.h"

namespace polar::game {

std::string upperCase(std::string text) {
    for (char& c : text) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return text;
}

void drawBand(render::Canvas& canvas, int top, int height) {
    render::fillRect(canvas, 0, top, canvas.width(), height, render::Color{0, 0, 0, 170});
}

void drawHeading(render::Canvas& canvas, const std::string& text, int y) {
    drawCentredText(canvas, text, y, 3, kTitleColor);
}

void drawHelpLine(render::Canvas& canvas, const std::string& text) {
    drawCentredText(canvas, text, canvas.height() - 40, 1, kDimColor);
}

}  // namespace polar::game
