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
// Blocks per worker: enough that the last block to finish is short (a worker slowed by a dense
// block, or woken late, is balanced by the others); at 100k objects and 2 workers, 16 gave a step
// about 6 % faster than 4 (median of 10 alternating pairs, with the pool's 16 ranges per worker).
constexpr std::size_t kBlocksPerWorker = 16;
// Parts the hit sort splits into, at most: each split is a pass over the hits.
constexpr std::uint32_t kMaxSortParts = 8;

}  // namespace

void Detector::setTasks(TaskSystem* tasks, std::uint32_t parallelMin) {
    tasks_ = tasks;
    parallelMin_ = parallelMin;
    std::uint32_t workers = tasks ? tasks->workerCount() : 1;
    workerQueues_.resize(workers - 1);
    spills_.resize(workers);
    grid_.setTasks(tasks, parallelMin);
    blocks_.resize(tasks && workers > 1 ? workers * kBlocksPerWorker : 0);
}

template <class Visit>
void Detector::inBlocks(std::size_t count, HitList& out, std::size_t& last, EffectStats& stats,
                        Visit&& visit) {
    std::size_t before = out.size();
    if (last == kNoPass || !worthSharing(tasks_, count, parallelMin_)) {
        HitSink sink(out);
        queue_.sink = &sink;
        visit(std::size_t(0), count, queue_, stats);
        flushPairs(queue_);
        queue_.sink = nullptr;
        last = out.size() - before;
        return;
    }
    // Room for the last pass's hits and a quarter more, within what the list already holds: growing
    // it here would hold the old array beside the new one, at the step with the most hits so far,
    // the peak of the process's memory. A pass that finds more spills the rest, and the list grows.
    std::size_t wanted = before + last + last / 4 + 256;
    out.reserve(std::max(std::min(wanted, out.capacity()), before + last));
    claimed_.store(before, std::memory_order_relaxed);
    auto blocks = static_cast<std::uint32_t>(std::min(blocks_.size(), count));
    auto body = [&](std::uint32_t first, std::uint32_t end, std::uint32_t worker) {
        PairQueue& queue = worker == 0 ? queue_ : workerQueues_[worker - 1];
        HitSink sink(out, claimed_, spills_[worker]);
        queue.sink = &sink;
        for (std::uint32_t b = first; b < end; ++b) {
            EffectStats counted;
            visit(count * b / blocks, count * (b + 1) / blocks, queue, counted);
            blocks_[b].objects = counted.objects;
            blocks_[b].pairs = counted.pairs;
        }
        flushPairs(queue);
        queue.sink = nullptr;
    };
    parallelFor(*tasks_, blocks, 1, body);
    HitSink::finishClaims(out, claimed_.load(std::memory_order_relaxed), spills_);
    for (std::uint32_t b = 0; b < blocks; ++b) {
        stats.objects += blocks_[b].objects;
        stats.pairs += blocks_[b].pairs;
    }
    last = out.size() - before;
}

void Detector::prepare(const DetectionInput& in, BroadPhase method, std::uint64_t layout) {
    std::span<const std::uint32_t> indices = in.candidates;
    containers_ = in.containers;
    accuracy_ = in.accuracy;
    extraHits_.clear();
    bool keepOrder = method == BroadPhase::Grid && method_ == BroadPhase::Grid && layout == layout_ &&
                     order_.size() == indices.size();
    method_ = method;
    layout_ = layout;
    if (!keepOrder) order_.assign(indices.begin(), indices.end());
    DetectionInput slots = in;
    if (method == BroadPhase::Grid) slots.candidates = order_;  // the last step's cell order
    data_.build(slots, others_, tasks_, parallelMin_, keepOrder ? &plan_ : nullptr);
    if (method == BroadPhase::Grid) {
        grid_.build(data_, data_.regularSlots, kGridCellFactor);
        // The next step lays its data out in this step's cell order (the grid's sorted slots, then
        // the huge ones), and is told where each block of those slots' radii circles begins: blocks
        // of SlotPlan::kBlock, each laid and summed on its own, then the sums run on.
        std::span<const std::uint32_t> sorted = grid_.sorted();
        const std::vector<std::uint32_t>& huge = grid_.huge();
        const auto laid = static_cast<std::uint32_t>(sorted.size() + huge.size());
        constexpr std::uint32_t kBlock = SlotPlan::kBlock;
        const std::uint32_t blocks = (laid + kBlock - 1) / kBlock;
        order_.resize(laid);
        plan_.compoundBefore.resize(blocks + 1);
        auto lay = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
            for (std::uint32_t b = begin; b < end; ++b) {
                std::uint32_t compound = 0;
                for (std::uint32_t k = b * kBlock, last = std::min(laid, (b + 1) * kBlock); k < last; ++k) {
                    const std::uint32_t slot = k < sorted.size() ? sorted[k] : huge[k - sorted.size()];
                    order_[k] = data_.objectIndex[slot];
                    compound += data_.radiiBegin[slot + 1] - data_.radiiBegin[slot];
                }
                plan_.compoundBefore[b + 1] = compound;
            }
        };
        if (worthSharing(tasks_, laid, parallelMin_))
            parallelFor(*tasks_, blocks, 1, lay);
        else
            lay(0, blocks, 0);
        plan_.compoundBefore[0] = 0;
        for (std::uint32_t b = 0; b < blocks; ++b) plan_.compoundBefore[b + 1] += plan_.compoundBefore[b];
        plan_.slots = laid;
        order_.insert(order_.end(), others_.begin(), others_.end());
    }
    if (method == BroadPhase::SortAndSweep) sweep_.build(data_, data_.regularSlots);
}

void Detector::testSlots(PairQueue& queue, std::uint32_t i, std::uint32_t j, EffectStats& stats) {
    if (data_.objectIndex[i] > data_.objectIndex[j]) std::swap(i, j);
    const ObjectPose& a = data_.poses[i];
    const ObjectPose& b = data_.poses[j];
    // Slots hold only objects the rules test (collisions, radii), a container only when containers
    // run, and a broad phase pairs a container only with what it may hold: no rule to check here.
    assert(pairIsTested(a, b, containers_));
    ++stats.pairs;
    assert(queue.sink);  // set by the loop that queues, which flushes at its end
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
    if (++queue.size == kQueue) flushPairs(queue);
}

void Detector::flushPairs(PairQueue& queue) {
    testPairs(std::span(queue.pairs.data(), queue.size), accuracy_, queue.tests.data());
    std::size_t found = 0;
    for (std::size_t k = 0; k < queue.size; ++k) found += queue.tests[k].hit ? 1 : 0;
    std::size_t at = found ? queue.sink->claim(found) : 0;
    for (std::size_t k = 0; k < queue.size; ++k)
        if (queue.tests[k].hit)
            queue.sink->put(at++, {queue.objects[2 * k], queue.objects[2 * k + 1], queue.tests[k]});
    queue.size = 0;
}

void Detector::testContainers(EffectStats& stats) {
    if (method_ == BroadPhase::AllPairs || data_.containerSlots.empty()) return;
    ++stats.calls;
    const std::vector<std::uint32_t>& regular = data_.regularSlots;
    for (std::size_t c = 0; c < data_.containerSlots.size(); ++c) {
        std::uint32_t container = data_.containerSlots[c];
        ++stats.objects;
        inBlocks(regular.size(), extraHits_, lastContainerHits_, stats,
                 [&](std::size_t begin, std::size_t end, PairQueue& queue, EffectStats& counted) {
                     for (std::size_t k = begin; k < end; ++k) {
                         std::uint32_t held = regular[k];
                         if (data_.poses[held].flags & kIgnoreContainers) continue;
                         ++counted.objects;
                         if (data_.containerGap(c, held) > 0.0) continue;
                         testSlots(queue, container, held, counted);
                     }
                 });
    }
}

void Detector::findHits(bool all, std::size_t objectCount, EffectStats& stats, EffectStats& containerStats) {
    hits_.clear();
    assert(!all || method_ == BroadPhase::AllPairs);
    switch (method_) {
        case BroadPhase::AllPairs:
            findAllPairs(all, stats, containerStats);
            return;
        case BroadPhase::SortAndSweep:
            findSweep(stats);
            if (!extraHits_.empty()) {
                hits_.append(extraHits_.items());
                sortHits(objectCount);
            }
            return;
        case BroadPhase::Grid:
            findGrid(stats);
            hits_.append(extraHits_.items());
            sortHits(objectCount);
            return;
    }
}

void Detector::findAllPairs(bool all, EffectStats& stats, EffectStats& containerStats) {
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
            if (all || test.hit) hits_.push({data_.objectIndex[i], data_.objectIndex[j], test});
        }
    }
}

void Detector::findGrid(EffectStats& stats) {
    ++stats.calls;
    std::span<const std::uint32_t> sorted = grid_.sorted();
    stats.objects += sorted.size();
    inBlocks(sorted.size(), hits_, lastGridHits_, stats,
             [&](std::size_t begin, std::size_t end, PairQueue& queue, EffectStats& counted) {
                 for (std::size_t p = begin; p < end; ++p) {
                     std::uint32_t i = sorted[p];
                     // The grid has tested the two reach circles (a fast slot's holds its cast, a looser
                     // test that only adds pairs the narrow phase rejects): what is left is the compound
                     // radii's circles.
                     grid_.forEachPartner(p, [&](std::uint32_t j) {
                         if (data_.radiiMayTouch(i, j)) testSlots(queue, i, j, counted);
                     });
                 }
             });
    // Objects too large for any level pair with everything, linearly.
    HitSink extra(extraHits_);
    queue_.sink = &extra;
    for (std::uint32_t big : grid_.huge()) {
        for (std::uint32_t j : data_.regularSlots) {
            ++stats.objects;
            if (j == big) continue;
            bool otherHuge = std::find(grid_.huge().begin(), grid_.huge().end(), j) != grid_.huge().end();
            if (otherHuge && j < big) continue;  // a pair of two huge ones once
            if (data_.mayHit(big, j)) testSlots(queue_, big, j, stats);
        }
    }
    flushPairs(queue_);
    queue_.sink = nullptr;
}

void Detector::sortHits(std::size_t objectCount) {
    bool shared = worthSharing(tasks_, hits_.size(), parallelMin_);
    hitOrder_.sort(hits_.items(), objectCount, shared ? tasks_ : nullptr, kMaxSortParts);
}

void Detector::findSweep(EffectStats& stats) {
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
    HitSink sink(hits_);
    queue_.sink = &sink;
    for (std::uint32_t i : data_.regularSlots) {
        ++stats.objects;
        partners_.assign(rowPairs_.begin() + rowStart_[i], rowPairs_.begin() + rowStart_[i + 1]);
        std::sort(partners_.begin(), partners_.end());
        for (std::uint32_t j : partners_) testSlots(queue_, i, j, stats);
    }
    flushPairs(queue_);
    queue_.sink = nullptr;
}

std::size_t Detector::bytes() const {
    return data_.bytes() + grid_.bytes() + sweep_.bytes() +
           (order_.capacity() + plan_.compoundBefore.capacity() + others_.capacity()) *
               sizeof(std::uint32_t) +
           hits_.bytes() + extraHits_.bytes() + hitOrder_.bytes() +
           (partners_.capacity() + rowStart_.capacity() + rowPairs_.capacity()) * sizeof(std::uint32_t) +
           sweepPairs_.capacity() * sizeof(std::uint64_t) + blockBytes();
}

std::size_t Detector::blockBytes() const {
    std::size_t bytes = workerQueues_.capacity() * sizeof(PairQueue) + blocks_.capacity() * sizeof(Block);
    for (const std::vector<PairReport>& spill : spills_) bytes += spill.capacity() * sizeof(PairReport);
    return bytes;
}

std::size_t Detector::containerBytes() const {
    return data_.containerBytes();
}

}  // namespace polar
