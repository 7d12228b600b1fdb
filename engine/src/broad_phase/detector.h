#pragma once
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "broad_phase/sort_and_sweep.h"
#include "broad_phase/step_data.h"
#include "broad_phase/uniform_grid.h"
#include "narrow_phase/pair_test.h"
#include "polar/broad_phase.h"
#include "polar/step_stats.h"
#include "polar/world.h"

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
class Detector {
  public:
    // Builds the per-step data and the broad phase for the candidates among `objects` at `indices`
    // (ascending). `layout` changes whenever that list may have: the grid then forgets its order.
    void prepare(const std::vector<GameObject>& objects, std::span<const std::uint32_t> indices,
                 bool containers, BroadPhase method, Accuracy accuracy, std::span<const FastStart> fastStarts,
                 std::uint64_t layout);

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
    // Tests the broad phase's pairs and writes the hits in pair order; with `all` (all-pairs only),
    // every tested pair. `objectCount` bounds the object indices. Container pairs count in
    // `containerStats`.
    void findHits(std::vector<PairReport>& out, bool all, std::size_t objectCount, EffectStats& stats,
                  EffectStats& containerStats);

    // Memory held, and the part only the containers effect uses.
    std::size_t bytes() const;
    std::size_t containerBytes() const;

  private:
    // Queues slots i and j, in pair order (by their objects' creation order), for testPairs; the
    // queue is tested when full and by flushPairs, which every loop that queues calls at its end.
    void testSlots(std::uint32_t i, std::uint32_t j, std::vector<PairReport>& out, EffectStats& stats);
    // Tests the queued pairs and appends the hits to `out`, in queue order.
    void flushPairs(std::vector<PairReport>& out);
    void findAllPairs(std::vector<PairReport>& out, bool all, EffectStats& stats,
                      EffectStats& containerStats);
    void findGrid(std::vector<PairReport>& out, EffectStats& stats);
    void findSweep(std::vector<PairReport>& out, EffectStats& stats);
    // Puts hits in pair order: a counting sort by A applied in place, then B within each A.
    void sortHits(std::vector<PairReport>& hits, std::size_t objectCount);

    // The queue of pairs for testPairs: the poses, their objects, and the outcomes.
    static constexpr std::size_t kQueue = 256;
    std::array<PosePair, kQueue> queued_;
    std::array<std::uint32_t, 2 * kQueue> queuedObjects_;
    std::array<PairTest, kQueue> queuedTests_;
    std::size_t queueSize_ = 0;
    const std::vector<PairReport>* queueOut_ = nullptr;  // where the queued pairs' hits go

    StepData data_;
    UniformGrid grid_;
    SortAndSweep sweep_;
    BroadPhase method_ = BroadPhase::Grid;
    Accuracy accuracy_ = Accuracy::Bounds;
    bool containers_ = false;
    std::vector<std::uint32_t> order_;   // the grid's last cell order, as object indices
    std::vector<std::uint32_t> others_;  // candidates' objects outside the grid (scratch)
    std::uint64_t layout_ = ~std::uint64_t(0);
    std::vector<PairReport> extraHits_;    // hits of containers and huge objects
    std::vector<std::uint32_t> counts_;    // counting sort by A
    std::vector<std::uint32_t> rank_;      // where each hit goes
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
