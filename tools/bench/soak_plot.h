#pragma once
// The soak benchmark's picture: resident memory and per-step time against ticks, two panels with
// linear axes, one above the other, sharing the tick axis.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "polar/error.h"

namespace polar::bench {

// One window of the soak run, as plotted.
struct SoakPoint {
    double tick = 0;    // the window's last tick
    double rssMb = 0;   // resident memory at that tick
    double cpuUs = 0;   // median thread CPU time per step over the window
    double wallUs = 0;  // median wall time per step over the window
};

struct SoakPlot {
    std::string title;
    std::vector<SoakPoint> points;
    double baselineTick = 0;    // where the memory goal's baseline is read (a dashed line)
    double rssToleranceMb = 1;  // drawn as a band above the baseline's RSS
    double baselineRssMb = 0;

    // Draws both panels and writes the PNG atomically.
    std::optional<Error> save(const std::string& path, int width = 900, int height = 620) const;
};

}  // namespace polar::bench
