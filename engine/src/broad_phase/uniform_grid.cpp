#include "broad_phase/uniform_grid.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "broad_phase/counting_sort.h"
#include "tasks/blocks.h"
#include "tasks/parallel_for.h"

namespace polar {
namespace {

// Dense indexing while the cells number at most this many per object (plus a little).
constexpr std::uint64_t kDenseCellsPerObject = 8;
constexpr std::size_t kSampleSize = 1024;
// Slots per range when the build is shared: enough that a range outlasts claiming it.
constexpr std::uint32_t kMinRange = 1024;
// The shared sort's blocks of slots (and ranges of keys): a few per worker, and few enough that the
// table of counts per block and range stays small.
constexpr std::uint32_t kSortBlocksPerWorker = 4;
constexpr std::uint32_t kMaxSortBlocks = 256;

}  // namespace

std::int32_t UniformGrid::cellOf(double v, double origin, const Tier& tier) const {
    double c = std::floor((v - origin) * tier.inverse);
    constexpr double kLimit = kCellLimit;
    return static_cast<std::int32_t>(std::clamp(c, -kLimit, kLimit));
}

std::uint64_t UniformGrid::keyOf(std::uint32_t tier, std::int32_t x, std::int32_t y) const {
    const Tier& t = tiers_[tier];
    if (dense_) {
        if (x < 0 || y < 0 || x >= t.width || y >= t.height) return kNoCell;
        return t.base + std::uint64_t(y) * std::uint64_t(t.width) + std::uint64_t(x);
    }
    std::uint64_t key = (std::uint64_t(std::uint32_t(x)) << 32) | std::uint32_t(y);
    key = (key ^ (std::uint64_t(tier) * 0xD6E8FEB86659FD93ull)) * 0x9E3779B97F4A7C15ull;
    return key >> hashShift_;
}

void UniformGrid::setTasks(TaskSystem* tasks, std::uint32_t parallelMin) {
    tasks_ = tasks;
    parallelMin_ = parallelMin;
    partials_.resize(tasks ? tasks->workerCount() : 1);
}

void UniformGrid::build(const StepData& data, std::span<const std::uint32_t> slots, double cellFactor) {
    data_ = &data;
    usedTiers_.clear();
    sorted_.clear();
    huge_.clear();
    homes_.resize(data.size());
    if (slots.empty()) {
        starts_.assign(2, 0);
        dense_ = true;
        return;
    }

    // Base cell: the median larger side of an evenly strided sample, with hysteresis so that the
    // homes (and so the memory order) stay put from step to step. Any cell keeps the grid exact.
    sample_.clear();
    std::size_t stride = std::max<std::size_t>(1, slots.size() / kSampleSize);
    for (std::size_t k = 0; k < slots.size(); k += stride) {
        Box b = data.box(slots[k]);
        sample_.push_back(std::max(b.maxX - b.minX, b.maxY - b.minY));
    }
    auto middle = sample_.begin() + static_cast<std::ptrdiff_t>(sample_.size() / 2);
    std::nth_element(sample_.begin(), middle, sample_.end());
    double wanted = *middle * cellFactor;
    if (!(wanted > 0.0) || !std::isfinite(wanted)) wanted = cell_ > 0.0 ? cell_ : 1.0;
    if (!(cell_ > 0.0) || wanted > 1.5 * cell_ || wanted < cell_ / 1.5) cell_ = wanted;
    for (int T = 0; T < kMaxTiers; ++T) {
        tiers_[T].side = std::ldexp(cell_, T);
        tiers_[T].inverse = 1.0 / tiers_[T].side;
    }

    // The extent, and each slot's tier: tier T = the smallest with side ≤ c·2^T. Every slot's own
    // outputs, and per-worker extents, tier masks and counts, which combine exactly in any order
    // (min, max, or, +), so the ranges may run on the workers.
    for (Partial& p : partials_) p = Partial{};
    auto extentAndTiers = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t worker) {
        Partial p = partials_[worker];  // a copy: workers' partials share cache lines
        for (std::uint32_t k = begin; k < end; ++k) {
            std::uint32_t s = slots[k];
            Box b = data.box(s);
            p.minX = std::min(p.minX, b.minX), p.minY = std::min(p.minY, b.minY);
            p.maxX = std::max(p.maxX, b.maxX), p.maxY = std::max(p.maxY, b.maxY);
            double side = std::max(b.maxX - b.minX, b.maxY - b.minY);
            int tier = 0;
            if (side > cell_) tier = std::min(kMaxTiers - 1, std::max(0, std::ilogb(side / cell_)));
            while (tier > 0 && side <= tiers_[tier - 1].side) --tier;
            while (tier < kMaxTiers - 1 && side > tiers_[tier].side) ++tier;
            if (side > tiers_[tier].side) {
                homes_[s] = Home::of(kMaxTiers, 0, 0);  // too large for any tier: not entered
                ++p.huge;
                continue;
            }
            homes_[s] = Home::of(static_cast<std::uint32_t>(tier), 0, 0);
            p.tierMask |= std::uint64_t(1) << tier;
        }
        partials_[worker] = p;
    };
    parallelForIfWorth(tasks_, slots.size(), parallelMin_, kMinRange, extentAndTiers);
    Partial all;
    for (const Partial& p : partials_) {
        all.minX = std::min(all.minX, p.minX), all.minY = std::min(all.minY, p.minY);
        all.maxX = std::max(all.maxX, p.maxX), all.maxY = std::max(all.maxY, p.maxY);
        all.tierMask |= p.tierMask;
        all.huge += p.huge;
    }
    if (all.huge > 0)
        for (std::uint32_t s : slots)
            if (homes_[s].tier() == kMaxTiers) huge_.push_back(s);
    std::size_t entered = slots.size() - all.huge;

    // The origin snaps to whole cells so that homes do not shift with the scene's edge.
    originX_ = std::floor(all.minX / cell_) * cell_;
    originY_ = std::floor(all.minY / cell_) * cell_;
    if (!std::isfinite(originX_) || !std::isfinite(originY_)) originX_ = all.minX, originY_ = all.minY;
    std::uint64_t cells = 0;
    for (int T = 0; T < kMaxTiers; ++T) {
        if (!(all.tierMask >> T & 1)) continue;
        usedTiers_.push_back(static_cast<std::uint32_t>(T));
        Tier& t = tiers_[T];
        t.width = std::int64_t(cellOf(all.maxX, originX_, t)) + 1;
        t.height = std::int64_t(cellOf(all.maxY, originY_, t)) + 1;
        t.base = cells;
        cells += std::uint64_t(t.width) * std::uint64_t(t.height);
    }
    dense_ = cells <= kDenseCellsPerObject * entered + 4096;
    std::uint64_t keyCount = cells;  // < 2³²: dense cells are at most 8 per slot plus 4096
    if (!dense_) {
        int bits = std::max(4, static_cast<int>(std::bit_width(2 * entered)));
        hashShift_ = 64 - bits;
        keyCount = std::uint64_t(1) << bits;
    }

    // Homes (the cell holding the box's lower-left corner) and their keys, each slot's own.
    keys_.resize(data.size());
    auto homeAndKey = [&](std::uint32_t s) {
        std::uint32_t tier = homes_[s].tier();
        if (tier == kMaxTiers) return;
        Box b = data.box(s);
        const Tier& t = tiers_[tier];
        std::int32_t x = cellOf(b.minX, originX_, t), y = cellOf(b.minY, originY_, t);
        homes_[s] = Home::of(tier, x, y);
        keys_[s] = static_cast<std::uint32_t>(keyOf(tier, x, y));
    };
    sorted_.resize(entered);
    if (worthSharing(tasks_, slots.size(), parallelMin_)) {
        sortShared(slots, homeAndKey, keyCount);
    } else {
        for (std::uint32_t s : slots) homeAndKey(s);
        // Counting sort by key. The slots arrive nearly in key order (this step's data was laid out
        // in the last step's order), so the scatter below runs almost in sequence.
        CountingSort byKey(starts_, static_cast<std::size_t>(keyCount));
        for (std::uint32_t s : slots)
            if (homes_[s].tier() != kMaxTiers) byKey.count(keys_[s]);
        byKey.startRuns();
        for (std::uint32_t s : slots)
            if (homes_[s].tier() != kMaxTiers) sorted_[byKey.place(keys_[s])] = s;
        byKey.rewindRuns();
    }

    entries_.resize(entered);
    auto copyEntries = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t q = begin; q < end; ++q) {
            std::uint32_t s = sorted_[q];
            const ReachCircle& c = data.reach[s];
            if (c.fast == ReachCircle::kNotFast) {
                entries_[q] = c.disc();
            } else {
                // A fast slot moves along its cast before detection: a circle around the whole box.
                Box b = data.box(s);
                double hx = 0.5 * (b.maxX - b.minX), hy = 0.5 * (b.maxY - b.minY);
                double cx = b.minX + hx, cy = b.minY + hy;
                double r = std::hypot(hx, hy) * (1 + 1e-12) + 4e-14 * (std::fabs(cx) + std::fabs(cy));
                entries_[q] = {cx, cy, r};
            }
        }
    };
    parallelForIfWorth(tasks_, entered, parallelMin_, kMinRange, copyEntries);
}

template <class HomeAndKey>
void UniformGrid::sortShared(std::span<const std::uint32_t> slots, HomeAndKey& homeAndKey,
                             std::uint64_t keyCount) {
    // The counting sort of the one-thread build, in blocks: the keys cut into ranges of 2^shift,
    // each slot dealt to its range in slot order, then each range sorted on its own. Within a range
    // the slots keep their order, so every cell lists them as the one-thread sort does.
    const std::uint32_t blocks = std::min(kMaxSortBlocks, kSortBlocksPerWorker * tasks_->workerCount());
    const BlockSplit split{slots.size(), blocks};
    const int shift = std::bit_width((std::max<std::uint64_t>(keyCount, 1) - 1) / blocks);
    const auto ranges = static_cast<std::uint32_t>(((keyCount - 1) >> shift) + 1);
    starts_.resize(keyCount + 1);
    rangeAt_.resize(std::size_t(ranges) * blocks);
    dealt_.resize(sorted_.size());
    // Each block's homes and keys, and its slots per range.
    forEachBlock(tasks_, blocks, [&](std::uint32_t b) {
        std::array<std::uint32_t, kMaxSortBlocks> count{};
        for (std::size_t k = split.begin(b); k < split.end(b); ++k) {
            const std::uint32_t s = slots[k];
            homeAndKey(s);
            if (homes_[s].tier() != kMaxTiers) ++count[keys_[s] >> shift];
        }
        for (std::uint32_t r = 0; r < ranges; ++r) rangeAt_[std::size_t(r) * blocks + b] = count[r];
    });
    std::uint32_t placed = 0;
    for (std::uint32_t& at : rangeAt_) {
        const std::uint32_t count = at;
        at = placed;
        placed += count;
    }
    // Each slot dealt to its range, blocks in order, slots in order within a block.
    forEachBlock(tasks_, blocks, [&](std::uint32_t b) {
        std::array<std::uint32_t, kMaxSortBlocks> next;
        for (std::uint32_t r = 0; r < ranges; ++r) next[r] = rangeAt_[std::size_t(r) * blocks + b];
        for (std::size_t k = split.begin(b); k < split.end(b); ++k) {
            const std::uint32_t s = slots[k];
            if (homes_[s].tier() != kMaxTiers) dealt_[next[keys_[s] >> shift]++] = s;
        }
    });
    // Each range: its keys' runs, counted and placed (CountingSort over a part of starts_).
    forEachBlock(tasks_, blocks, [&](std::uint32_t r) {
        if (r >= ranges) return;
        const std::uint64_t firstKey = std::uint64_t(r) << shift;
        const std::uint64_t lastKey = std::min(keyCount, std::uint64_t(r + 1) << shift);
        const std::uint32_t from = rangeAt_[std::size_t(r) * blocks];
        const std::uint32_t to = r + 1 < ranges ? rangeAt_[std::size_t(r + 1) * blocks] : placed;
        std::uint32_t* start = starts_.data() + firstKey;
        const std::size_t keys = lastKey - firstKey;
        std::fill(start, start + keys, 0u);
        for (std::uint32_t q = from; q < to; ++q) ++start[keys_[dealt_[q]] - firstKey];
        std::uint32_t run = from;
        for (std::size_t k = 0; k < keys; ++k) {
            const std::uint32_t count = start[k];
            start[k] = run;
            run += count;
        }
        for (std::uint32_t q = from; q < to; ++q) {
            const std::uint32_t s = dealt_[q];
            sorted_[start[keys_[s] - firstKey]++] = s;
        }
        // Placing moved each start to the next run's: back by one run.
        for (std::size_t k = keys - 1; k > 0; --k) start[k] = start[k - 1];
        start[0] = from;
    });
    starts_[keyCount] = placed;
}

std::size_t UniformGrid::bytes() const {
    return usedTiers_.capacity() * sizeof(std::uint32_t) + homes_.capacity() * sizeof(Home) +
           starts_.capacity() * sizeof(std::uint32_t) + sorted_.capacity() * sizeof(std::uint32_t) +
           huge_.capacity() * sizeof(std::uint32_t) + entries_.capacity() * sizeof(Entry) +
           keys_.capacity() * sizeof(std::uint32_t) + sample_.capacity() * sizeof(double) +
           partials_.capacity() * sizeof(Partial) +
           (rangeAt_.capacity() + dealt_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace polar
