#include "soak_plot.h"

#include "line_panel.h"

namespace polar::bench {

std::optional<Error> SoakPlot::save(const std::string& path, int width, int height) const {
    PlotCanvas canvas(width, height);
    const std::uint32_t ink = 0xFF202020;
    const int left = 90, right = width - 190, top = 50, gap = 40, bottom = height - 60;
    const int middle = (top + bottom - gap) / 2;
    double xMax = points.empty() ? 1 : points.back().tick;

    LineSeries rss{"rss mb", 0xFF2060C0, {}}, cpu{"cpu us", 0xFFC03020, {}}, wall{"wall us", 0xFFE0A020, {}};
    for (const SoakPoint& p : points) {
        rss.points.emplace_back(p.tick, p.rssMb);
        cpu.points.emplace_back(p.tick, p.cpuUs);
        wall.points.emplace_back(p.tick, p.wallUs);
    }
    canvas.text(left, 16, title, ink, 2);
    LinePanel memory;
    memory.left = left, memory.top = top, memory.right = right, memory.bottom = middle;
    memory.xMax = xMax;
    memory.yLabel = "resident memory, mb";
    memory.series = {rss};
    memory.bandLow = baselineRssMb, memory.bandHigh = baselineRssMb + rssToleranceMb;
    memory.markX = baselineTick;
    memory.xLabels = false;
    memory.draw(canvas);
    LinePanel time = memory;
    time.top = middle + gap, time.bottom = bottom;
    time.yLabel = "median per step, us";
    time.series = {cpu, wall};
    time.bandLow = time.bandHigh = 0;
    time.xLabels = true;
    time.draw(canvas);
    std::string xLabel = "ticks (60 per second of play)";
    canvas.text((left + right) / 2 - PlotCanvas::textWidth(xLabel) / 2, bottom + 30, xLabel, ink);
    canvas.text(right + 12, top + 30, "green: goal band", ink);
    canvas.text(right + 12, top + 48, "dashed: baseline", ink);
    canvas.text(right + 12, top + 60, "tick " + plotNumber(baselineTick), ink);
    return savePng(canvas.image, path);
}

}  // namespace polar::bench
