#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "broad_phase/step_data.h"

namespace polar {

// Sort-and-sweep along x: boxes kept sorted by their left edge, then swept so that each box meets
// only the boxes that start before it ends.
//
// Why keep it? It is the classic alternative to a grid and needs no cell size, so it is the
// broad phase measured against the grid (see README). The order persists between steps and is
// repaired by insertion sort, which is nearly linear when objects move little per step. Its weakness
// is a wide scene: every pair overlapping in x is visited, about n²·(box width / scene width).
class SortAndSweep {
  public:
    // Sorts `slots` (ascending) by their boxes' left edges, reusing the last step's order.
    void build(const StepData& data, std::span<const std::uint32_t> slots);
    // Calls visit(i, j), i < j, once for every pair of the built slots whose boxes overlap.
    template <class Visit>
    void forEachPair(Visit&& visit) const;

    std::size_t bytes() const {
        return order_.capacity() * sizeof(Key) + seen_.capacity() * sizeof(std::uint32_t) +
               boxes_.capacity() * sizeof(Box);
    }

  private:
    struct Key {
        double minX;
        std::uint32_t slot;
    };
    std::vector<Box> boxes_;  // by slot
    std::vector<Key> order_;
    std::vector<std::uint32_t> seen_;  // the slot list the order was made for
};

template <class Visit>
void SortAndSweep::forEachPair(Visit&& visit) const {
    for (std::size_t a = 0; a < order_.size(); ++a) {
        const Box& boxA = boxes_[order_[a].slot];
        for (std::size_t b = a + 1; b < order_.size() && order_[b].minX <= boxA.maxX; ++b) {
            const Box& boxB = boxes_[order_[b].slot];
            if (boxA.minY <= boxB.maxY && boxB.minY <= boxA.maxY) {
                std::uint32_t i = order_[a].slot, j = order_[b].slot;
                if (i < j)
                    visit(i, j);
                else
                    visit(j, i);
            }
        }
    }
}

}  // namespace polar
