#include "accuracy_plot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

#include "polar/platform/image_file.h"
#include "polar/render/render.h"

namespace polar::bench {
namespace {

using render::Canvas;
using render::Color;

std::string tickText(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%g", v);
    return buffer;
}

void line(Canvas& canvas, double x0, double y0, double x1, double y1, Color c) {
    render::drawLine(canvas, Vec2(x0, y0), Vec2(x1, y1), c);
}

}  // namespace

std::optional<Error> saveScatterPlot(const std::string& path, const PlotSpec& spec,
                                     const std::vector<PlotPoint>& points) {
    Canvas canvas(spec.width, spec.height);
    canvas.clear(render::kWhite);
    const Color ink{32, 32, 32, 255}, grid{228, 228, 228, 255}, axis{96, 96, 96, 255};
    const int scale = 2;
    const int left = 80, right = spec.width - 30, top = 70, bottom = spec.height - 70;

    // Both axes logarithmic: the levels' errors and costs each span well over a decade.
    auto decades = [&](auto get, double& lo, double& hi) {
        double min = INFINITY, max = 0;
        for (const PlotPoint& p : points) {
            double v = std::max(get(p), 1e-6);
            min = std::min(min, v);
            max = std::max(max, v);
        }
        if (points.empty()) min = 1, max = 10;
        lo = std::pow(10.0, std::floor(std::log10(min)));
        hi = std::pow(10.0, std::ceil(std::log10(max)));
        if (hi <= lo) hi = lo * 10;
    };
    double xLo, xHi, yLo, yHi;
    decades([](const PlotPoint& p) { return p.x; }, xLo, xHi);
    decades([](const PlotPoint& p) { return p.y; }, yLo, yHi);
    auto px = [&](double x) {
        return left +
               (std::log10(x) - std::log10(xLo)) / (std::log10(xHi) - std::log10(xLo)) * (right - left);
    };
    auto py = [&](double y) {
        y = std::max(y, 1e-6);
        return bottom -
               (std::log10(y) - std::log10(yLo)) / (std::log10(yHi) - std::log10(yLo)) * (bottom - top);
    };
    auto text = [&](const std::string& s, int x, int y, Color c) {
        render::drawText(canvas, s, x, y, scale, c);
    };
    auto width = [&](const std::string& s) { return render::measureText(s, scale).width; };

    // Grid and ticks at 1, 2, 5 × 10^k on both axes.
    auto ticks = [](double lo, double hi, auto draw) {
        for (double decade = lo; decade < hi * 1.001; decade *= 10)
            for (double m : {1.0, 2.0, 5.0})
                if (decade * m <= hi * 1.001) draw(decade * m);
    };
    ticks(xLo, xHi, [&](double x) {
        double X = px(x);
        line(canvas, X, top, X, bottom, grid);
        line(canvas, X, bottom, X, bottom + 5, axis);
        text(tickText(x), static_cast<int>(X) - width(tickText(x)) / 2, bottom + 10, ink);
    });
    ticks(yLo, yHi, [&](double y) {
        double Y = py(y);
        line(canvas, left, Y, right, Y, grid);
        line(canvas, left - 5, Y, left, Y, axis);
        text(tickText(y), left - 10 - width(tickText(y)), static_cast<int>(Y) - 7, ink);
    });
    line(canvas, left, top, left, bottom, axis);
    line(canvas, left, bottom, right, bottom, axis);
    text(spec.title, (left + right - width(spec.title)) / 2, 14, ink);
    text(spec.yLabel, left - 60, top - 30, ink);
    text(spec.xLabel, (left + right - width(spec.xLabel)) / 2, spec.height - 34, ink);

    // Points, then labels beside them, nudged up when they would overprint an earlier label.
    std::vector<std::array<int, 4>> placed;  // x0, y0, x1, y1 of the labels drawn
    for (const PlotPoint& p : points)
        render::fillCircle(canvas, Vec2(px(p.x), py(p.y)), 6, Color::fromArgb(p.colour));
    for (const PlotPoint& p : points) {
        int X = static_cast<int>(px(p.x)), Y = static_cast<int>(py(p.y));
        int w = width(p.label), h = render::measureText(p.label, scale).height;
        int x0 = X + 10 + w < right ? X + 10 : X - 10 - w;
        int y0 = Y - h / 2;
        for (bool moved = true; moved;) {
            moved = false;
            for (const auto& b : placed) {
                if (x0 <= b[2] && x0 + w >= b[0] && y0 <= b[3] && y0 + h >= b[1]) {
                    y0 = b[1] - h - 3;
                    moved = true;
                }
            }
        }
        text(p.label, x0, y0, Color::fromArgb(p.colour));
        placed.push_back({x0, y0, x0 + w, y0 + h});
    }
    return render::savePng(canvas, path);
}

}  // namespace polar::bench
