#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "polar/collision.h"
#include "polar/tasks.h"

namespace polar {

// Puts a pass's hits in pair order (A's creation order, then B's), in place.
//
// Why in parts? The hits arrive in the order the workers claimed their positions, and the sort is
// the one part of detection left on one thread. With more than one worker the hits are first
// split by ranges of A (each split in place around a sampled median), then every part is sorted on
// its own: a counting sort by A applied in place, then B within each A by insertion (runs are
// short). Each pair is found once, so pair order is total: neither the claims' race nor the splits
// can show in the result.
class HitOrder {
  public:
    // Sorts `hits`, whose A and B are below `objectCount`, in as many parts as `tasks` has workers
    // and at most `maxParts` (tasks null: one part, on the calling thread).
    void sort(std::span<PairReport> hits, std::size_t objectCount, TaskSystem* tasks, std::uint32_t maxParts);
    std::size_t bytes() const;

  private:
    // Hits [begin, end) of the pass, each with lo ≤ A < hi.
    struct Part {
        std::size_t begin = 0;
        std::size_t end = 0;
        std::uint32_t lo = 0;
        std::uint32_t hi = 0;
    };
    // Splits each part of parts_ in two by its hits' median A, into next_.
    void split(std::span<PairReport> hits, TaskSystem* tasks);
    // Sorts one part; its run starts occupy counts_ from `countsAt` (hi − lo + 1 of them).
    void sortPart(std::span<PairReport> hits, const Part& part, std::size_t countsAt);

    std::vector<Part> parts_;
    std::vector<Part> next_;
    std::vector<std::uint32_t> counts_;  // counting sort by A, every part's run starts
    std::vector<std::uint32_t> rank_;    // where each hit goes, within its part
};

}  // namespace polar
