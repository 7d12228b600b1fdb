#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "broad_phase/step_data.h"
#include "polar/tasks.h"

namespace polar {

// A hierarchy of uniform grids, rebuilt every step by one counting sort into flat arrays.
//
// Why this shape? Tier T has square cells of side c·2^T; an object lives at the lowest tier whose
// cell is at least as large as its box, entered once, in the cell holding its box's lower-left
// corner (its home). Its box then spans at most 2×2 cells of its tier and of every tier above, so
// any object it may touch has its home in a small block of cells: at its own tier the 2×2 block
// after its home (earlier homes find it instead), at higher tiers the 3×3 block reaching one cell
// below-left. Mixed sizes cost nothing extra: giants sit at high tiers with few cells. Slots are
// sorted by home (row-major within a tier), so a pass in that order walks memory nearly in sequence,
// and the next step builds its per-step data in this order, which keeps it spatially coherent.
// Cells are indexed densely when the scene's extent allows (≤ 8 cells per object), otherwise hashed;
// a hashed bucket can hold several cells, so entries are matched by their home, never assumed.
class UniformGrid {
  public:
    // The task system for the build's per-slot loops (null: all on the calling thread), and the
    // size below which a loop runs on the calling thread anyway. The grid does not depend on either.
    void setTasks(TaskSystem* tasks, std::uint32_t parallelMin);
    // Builds the grid over `slots` by their boxes, with a base cell c = cellFactor × (a sample
    // median of the boxes' larger sides), kept from the last build unless it is off by 1.5×.
    void build(const StepData& data, std::span<const std::uint32_t> slots, double cellFactor);

    // The slots in home order.
    std::span<const std::uint32_t> sorted() const { return sorted_; }
    // Slots too large for the deepest tier (side > c·2^63), not in the grid: pair them linearly.
    const std::vector<std::uint32_t>& huge() const { return huge_; }
    double cellSize() const { return cell_; }
    bool dense() const { return dense_; }
    std::size_t tierCount() const { return usedTiers_.size(); }

    // For the slot at sorted position p, calls visit(j) for every slot j whose reach circle may
    // overlap its own and which the pass does not visit from j's side: over all p, each such pair
    // once. (A fast slot's circle here holds its whole cast box.)
    template <class Visit>
    void forEachPartner(std::size_t p, Visit&& visit) const;
    // Calls visit(j) once for every slot whose box may overlap `query`.
    template <class Visit>
    void forEachOverlapping(const Box& query, Visit&& visit) const;

    std::size_t bytes() const;

  private:
    static constexpr int kMaxTiers = 64;
    // Cell coordinates are clamped to ±kCellLimit, far inside int32, so that x ± 1 never overflows.
    // Any monotone map from world to cells keeps the grid exact; clamping only merges cells at
    // 2^26 cells from the grid's corner, which no scene of objects that size fills.
    static constexpr std::int32_t kCellLimit = 1 << 26;
    // A slot's home: the cell holding its box's lower-left corner, in its tier (kMaxTiers: none),
    // packed in 8 bytes since the pair loop reads one per slot: x and y offset by kCellLimit in 28
    // bits each, the tier in the top 8.
    struct Home {
        std::uint64_t bits = 0;

        static Home of(std::uint32_t tier, std::int32_t x, std::int32_t y) {
            return {(std::uint64_t(tier) << 56) | (std::uint64_t(std::uint32_t(y + kCellLimit)) << 28) |
                    std::uint64_t(std::uint32_t(x + kCellLimit))};
        }
        std::uint32_t tier() const { return static_cast<std::uint32_t>(bits >> 56); }
        std::int32_t x() const { return static_cast<std::int32_t>(bits & kField) - kCellLimit; }
        std::int32_t y() const { return static_cast<std::int32_t>((bits >> 28) & kField) - kCellLimit; }
        bool operator==(const Home&) const = default;

      private:
        static constexpr std::uint64_t kField = (std::uint64_t(1) << 28) - 1;
    };
    static_assert(2 * kCellLimit < (1 << 28) && kMaxTiers < 256, "a home's fields fit their bits");
    // A slot's reach circle as a Disc, copied in home order so that the pair loop reads candidates
    // from contiguous memory. Its slot is sorted_ at the same position.
    using Entry = Disc;
    struct Tier {
        double side = 1.0;                   // cell side, c·2^T
        double inverse = 1.0;                // 1 / side
        std::int64_t width = 0, height = 0;  // dense cells per row and rows
        std::uint64_t base = 0;              // first dense cell of this tier
    };

    // One worker's share of the extent, the tiers used and the slots too large for any tier.
    struct Partial {
        double minX = INFINITY, minY = INFINITY, maxX = -INFINITY, maxY = -INFINITY;
        std::uint64_t tierMask = 0;
        std::size_t huge = 0;
    };

    std::int32_t cellOf(double v, double origin, const Tier& tier) const;
    // The counting-sort key of a cell, or kNoCell for a dense cell outside the grid.
    std::uint64_t keyOf(std::uint32_t tier, std::int32_t x, std::int32_t y) const;
    // The homes, keys and counting sort by key on the task system (see build).
    template <class HomeAndKey>
    void sortShared(std::span<const std::uint32_t> slots, HomeAndKey& homeAndKey, std::uint64_t keyCount);
    template <class Visit>
    void visitCell(std::uint32_t tier, std::int32_t x, std::int32_t y, Visit&& visit) const;
    // visitCell for cells x0..x1 of row y, in order. Dense cells of a row are consecutive keys, so
    // there it is one run of sorted positions, not a look-up per cell.
    template <class Visit>
    void visitRow(std::uint32_t tier, std::int32_t x0, std::int32_t x1, std::int32_t y, Visit&& visit) const;
    static constexpr std::uint64_t kNoCell = ~std::uint64_t(0);

    const StepData* data_ = nullptr;
    double cell_ = 0.0;
    double originX_ = 0.0, originY_ = 0.0;
    bool dense_ = true;
    int hashShift_ = 60;
    std::array<Tier, kMaxTiers> tiers_{};
    std::vector<std::uint32_t> usedTiers_;  // ascending
    std::vector<Home> homes_;               // by slot
    std::vector<std::uint32_t> starts_;     // cell or bucket k holds sorted_[starts_[k], starts_[k + 1])
    std::vector<std::uint32_t> sorted_;
    std::vector<Entry> entries_;  // by sorted position
    std::vector<std::uint32_t> huge_;
    std::vector<std::uint32_t> keys_;  // by slot, scratch: cell keys fit (≤ 8 cells or 4 buckets per slot)
    std::vector<double> sample_;       // scratch for the median
    std::vector<std::uint32_t> rangeAt_;  // shared sort: per range of keys and block, where its slots go
    std::vector<std::uint32_t> dealt_;    // shared sort: the slots by range of keys
    std::vector<Partial> partials_{Partial{}};  // per worker (one without a task system)
    TaskSystem* tasks_ = nullptr;
    std::uint32_t parallelMin_ = 0;
};

template <class Visit>
void UniformGrid::visitCell(std::uint32_t tier, std::int32_t x, std::int32_t y, Visit&& visit) const {
    std::uint64_t key = keyOf(tier, x, y);
    if (key == kNoCell) return;
    Home cell = Home::of(tier, x, y);
    for (std::uint32_t q = starts_[key], end = starts_[key + 1]; q < end; ++q) {
        if (!dense_ && homes_[sorted_[q]] != cell) continue;
        visit(q);
    }
}

template <class Visit>
void UniformGrid::visitRow(std::uint32_t tier, std::int32_t x0, std::int32_t x1, std::int32_t y,
                           Visit&& visit) const {
    if (!dense_) {
        for (std::int32_t x = x0; x <= x1; ++x) visitCell(tier, x, y, visit);
        return;
    }
    const Tier& t = tiers_[tier];
    if (y < 0 || y >= t.height) return;
    x0 = std::max(x0, 0);
    x1 = static_cast<std::int32_t>(std::min<std::int64_t>(x1, t.width - 1));
    if (x0 > x1) return;
    for (std::uint32_t q = starts_[keyOf(tier, x0, y)], end = starts_[keyOf(tier, x1, y) + 1]; q < end; ++q)
        visit(q);
}

template <class Visit>
void UniformGrid::forEachPartner(std::size_t p, Visit&& visit) const {
    const Entry& self = entries_[p];
    std::uint32_t i = sorted_[p];
    Home home = homes_[i];
    std::uint32_t tier = home.tier();
    std::int32_t hx = home.x(), hy = home.y();
    auto candidate = [&](std::uint32_t q) {
        if (self.touches(entries_[q])) visit(sorted_[q]);
    };
    // Same tier: the rest of the home cell, then the cell to the right and the three above.
    std::uint64_t key = keyOf(tier, hx, hy);
    for (std::uint32_t q = static_cast<std::uint32_t>(p) + 1, end = starts_[key + 1]; q < end; ++q) {
        if (!dense_ && homes_[sorted_[q]] != home) continue;
        candidate(q);
    }
    visitCell(tier, hx + 1, hy, candidate);
    visitRow(tier, hx - 1, hx + 1, hy + 1, candidate);
    // Higher tiers: every home from one cell below-left of the box's cells to its last cell.
    Box box = data_->box(i);
    for (std::uint32_t upper : usedTiers_) {
        if (upper <= tier) continue;
        const Tier& t = tiers_[upper];
        std::int32_t x0 = cellOf(box.minX, originX_, t) - 1, x1 = cellOf(box.maxX, originX_, t);
        std::int32_t y0 = cellOf(box.minY, originY_, t) - 1, y1 = cellOf(box.maxY, originY_, t);
        for (std::int32_t y = y0; y <= y1; ++y) visitRow(upper, x0, x1, y, candidate);
    }
}

template <class Visit>
void UniformGrid::forEachOverlapping(const Box& query, Visit&& visit) const {
    for (std::uint32_t tier : usedTiers_) {
        const Tier& t = tiers_[tier];
        std::int32_t x0 = cellOf(query.minX, originX_, t) - 1, x1 = cellOf(query.maxX, originX_, t);
        std::int32_t y0 = cellOf(query.minY, originY_, t) - 1, y1 = cellOf(query.maxY, originY_, t);
        if (std::int64_t(x1 - x0 + 1) * std::int64_t(y1 - y0 + 1) > std::int64_t(sorted_.size()) + 16) {
            // A query wider than the grid's contents: test every home of this tier instead.
            for (std::uint32_t j : sorted_) {
                Home h = homes_[j];
                if (h.tier() == tier && h.x() >= x0 && h.x() <= x1 && h.y() >= y0 && h.y() <= y1) visit(j);
            }
            continue;
        }
        for (std::int32_t y = y0; y <= y1; ++y)
            for (std::int32_t x = x0; x <= x1; ++x)
                visitCell(tier, x, y, [&](std::uint32_t q) { visit(sorted_[q]); });
    }
}

}  // namespace polar
