#pragma once
#include "narrow_phase/pair_rule.h"

namespace polar {

// Whether two circles share a point (touching counts), from the difference of their centres
// (dx, dy) = c₁ − c₂ and the sum of their radii: the contact rule's verdict on circles,
// contactHit(|c₁ − c₂|², r₁ + r₂), i.e. dx² + dy² ≤ (r₁ + r₂)². A NaN anywhere makes it false.
inline bool circlesOverlap(double dx, double dy, double radiusSum) {
    return contactHit(dx * dx + dy * dy, radiusSum);
}

// A world centre and a reach: a radius with its rounding allowance in one number (24 bytes). The
// broad phase's candidate circles: the grid's entries and compound objects' radii.
struct Disc {
    double x = 0.0;
    double y = 0.0;
    double reach = 0.0;

    bool touches(const Disc& o) const { return circlesOverlap(x - o.x, y - o.y, reach + o.reach); }
};

}  // namespace polar
