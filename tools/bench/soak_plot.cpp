#include "soak_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "plot_canvas.h"

namespace polar::bench {
namespace {

// A step of 1, 2 or 5 times a power of ten that cuts `span` into about `count` pieces.
double niceStep(double span, int count) {
    double raw = span / std::max(1, count);
    double decade = std::pow(10.0, std::floor(std::log10(raw)));
    for (double m : {1.0, 2.0, 5.0})
        if (m * decade >= raw) return m * decade;
    return 10 * decade;
}

std::string number(double value) {
    char buffer[32];
    if (std::fabs(value) >= 1e6)
        std::snprintf(buffer, sizeof buffer, "%gm", value / 1e6);
    else if (std::fabs(value) >= 1e3)
        std::snprintf(buffer, sizeof buffer, "%gk", value / 1e3);
    else
        std::snprintf(buffer, sizeof buffer, "%g", value);
    return buffer;
}

struct Series {
    std::string name;
    std::uint32_t colour;
    std::vector<std::pair<double, double>> points;
};

// One panel: frame, grid with labelled ticks, the series and their legend. The y range always
// includes zero, so a flat line reads as flat and a small rise is not magnified into a cliff.
void drawPanel(PlotCanvas& canvas, int left, int top, int right, int bottom, double xMax,
               const std::string& yLabel, const std::vector<Series>& series, double yFloor, double bandLow,
               double bandHigh, double markX, bool xLabels) {
    const std::uint32_t ink = 0xFF202020, grid = 0xFFDDDDDD;
    double yMax = 0;
    for (const Series& s : series)
        for (auto [x, y] : s.points) yMax = std::max(yMax, y);
    yMax = std::max({yMax * 1.15, bandHigh * 1.05, yFloor});
    auto px = [&](double x) { return left + x / xMax * (right - left); };
    auto py = [&](double y) { return bottom - y / yMax * (bottom - top); };

    if (bandHigh > bandLow)
        canvas.fill(left + 1, static_cast<int>(py(bandHigh)), right - 1, static_cast<int>(py(bandLow)),
                    0xFFE4F4E4);
    double yStep = niceStep(yMax, 5);
    for (double y = 0; y <= yMax; y += yStep) {
        canvas.line(left, py(y), right, py(y), grid);
        std::string label = number(y);
        canvas.text(left - 8 - PlotCanvas::textWidth(label), static_cast<int>(py(y)) - 3, label, ink);
    }
    double xStep = niceStep(xMax, 8);
    for (double x = 0; x <= xMax * 1.0001; x += xStep) {
        canvas.line(px(x), top, px(x), bottom, grid);
        if (!xLabels) continue;
        std::string label = number(x);
        canvas.text(static_cast<int>(px(x)) - PlotCanvas::textWidth(label) / 2, bottom + 8, label, ink);
    }
    if (markX > 0) canvas.line(px(markX), top, px(markX), bottom, 0xFF888888, 1, 4);
    canvas.line(left, top, left, bottom, ink);
    canvas.line(left, bottom, right, bottom, ink);
    canvas.line(right, top, right, bottom, ink);
    canvas.line(left, top, right, top, ink);
    canvas.textUp(left - 62, (top + bottom) / 2 + PlotCanvas::textWidth(yLabel) / 2, yLabel, ink);

    int legendY = top + 6;
    for (const Series& s : series) {
        for (std::size_t k = 1; k < s.points.size(); ++k)
            canvas.line(px(s.points[k - 1].first), py(s.points[k - 1].second), px(s.points[k].first),
                        py(s.points[k].second), s.colour, 2);
        canvas.line(right + 12, legendY + 3, right + 36, legendY + 3, s.colour, 3);
        canvas.text(right + 42, legendY, s.name, ink);
        legendY += 18;
    }
}

}  // namespace

std::optional<Error> SoakPlot::save(const std::string& path, int width, int height) const {
    PlotCanvas canvas(width, height);
    const std::uint32_t ink = 0xFF202020;
    const int left = 90, right = width - 190, top = 50, gap = 40, bottom = height - 60;
    const int middle = (top + bottom - gap) / 2;
    double xMax = points.empty() ? 1 : points.back().tick;

    Series rss{"rss mb", 0xFF2060C0, {}}, cpu{"cpu us", 0xFFC03020, {}}, wall{"wall us", 0xFFE0A020, {}};
    for (const SoakPoint& p : points) {
        rss.points.emplace_back(p.tick, p.rssMb);
        cpu.points.emplace_back(p.tick, p.cpuUs);
        wall.points.emplace_back(p.tick, p.wallUs);
    }
    canvas.text(left, 16, title, ink, 2);
    drawPanel(canvas, left, top, right, middle, xMax, "resident memory, mb", {rss}, 1.0, baselineRssMb,
              baselineRssMb + rssToleranceMb, baselineTick, false);
    drawPanel(canvas, left, middle + gap, right, bottom, xMax, "median per step, us", {cpu, wall}, 1.0, 0, 0,
              baselineTick, true);
    std::string xLabel = "ticks (60 per second of play)";
    canvas.text((left + right) / 2 - PlotCanvas::textWidth(xLabel) / 2, bottom + 30, xLabel, ink);
    canvas.text(right + 12, top + 30, "green: goal band", ink);
    canvas.text(right + 12, top + 48, "dashed: baseline", ink);
    canvas.text(right + 12, top + 60, "tick " + number(baselineTick), ink);
    return savePng(canvas.image, path);
}

}  // namespace polar::bench
