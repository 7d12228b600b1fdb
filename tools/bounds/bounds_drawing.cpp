#include "bounds_drawing.h"

#include <cmath>
#include <vector>

namespace polar::bounds_tool {

void drawArrow(render::Canvas& canvas, const Vec2& from, const Vec2& to, Color color) {
    render::drawLine(canvas, from, to, color);
    Vec2 back = (from - to).normalized() * 5.0;
    Vec2 side(-back.y() * 0.6, back.x() * 0.6);
    render::drawLine(canvas, to, to + back + side, color);
    render::drawLine(canvas, to, to + back - side, color);
}

void drawCompass(render::Canvas& canvas, const Vec2& c) {
    const double r = 22;
    render::drawCircle(canvas, c, r, kAxes.withAlpha(160));
    drawArrow(canvas, c, c + Vec2(r + 8, 0), kText);
    drawArrow(canvas, c, c + Vec2(0, -(r + 8)), kText);
    render::drawLine(canvas, c, c + Vec2(-r, 0), kAxes);
    render::drawLine(canvas, c, c + Vec2(0, r), kAxes);
    render::drawText(canvas, "0", static_cast<int>(c.x() + r + 11), static_cast<int>(c.y() - 4), 1, kText);
    render::drawText(canvas, "90", static_cast<int>(c.x() - 5), static_cast<int>(c.y() - r - 20), 1, kText);
    render::drawText(canvas, "180", static_cast<int>(c.x() - r - 20), static_cast<int>(c.y() - 13), 1,
                     kDimText);
    render::drawText(canvas, "270", static_cast<int>(c.x() - 8), static_cast<int>(c.y() + r + 4), 1,
                     kDimText);
    // A counter-clockwise arrow from 15° to 75° (canvas y points down, so up is −y).
    std::vector<Vec2> arc;
    for (int i = 0; i <= 12; ++i) {
        double a = degToRad(15 + 60.0 * i / 12);
        arc.push_back(c + Vec2(std::cos(a), -std::sin(a)) * (r * 0.65));
    }
    render::drawPolyline(canvas, arc, kRadiiColors[0]);
    Vec2 tip = arc.back(), dir = (arc.back() - arc[arc.size() - 2]).normalized() * 4.0;
    Vec2 side(-dir.y(), dir.x());
    render::drawLine(canvas, tip, tip - dir + side, kRadiiColors[0]);
    render::drawLine(canvas, tip, tip - dir - side, kRadiiColors[0]);
}

}  // namespace polar::bounds_tool
