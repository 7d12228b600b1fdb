#pragma once
// Per-step data for broad-phase unit tests, built straight from discs.
#include <cstdint>
#include <vector>

#include "broad_phase/disc.h"
#include "broad_phase/step_data.h"

namespace polar {

// Per-step data holding only what the broad phases read: a reach circle per slot, without margin,
// so that slot s's circle is exactly discs[s] (and its box the square around it).
inline StepData stepDataOf(const std::vector<Disc>& discs) {
    StepData data;
    for (std::uint32_t s = 0; s < discs.size(); ++s) {
        data.objectIndex.push_back(s);
        ReachCircle c;
        c.x = discs[s].x;
        c.y = discs[s].y;
        c.radius = discs[s].reach;
        data.reach.push_back(c);
        data.regularSlots.push_back(s);
    }
    return data;
}

}  // namespace polar
