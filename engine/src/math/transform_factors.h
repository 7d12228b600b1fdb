#pragma once
#include <cstddef>

#include "polar/transform.h"

namespace polar {

// A Transform's stored numbers as they are in memory, for code that must keep them to the bit: the
// factors and the cached cosine and sine of θ, which a snapshot restores as they were instead of
// computing them again (the same bits either way, at a sine and cosine an object less).
// Order: position x, y, θ, cos θ, sin θ, sx, sy.
struct TransformFactors {
    static constexpr std::size_t kCount = 7;

    static void read(const Transform& t, double* out) {
        out[0] = t.position_.x();
        out[1] = t.position_.y();
        out[2] = t.angle_;
        out[3] = t.cos_;
        out[4] = t.sin_;
        out[5] = t.scale_.x();
        out[6] = t.scale_.y();
    }
    // Sets all seven; cos θ and sin θ are taken as given, so they must be the ones `read` gave.
    static void write(Transform& t, const double* in) {
        t.position_ = Vec2(in[0], in[1]);
        t.angle_ = in[2];
        t.cos_ = in[3];
        t.sin_ = in[4];
        t.scale_ = Vec2(in[5], in[6]);
    }
};

}  // namespace polar
