#include "log_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plot_canvas.h"

namespace polar::bench {
namespace {

std::string decadeLabel(double value, bool isTime) {
    char buffer[32];
    if (isTime) {
        if (value >= 1000)
            std::snprintf(buffer, sizeof buffer, "%g s", value / 1000);
        else
            std::snprintf(buffer, sizeof buffer, "%g ms", value);
    } else if (value >= 1000) {
        std::snprintf(buffer, sizeof buffer, "%gk", value / 1000);
    } else {
        std::snprintf(buffer, sizeof buffer, "%g", value);
    }
    return buffer;
}

}  // namespace

RgbaImage LogLogPlot::draw(int width, int height) const {
    PlotCanvas canvas(width, height);
    const std::uint32_t ink = 0xFF202020, grid = 0xFFDDDDDD, minor = 0xFFF0F0F0;

    double xMin = INFINITY, xMax = 0, yMin = INFINITY, yMax = 0;
    auto include = [&](double x, double y) {
        xMin = std::min(xMin, x), xMax = std::max(xMax, x), yMin = std::min(yMin, y),
        yMax = std::max(yMax, y);
    };
    for (const PlotSeries& s : series)
        for (auto [x, y] : s.points) include(x, y);
    for (const PlotRange& r : ranges) include(r.x, r.low), include(r.x, r.high);
    for (const PlotLevel& l : levels) include(xMin, l.y);
    if (!(xMax > 0)) xMin = 1, xMax = 10, yMin = 1, yMax = 10;
    // x padded by a third of a decade so end points sit inside the frame; y in whole decades.
    double lx0 = std::log10(xMin) - 0.33, lx1 = std::log10(xMax) + 0.33;
    double ly0 = std::floor(std::log10(yMin)), ly1 = std::ceil(std::log10(yMax));
    if (ly1 <= ly0) ly1 = ly0 + 1;

    const int left = 90, right = width - 200, top = 50, bottom = height - 60;
    auto px = [&](double x) { return left + (std::log10(x) - lx0) / (lx1 - lx0) * (right - left); };
    auto py = [&](double y) { return bottom - (std::log10(y) - ly0) / (ly1 - ly0) * (bottom - top); };

    for (double d = std::floor(lx0); d <= lx1; ++d) {
        for (int m = 1; m < 10; ++m) {
            double x = m * std::pow(10, d);
            if (std::log10(x) < lx0 || std::log10(x) > lx1) continue;
            canvas.line(px(x), top, px(x), bottom, m == 1 ? grid : minor);
            if (m != 1) continue;
            std::string label = decadeLabel(x, false);
            canvas.text(static_cast<int>(px(x)) - PlotCanvas::textWidth(label) / 2, bottom + 8, label, ink);
        }
    }
    for (double d = ly0; d <= ly1; ++d) {
        for (int m = 2; m < 10 && d < ly1; ++m)
            canvas.line(left, py(m * std::pow(10, d)), right, py(m * std::pow(10, d)), minor);
        canvas.line(left, py(std::pow(10, d)), right, py(std::pow(10, d)), grid);
        std::string label = decadeLabel(std::pow(10, d), true);
        canvas.text(left - 8 - PlotCanvas::textWidth(label), static_cast<int>(py(std::pow(10, d))) - 3, label,
                    ink);
    }
    canvas.line(left, top, left, bottom, ink);
    canvas.line(left, bottom, right, bottom, ink);
    canvas.line(right, top, right, bottom, ink);
    canvas.line(left, top, right, top, ink);

    canvas.text(left, 16, title, ink, 2);
    canvas.text((left + right) / 2 - PlotCanvas::textWidth(xLabel) / 2, bottom + 30, xLabel, ink);
    canvas.textUp(20, (top + bottom) / 2 + PlotCanvas::textWidth(yLabel) / 2, yLabel, ink);

    int legendY = top + 4;
    auto legend = [&](const std::string& name, std::uint32_t colour, bool dashed) {
        canvas.line(right + 12, legendY + 3, right + 36, legendY + 3, colour, 3, dashed ? 4 : 0);
        canvas.text(right + 42, legendY, name, ink);
        legendY += 18;
    };
    for (const PlotLevel& l : levels) {
        canvas.line(left, py(l.y), right, py(l.y), l.colour, 2, 6);
        legend(l.label, l.colour, true);
    }
    for (const PlotRange& r : ranges) {
        double x = px(r.x);
        canvas.line(x, py(r.low), x, py(r.high), r.colour, 7);
        canvas.line(x - 7, py(r.low), x + 7, py(r.low), r.colour, 2);
        canvas.line(x - 7, py(r.high), x + 7, py(r.high), r.colour, 2);
    }
    if (!ranges.empty()) legend(ranges.front().label, ranges.front().colour, false);
    for (const PlotSeries& s : series) {
        for (std::size_t k = 1; k < s.points.size(); ++k)
            canvas.line(px(s.points[k - 1].first), py(s.points[k - 1].second), px(s.points[k].first),
                        py(s.points[k].second), s.colour, s.dashed ? 2 : 3, s.dashed ? 5 : 0);
        int half = s.dashed ? 3 : 4;
        for (auto [x, y] : s.points) {
            int cx = static_cast<int>(std::lround(px(x))), cy = static_cast<int>(std::lround(py(y)));
            canvas.fill(cx - half, cy - half, cx + half, cy + half, s.colour);
        }
        legend(s.name, s.colour, s.dashed);
    }
    return canvas.image;
}

}  // namespace polar::bench
