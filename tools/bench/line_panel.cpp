#include "line_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace polar::bench {

double niceStep(double span, int count) {
    double raw = span / std::max(1, count);
    double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= raw) return m * decade;
    return 10 * decade;
}

std::string plotNumber(double value) {
    char buffer[32];
    if (std::fabs(value) >= 1e6)
        std::snprintf(buffer, sizeof buffer, "%gm", value / 1e6);
    else if (std::fabs(value) >= 1e3)
        std::snprintf(buffer, sizeof buffer, "%gk", value / 1e3);
    else
        std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

void LinePanel::draw(PlotCanvas& canvas) const {
    const std::uint32_t ink = 0xFF202020, grid = 0xFFDDDDDD;
    double yTop = yMax;
    if (yTop <= 0) {
        for (const LineSeries& s : series)
            for (auto [x, y] : s.points) yTop = std::max(yTop, y);
        yTop = std::max({yTop * 1.15, bandHigh * 1.05, yFloor});
    }
    auto px = [&](double x) { return left + x / xMax * (right - left); };
    auto py = [&](double y) { return bottom - y / yTop * (bottom - top); };

    if (bandHigh > bandLow)
        canvas.fill(left + 1, static_cast<int>(py(bandHigh)), right - 1, static_cast<int>(py(bandLow)),
                    0xFFE4F4E4);
    double yStep = niceStep(yTop, 5);
    for (double y = 0; y <= yTop * 1.0001; y += yStep) {
        canvas.line(left, py(y), right, py(y), grid);
        std::string label = plotNumber(y);
        canvas.text(left - 8 - PlotCanvas::textWidth(label), static_cast<int>(py(y)) - 3, label, ink);
    }
    double xStep = niceStep(xMax, 8);
    for (double x = 0; x <= xMax * 1.0001; x += xStep) {
        canvas.line(px(x), top, px(x), bottom, grid);
        if (!xLabels) continue;
        std::string label = plotNumber(x);
        canvas.text(static_cast<int>(px(x)) - PlotCanvas::textWidth(label) / 2, bottom + 8, label, ink);
    }
    if (markX > 0) canvas.line(px(markX), top, px(markX), bottom, 0xFF888888, 1, 4);
    canvas.line(left, top, left, bottom, ink);
    canvas.line(left, bottom, right, bottom, ink);
    canvas.line(right, top, right, bottom, ink);
    canvas.line(left, top, right, top, ink);
    canvas.textUp(left - 62, (top + bottom) / 2 + PlotCanvas::textWidth(yLabel) / 2, yLabel, ink);
    if (!xLabel.empty())
        canvas.text((left + right) / 2 - PlotCanvas::textWidth(xLabel) / 2, bottom + 24, xLabel, ink);

    int legendY = top + 6;
    for (const LineSeries& s : series) {
        for (std::size_t k = 1; k < s.points.size(); ++k)
            canvas.line(px(s.points[k - 1].first), py(s.points[k - 1].second), px(s.points[k].first),
                        py(s.points[k].second), s.colour, 2);
        canvas.line(right + 12, legendY + 3, right + 36, legendY + 3, s.colour, 3);
        canvas.text(right + 42, legendY, s.name, ink);
        legendY += 18;
    }
}

}  // namespace polar::bench
