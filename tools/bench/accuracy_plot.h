#pragma once
// A scatter plot for the accuracy benchmark, drawn by hand into an RgbaImage: log-scaled x, linear
// y, one labelled point per series, text from a built-in 5×7 pixel font. Enough for a figure in the
// README; not a general renderer.
#include <string>
#include <vector>

#include "polar/png_io.h"

namespace polar::bench {

struct PlotPoint {
    std::string label;
    double x = 0.0;  // > 0 (log scale)
    double y = 0.0;
    std::uint32_t colour = 0xff000000;  // 0xAARRGGBB
};

struct PlotSpec {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    int width = 900;
    int height = 560;
};

// Draws the points with axes, ticks and labels.
RgbaImage scatterPlot(const PlotSpec& spec, const std::vector<PlotPoint>& points);

}  // namespace polar::bench
