#pragma once
// A scatter plot for the accuracy benchmark, drawn with Polarcade's renderer: both axes log-scaled,
// one labelled point per series. Enough for a figure in the README; not a plotting library.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "polar/error.h"

namespace polar::bench {

struct PlotPoint {
    std::string label;
    double x = 0.0;                     // > 0 (log scale)
    double y = 0.0;                     // > 0 (log scale; drawn at 1e-6 when 0)
    std::uint32_t colour = 0xff000000;  // 0xAARRGGBB
};

struct PlotSpec {
    std::string title;
    std::string xLabel;
    std::string yLabel;
    int width = 900;
    int height = 560;
};

// Draws the points with axes, ticks and labels and writes the PNG atomically.
std::optional<Error> saveScatterPlot(const std::string& path, const PlotSpec& spec,
                                     const std::vector<PlotPoint>& points);

}  // namespace polar::bench
