#include "broad_phase/detector.h"

#include <algorithm>
#include <cassert>

#include "broad_phase/counting_sort.h"
#include "narrow_phase/pair_test.h"
#include "tasks/parallel_for.h"

namespace polar {
namespace {

// The grid's base cell side as a multiple of the median box side (see README, "Broad phase").
constexpr double kGridCellFactor = 1.5;
// Blocks per worker: a few, so that a worker slowed by a dense block is balanced by the others.
constexpr std::size_t kBlocksPerWorker = 4;

}  // namespace

void Detector::setTasks(TaskSystem* tasks, std::uint32_t parallelMin) {
    tasks_ = tasks;
    parallelMin_ = parallelMin;
    std::uint32_t workers = tasks ? tasks->workerCount() : 1;
    workerQueues_.resize(workers - 1);
    blocks_.resize(tasks && workers > 1 ? workers * kBlocksPerWorker : 0);
}

template <class Visit>
void Detector::inBlocks(std::size_t count, std::vector<PairReport>& out, EffectStats& stats, Visit&& visit) {
    if (!worthSharing(tasks_, count, parallelMin_)) {
        visit(std::size_t(0), count, queue_, out, stats);
        flushPairs(queue_, out);
        return;
    }
    auto blocks = static_cast<std::uint32_t>(std::min(blocks_.size(), count));
    auto body = [&](std::uint32_t first, std::uint32_t last, std::uint32_t worker) {
        PairQueue& queue = worker == 0 ? queue_ : workerQueues_[worker - 1];
        for (std::uint32_t b = first; b < last; ++b) {
            Block& block = blocks_[b];
            block.hits.clear();
            EffectStats counted;
            visit(count * b / blocks, count * (b + 1) / blocks, queue, block.hits, counted);
            flushPairs(queue, block.hits);
            block.objects = counted.objects;
            block.pairs = counted.pairs;
        }
    };
    parallelFor(*tasks_, blocks, 1, body);
    std::size_t most = 0;
    for (std::uint32_t b = 0; b < blocks; ++b) {
        out.insert(out.end(), blocks_[b].hits.begin(), blocks_[b].hits.end());
        stats.objects += blocks_[b].objects;
        stats.pairs += blocks_[b].pairs;
        most = std::max(most, blocks_[b].hits.size());
    }
    // A block's share of the hits changes a little from step to step (where the grid's order puts
    // its ends), so one that merely kept its own largest size would still grow now and then. Every
    // block keeps room for twice the largest share instead, renewed only when a share nears it: a
    // steady step allocates nothing.
    for (Block& block : blocks_)
        if (block.hits.capacity() < most + most / 4 + 8) block.hits.reserve(2 * most + 16);
}

void Detector::prepare(const std::vector<GameObject>& objects, std::span<const std::uint32_t> indices,
                       bool containers, BroadPhase method, Accuracy accuracy,
                       std::span<const FastStart> fastStarts, std::uint64_t layout) {
    containers_ = containers;
    accuracy_ = accuracy;
    extraHits_.clear();
    bool keepOrder = method == BroadPhase::Grid && method_ == BroadPhase::Grid && layout == layout_ &&
                     order_.size() == indices.size();
    method_ = method;
    layout_ = layout;
    if (!keepOrder) order_.assign(indices.begin(), indices.end());
    data_.build(objects, method == BroadPhase::Grid ? std::span<const std::uint32_t>(order_) : indices,
                containers, accuracy, fastStarts, others_, tasks_, parallelMin_);
    if (method == BroadPhase::Grid) {
        grid_.build(data_, data_.regularSlots, kGridCellFactor);
        // The next step lays its data out in this step's cell order.
        order_.clear();
        for (std::uint32_t slot : grid_.sorted()) order_.push_back(data_.objectIndex[slot]);
        for (std::uint32_t slot : grid_.huge()) order_.push_back(data_.objectIndex[slot]);
        order_.insert(order_.end(), others_.begin(), others_.end());
    }
    if (method == BroadPhase::SortAndSweep) sweep_.build(data_, data_.regularSlots);
}

void Detector::testSlots(PairQueue& queue, std::uint32_t i, std::uint32_t j, std::vector<PairReport>& out,
                         EffectStats& stats) {
    if (data_.objectIndex[i] > data_.objectIndex[j]) std::swap(i, j);
    const ObjectPose& a = data_.poses[i];
    const ObjectPose& b = data_.poses[j];
    // Slots hold only objects the rules test (collisions, radii), a container only when containers
    // run, and a broad phase pairs a container only with what it may hold: no rule to check here.
    assert(pairIsTested(a, b, containers_));
    ++stats.pairs;
    assert(queue.size == 0 || queue.out == &out);  // a loop that queues flushes before the next one
    queue.out = &out;
    // testPairs reads both poses some pairs later: fetch their lines now, so that the misses of
    // the queued pairs overlap instead of stalling the pair tests one after another.
    for (const ObjectPose* pose : {&a, &b}) {
        const char* bytes = reinterpret_cast<const char*>(pose);
        // Probes under a line apart reach every line the pose spans (its last byte, 16-byte aligned,
        // never starts a line of its own).
        for (std::size_t at = 0; at < sizeof(ObjectPose); at += 55) __builtin_prefetch(bytes + at);
    }
    queue.pairs[queue.size] = {&a, &b};
    queue.objects[2 * queue.size] = data_.objectIndex[i];
    queue.objects[2 * queue.size + 1] = data_.objectIndex[j];
    if (++queue.size == kQueue) flushPairs(queue, out);
}

void Detector::flushPairs(PairQueue& queue, std::vector<PairReport>& out) {
    testPairs(std::span(queue.pairs.data(), queue.size), accuracy_, queue.tests.data());
    for (std::size_t k = 0; k < queue.size; ++k)
        if (queue.tests[k].hit)
            out.push_back({queue.objects[2 * k], queue.objects[2 * k + 1], queue.tests[k]});
    queue.size = 0;
}

void Detector::testContainers(EffectStats& stats) {
    if (method_ == BroadPhase::AllPairs || data_.containerSlots.empty()) return;
    ++stats.calls;
    const std::vector<std::uint32_t>& regular = data_.regularSlots;
    for (std::size_t c = 0; c < data_.containerSlots.size(); ++c) {
        std::uint32_t container = data_.containerSlots[c];
        ++stats.objects;
        inBlocks(regular.size(), extraHits_, stats,
                 [&](std::size_t begin, std::size_t end, PairQueue& queue, std::vector<PairReport>& hits,
                     EffectStats& counted) {
                     for (std::size_t k = begin; k < end; ++k) {
                         std::uint32_t held = regular[k];
                         if (data_.poses[held].flags & kIgnoreContainers) continue;
                         ++counted.objects;
                         if (data_.containerGap(c, held) > 0.0) continue;
                         testSlots(queue, container, held, hits, counted);
                     }
                 });
    }
}

void Detector::findHits(std::vector<PairReport>& out, bool all, std::size_t objectCount, EffectStats& stats,
                        EffectStats& containerStats) {
    out.clear();
    assert(!all || method_ == BroadPhase::AllPairs);
    switch (method_) {
        case BroadPhase::AllPairs:
            findAllPairs(out, all, stats, containerStats);
            return;
        case BroadPhase::SortAndSweep:
            findSweep(out, stats);
            if (!extraHits_.empty()) {
                out.insert(out.end(), extraHits_.begin(), extraHits_.end());
                sortHits(out, objectCount);
            }
            return;
        case BroadPhase::Grid:
            findGrid(out, stats);
            out.insert(out.end(), extraHits_.begin(), extraHits_.end());
            sortHits(out, objectCount);
            return;
    }
}

void Detector::findAllPairs(std::vector<PairReport>& out, bool all, EffectStats& stats,
                            EffectStats& containerStats) {
    // The reference: every pair A < B the rules test, in pair order (slots are in creation order).
    ++stats.calls;
    if (!data_.containerSlots.empty()) ++containerStats.calls;
    auto n = static_cast<std::uint32_t>(data_.size());
    for (std::uint32_t i = 0; i < n; ++i) {
        ++stats.objects;
        for (std::uint32_t j = i + 1; j < n; ++j) {
            const ObjectPose& a = data_.poses[i];
            const ObjectPose& b = data_.poses[j];
            if (!pairIsTested(a, b, containers_)) continue;
            bool container = ((a.flags | b.flags) & kContainer) != 0;
            ++(container ? containerStats : stats).pairs;
            PairTest test = testPair(a, b, accuracy_);
            if (all || test.hit) out.push_back({data_.objectIndex[i], data_.objectIndex[j], test});
        }
    }
}

void Detector::findGrid(std::vector<PairReport>& out, EffectStats& stats) {
    ++stats.calls;
    std::span<const std::uint32_t> sorted = grid_.sorted();
    stats.objects += sorted.size();
    inBlocks(sorted.size(), out, stats,
             [&](std::size_t begin, std::size_t end, PairQueue& queue, std::vector<PairReport>& hits,
                 EffectStats& counted) {
                 for (std::size_t p = begin; p < end; ++p) {
                     std::uint32_t i = sorted[p];
                     // The grid has tested the two reach circles (a fast slot's holds its cast, a looser
                     // test that only adds pairs the narrow phase rejects): what is left is the compound
                     // radii's circles.
                     grid_.forEachPartner(p, [&](std::uint32_t j) {
                         if (data_.radiiMayTouch(i, j)) testSlots(queue, i, j, hits, counted);
                     });
                 }
             });
    // Objects too large for any level pair with everything, linearly.
    for (std::uint32_t big : grid_.huge()) {
        for (std::uint32_t j : data_.regularSlots) {
            ++stats.objects;
            if (j == big) continue;
            bool otherHuge = std::find(grid_.huge().begin(), grid_.huge().end(), j) != grid_.huge().end();
            if (otherHuge && j < big) continue;  // a pair of two huge ones once
            if (data_.mayHit(big, j)) testSlots(queue_, big, j, extraHits_, stats);
        }
    }
    flushPairs(queue_, extraHits_);
}

void Detector::sortHits(std::vector<PairReport>& hits, std::size_t objectCount) {
    // Counting sort by A: where each hit goes, then that permutation applied in place.
    CountingSort byA(counts_, objectCount);
    for (const PairReport& h : hits) byA.count(h.a);
    byA.startRuns();
    rank_.resize(hits.size());
    for (std::size_t k = 0; k < hits.size(); ++k) rank_[k] = byA.place(hits[k].a);
    permuteInPlace(std::span<PairReport>(hits), std::span<std::uint32_t>(rank_));
    // Within one A, order by B: runs are short, so insertion sort.
    for (std::size_t begin = 0; begin < hits.size();) {
        std::size_t end = begin + 1;
        while (end < hits.size() && hits[end].a == hits[begin].a) ++end;
        for (std::size_t i = begin + 1; i < end; ++i)
            for (std::size_t j = i; j > begin && hits[j].b < hits[j - 1].b; --j)
                std::swap(hits[j], hits[j - 1]);
        begin = end;
    }
}

void Detector::findSweep(std::vector<PairReport>& out, EffectStats& stats) {
    ++stats.calls;
    // Collect the overlapping pairs, bucket them by first slot (a counting sort), then test by row.
    sweepPairs_.clear();
    sweep_.forEachPair([&](std::uint32_t i, std::uint32_t j) {
        if (data_.mayHit(i, j)) sweepPairs_.push_back((std::uint64_t(i) << 32) | j);
    });
    CountingSort byFirst(rowStart_, data_.size());
    for (std::uint64_t p : sweepPairs_) byFirst.count(p >> 32);
    byFirst.startRuns();
    rowPairs_.resize(sweepPairs_.size());
    for (std::uint64_t p : sweepPairs_) rowPairs_[byFirst.place(p >> 32)] = std::uint32_t(p);
    byFirst.rewindRuns();
    // Row i, the partners of slot i, is rowPairs_[rowStart_[i], rowStart_[i + 1]). Slots are in
    // creation order.
    for (std::uint32_t i : data_.regularSlots) {
        ++stats.objects;
        partners_.assign(rowPairs_.begin() + rowStart_[i], rowPairs_.begin() + rowStart_[i + 1]);
        std::sort(partners_.begin(), partners_.end());
        for (std::uint32_t j : partners_) testSlots(queue_, i, j, out, stats);
    }
    flushPairs(queue_, out);
}

std::size_t Detector::bytes() const {
    return data_.bytes() + grid_.bytes() + sweep_.bytes() +
           (order_.capacity() + others_.capacity() + counts_.capacity() + rank_.capacity()) *
               sizeof(std::uint32_t) +
           extraHits_.capacity() * sizeof(PairReport) +
           (partners_.capacity() + rowStart_.capacity() + rowPairs_.capacity()) * sizeof(std::uint32_t) +
           sweepPairs_.capacity() * sizeof(std::uint64_t) + blockBytes();
}

std::size_t Detector::blockBytes() const {
    std::size_t bytes = workerQueues_.capacity() * sizeof(PairQueue) + blocks_.capacity() * sizeof(Block);
    for (const Block& block : blocks_) bytes += block.hits.capacity() * sizeof(PairReport);
    return bytes;
}

std::size_t Detector::containerBytes() const {
    return data_.containerBytes();
}

}  // namespace polar
