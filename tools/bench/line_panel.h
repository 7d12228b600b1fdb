#pragma once
// One panel of a line plot with linear axes starting at zero, drawn into a PlotCanvas: frame, grid
// with labelled ticks, the lines and their legend at the right. The soak and difficulty benchmarks'
// pictures are made of these.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "plot_canvas.h"

namespace polar::bench {

// A step of 1, 2 or 5 times a power of ten that cuts `span` into about `count` pieces.
double niceStep(double span, int count);

// A tick label: "250", "1.5k", "2m".
std::string plotNumber(double value);

struct LineSeries {
    std::string name;
    std::uint32_t colour = 0xFF000000;  // 0xAARRGGBB
    std::vector<std::pair<double, double>> points;
};

struct LinePanel {
    int left = 0, top = 0, right = 0, bottom = 0;  // the frame, in pixels
    double xMax = 1;
    // The top of the y axis; 0: the lines' highest point plus 15 %, at least yFloor and the band's
    // top plus 5 %. The axis always starts at zero, so a flat line reads as flat and a small rise is
    // not magnified into a cliff.
    double yMax = 0;
    double yFloor = 1;
    std::string yLabel;
    std::string xLabel;  // drawn under the tick labels; empty: none
    std::vector<LineSeries> series;
    double bandLow = 0, bandHigh = 0;  // a shaded band (a goal); none when bandHigh <= bandLow
    double markX = 0;                  // a dashed vertical line; none at 0
    bool xLabels = true;               // tick labels under the frame

    void draw(PlotCanvas& canvas) const;
};

}  // namespace polar::bench
