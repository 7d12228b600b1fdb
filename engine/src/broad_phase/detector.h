#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "broad_phase/hit_list.h"
#include "broad_phase/hit_order.h"
#include "broad_phase/sort_and_sweep.h"
#include "broad_phase/step_data.h"
#include "broad_phase/uniform_grid.h"
#include "narrow_phase/pair_test.h"
#include "polar/broad_phase.h"
#include "polar/step_stats.h"
#include "polar/tasks.h"

namespace polar {

// One detection pass: per-step data, a broad phase, and the narrow phase on the pairs it yields,
// with the hits written in pair order (A's creation order, then B's).
//
// Why is every method exact? The narrow phase is a pure function of two poses, so any method that
// tests a superset of the pairs that can hit, and puts what it finds in pair order, reports the same
// hits in the same order as the all-pairs loop. The broad phases cull with reach circles that provably
// hold every radius the narrow phase can compute (see StepData), widened for rounding. All-pairs and
// sort-and-sweep work in creation order. The grid works in its cell order, for memory locality, and
// a counting sort by A, then B, restores pair order; container pairs are found by a linear pass.
//
// Why blocks? With a task system of several workers, the container pass and the grid's pair search
// split their items into blocks, 16 per worker, each counted apart; the workers write their hits
// straight into the one hit list at positions they claim (HitList), and findHits sorts the list into
// pair order. Each pair is found once, so that order is a total one: the hits are the same at any
// worker count, and no second list of them is ever held.
class Detector {
  public:
    // The task system for the parallel parts (null: all on the calling thread), and the size below
    // which a part runs on the calling thread anyway. Results do not depend on either.
    void setTasks(TaskSystem* tasks, std::uint32_t parallelMin);

    // Builds the per-step data and the broad phase for `in`'s candidates (ascending). `layout` changes
    // whenever that list may have: the grid then forgets its order.
    void prepare(const DetectionInput& in, BroadPhase method, std::uint64_t layout);

    StepData& data() { return data_; }
    const StepData& data() const { return data_; }
    BroadPhase method() const { return method_; }
    bool containers() const { return containers_; }
    // The narrow phase's level for this pass.
    Accuracy accuracy() const { return accuracy_; }

    // Calls visit(j) for every finite slot j ≠ self that could meet a box: those whose boxes may
    // overlap it, and every container (a container pair can hit from anywhere outside the wall).
    template <class Visit>
    void forEachNear(std::uint32_t self, const Box& box, Visit&& visit) const;

    // The containers effect's pass: tests each container against the objects it may touch. The hits
    // wait for findHits. (All-pairs tests container pairs in its own loop instead.)
    void testContainers(EffectStats& stats);
    // Tests the broad phase's pairs and lists the hits in pair order; with `all` (all-pairs only),
    // every tested pair. `objectCount` bounds the object indices. Container pairs count in
    // `containerStats`.
    void findHits(bool all, std::size_t objectCount, EffectStats& stats, EffectStats& containerStats);
    // The last findHits' list.
    std::span<const PairReport> hits() const { return hits_.items(); }
    // Takes a copied world's list of hits as its own.
    void copyHits(std::span<const PairReport> hits) {
        hits_.clear();
        hits_.append(hits);
    }
    // A restored world's list of hits (world_snapshot.cpp), one at a time after clearHits.
    void clearHits(std::size_t room) {
        hits_.clear();
        hits_.reserve(room);
    }
    void addHit(const PairReport& hit) { hits_.push(hit); }

    // Memory held, and the part only the containers effect uses.
    std::size_t bytes() const;
    std::size_t containerBytes() const;

  private:
    // The pairs waiting for testPairs: the poses, their objects, and the outcomes. One per worker.
    static constexpr std::size_t kQueue = 256;
    struct PairQueue {
        std::array<PosePair, kQueue> pairs;
        std::array<std::uint32_t, 2 * kQueue> objects;
        std::array<PairTest, kQueue> tests;
        std::size_t size = 0;
        HitSink* sink = nullptr;  // where the queued pairs' hits go
    };
    // One block's counts.
    struct Block {
        std::uint64_t objects = 0;
        std::uint64_t pairs = 0;
    };
    // A pass whose hits are not yet known: it runs on the calling thread, with nothing to size the
    // room by.
    static constexpr std::size_t kNoPass = ~std::size_t(0);

    // Queues slots i and j, in pair order (by their objects' creation order), for testPairs; the
    // queue is tested when full and by flushPairs, which every loop that queues calls at its end.
    void testSlots(PairQueue& queue, std::uint32_t i, std::uint32_t j, EffectStats& stats);
    // Tests the queued pairs and puts the hits in the queue's sink.
    void flushPairs(PairQueue& queue);
    // Calls visit(begin, end, queue, stats) on ranges of the items [0, count), each queue's hits
    // going to `out`, the objects and pairs counted in `stats`: one range on the calling thread, or
    // blocks on the workers when the task system is set and count is large. `last` is the number of
    // hits the last such pass found (kNoPass before the first), to size the room by.
    template <class Visit>
    void inBlocks(std::size_t count, HitList& out, std::size_t& last, EffectStats& stats, Visit&& visit);
    void findAllPairs(bool all, EffectStats& stats, EffectStats& containerStats);
    void findGrid(EffectStats& stats);
    void findSweep(EffectStats& stats);
    // Puts the hits in pair order (hit_order.h), on the workers when there are enough.
    void sortHits(std::size_t objectCount);
    std::size_t blockBytes() const;

    PairQueue queue_;                      // the calling thread's, and worker 0's
    std::vector<PairQueue> workerQueues_;  // workers 1, 2, ...
    std::vector<Block> blocks_;
    std::vector<std::vector<PairReport>> spills_;  // per worker: hits claimed past the room
    std::atomic<std::size_t> claimed_{0};          // a shared pass's next unclaimed position
    std::size_t lastGridHits_ = kNoPass;
    std::size_t lastContainerHits_ = kNoPass;
    TaskSystem* tasks_ = nullptr;
    std::uint32_t parallelMin_ = 0;

    StepData data_;
    UniformGrid grid_;
    SortAndSweep sweep_;
    BroadPhase method_ = BroadPhase::Grid;
    Accuracy accuracy_ = Accuracy::Bounds;
    bool containers_ = false;
    std::vector<std::uint32_t> order_;   // the grid's last cell order, as object indices
    SlotPlan plan_;                      // what the last step knew of order_'s candidates
    std::vector<std::uint32_t> others_;  // candidates' objects outside the grid (scratch)
    std::uint64_t layout_ = ~std::uint64_t(0);
    HitList hits_;
    HitList extraHits_;  // hits of containers and huge objects
    HitOrder hitOrder_;
    std::vector<std::uint32_t> partners_;  // sort-and-sweep: one row's partners
    std::vector<std::uint32_t> rowStart_;  // sort-and-sweep: its pairs bucketed by first slot
    std::vector<std::uint32_t> rowPairs_;
    std::vector<std::uint64_t> sweepPairs_;  // sort-and-sweep: the pairs that may hit
};

template <class Visit>
void Detector::forEachNear(std::uint32_t self, const Box& box, Visit&& visit) const {
    if (method_ == BroadPhase::Grid) {
        grid_.forEachOverlapping(box, [&](std::uint32_t j) {
            if (j != self && box.overlaps(data_.box(j))) visit(j);
        });
        for (std::uint32_t j : grid_.huge())
            if (j != self && box.overlaps(data_.box(j))) visit(j);
    } else {
        for (std::uint32_t j : data_.regularSlots)
            if (j != self && box.overlaps(data_.box(j))) visit(j);
    }
    for (std::uint32_t j : data_.containerSlots)
        if (j != self) visit(j);
}

}  // namespace polar
