#pragma once
// Log-log line plots drawn straight into an RgbaImage, for benchmarks that print a picture.
#include <cstdint>
#include <string>
#include <vector>

#include "polar/platform/png_io.h"

namespace polar::bench {

struct PlotSeries {
    std::string name;
    std::uint32_t colour = 0xFF000000;              // 0xAARRGGBB
    std::vector<std::pair<double, double>> points;  // (x, y), both > 0
    bool dashed = false;
};

// A vertical range at one x (a reference measured elsewhere).
struct PlotRange {
    std::string label;
    std::uint32_t colour = 0xFF888888;
    double x = 0.0, low = 0.0, high = 0.0;
};

// A horizontal reference line (a goal).
struct PlotLevel {
    std::string label;
    std::uint32_t colour = 0xFF888888;
    double y = 0.0;
};

struct LogLogPlot {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    std::vector<PlotSeries> series;
    std::vector<PlotRange> ranges;
    std::vector<PlotLevel> levels;

    // Draws the plot with decade grid lines, labelled ticks and a legend.
    RgbaImage draw(int width, int height) const;
};

}  // namespace polar::bench
