#pragma once
#include <cstdint>

namespace polar::game {

// How the theatre's last seek went, for observers (the browser test measures seeks in the page).
struct SeekTiming {
    std::uint64_t seeks = 0;                              // seeks so far; the figures are the last one's
    std::uint64_t ticks = 0;                              // ticks stepped after the restore
    double restoreMs = 0, steppingMs = 0, drawingMs = 0;  // drawing: the first frame after it
};

}  // namespace polar::game
