#include "broad_phase/sort_and_sweep.h"

#include <algorithm>

namespace polar {

void SortAndSweep::build(const StepData& data, std::span<const std::uint32_t> slots) {
    boxes_.resize(data.size());
    for (std::uint32_t s : slots) boxes_[s] = data.box(s);
    const std::vector<Box>& boxes = boxes_;
    if (!std::equal(seen_.begin(), seen_.end(), slots.begin(), slots.end())) {
        seen_.assign(slots.begin(), slots.end());
        order_.clear();
        for (std::uint32_t s : slots) order_.push_back({boxes[s].minX, s});
        std::sort(order_.begin(), order_.end(), [](const Key& a, const Key& b) { return a.minX < b.minX; });
        return;
    }
    for (Key& key : order_) key.minX = boxes[key.slot].minX;
    // Insertion sort: objects move little per step, so each is only a few places out of order.
    for (std::size_t i = 1; i < order_.size(); ++i) {
        Key key = order_[i];
        std::size_t j = i;
        for (; j > 0 && order_[j - 1].minX > key.minX; --j) order_[j] = order_[j - 1];
        order_[j] = key;
    }
}

}  // namespace polar
