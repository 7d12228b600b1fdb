#pragma once
#include <vector>

namespace polar {

// The line y = m·x + b.
struct EnvelopeLine {
    double m, b;
    double at(double x) const { return m * x + b; }
};

// One line's stretch [x0, x1] of an envelope.
struct EnvelopePiece {
    double x0, x1;
    EnvelopeLine line;
};

// The lower (min) or upper (max) envelope of lines over [lo, hi] (hi may be ∞), as pieces from left
// to right.
std::vector<EnvelopePiece> envelope(const std::vector<EnvelopeLine>& lines, double lo, double hi, bool lower);

}  // namespace polar
