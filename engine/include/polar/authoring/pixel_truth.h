#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "polar/authoring/alpha_mask.h"
#include "polar/math.h"

namespace polar {

// The opaque pixels of a sprite (alpha above a threshold) as squares in bound space, for the
// ground truth that accuracy levels are measured against.
//
// Why keep the boundary pixels apart? Two unions of squares overlap iff a boundary square of one
// overlaps a square of the other: if no boundary square of B meets A, B's outline never enters A,
// so A's part inside B lies wholly within B and A's own boundary squares meet B. Testing only the
// boundary squares of each against all squares of the other is exact and costs the perimeter, not
// the area.
class OpaquePixels {
  public:
    explicit OpaquePixels(const AlphaMask& mask, std::uint8_t threshold = AlphaMask::kDefaultThreshold);

    const AlphaMask& mask() const { return mask_; }
    bool opaque(int x, int y) const {
        return x >= 0 && y >= 0 && x < mask_.width && y < mask_.height &&
               opaque_[static_cast<std::size_t>(y) * mask_.width + x];
    }
    // Opaque pixels with a transparent (or missing) 4-neighbour, as (x, y).
    const std::vector<std::array<int, 2>>& boundary() const { return boundary_; }
    // The farthest opaque pixel corner from the bound-space origin.
    double boundRadius() const { return boundRadius_; }
    bool empty() const { return boundary_.empty(); }

  private:
    AlphaMask mask_;
    std::vector<std::uint8_t> opaque_;
    std::vector<std::array<int, 2>> boundary_;
    double boundRadius_ = 0.0;
};

// Whether the opaque pixels of two sprites, each placed by world(q) = position + L·q, overlap with
// positive area. Each pixel is its exact square mapped to a parallelogram; pairs are decided by the
// separating-axis test (two axes of a square, two of a parallelogram), so the answer is exact up to
// rounding. A singular L gives pixels of zero area, which overlap nothing.
bool opaquePixelsOverlap(const OpaquePixels& a, const Vec2& positionA, const Mat2& linearA,
                         const OpaquePixels& b, const Vec2& positionB, const Mat2& linearB);

}  // namespace polar
