#include "broad_phase/hit_order.h"

#include <algorithm>
#include <array>

#include "broad_phase/counting_sort.h"
#include "tasks/parallel_for.h"

namespace polar {
namespace {

// Hits sampled to choose where a part splits: enough that the halves come out near even.
constexpr std::size_t kSample = 63;

}  // namespace

void HitOrder::sort(std::span<PairReport> hits, std::size_t objectCount, TaskSystem* tasks,
                    std::uint32_t maxParts) {
    parts_.assign(1, Part{0, hits.size(), 0, static_cast<std::uint32_t>(objectCount)});
    std::uint32_t parts = tasks ? std::min(tasks->workerCount(), maxParts) : 1;
    while (parts_.size() * 2 <= parts) split(hits, tasks);
    // Each part's run starts, side by side: hi − lo + 1 for each, objectCount + parts in all.
    counts_.resize(objectCount + parts_.size());
    rank_.resize(hits.size());
    auto sortParts = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t p = begin; p < end; ++p) sortPart(hits, parts_[p], parts_[p].lo + p);
    };
    if (parts_.size() > 1)
        parallelFor(*tasks, static_cast<std::uint32_t>(parts_.size()), 1, sortParts);
    else
        sortParts(0, 1, 0);
}

void HitOrder::split(std::span<PairReport> hits, TaskSystem* tasks) {
    next_.resize(2 * parts_.size());
    auto splitParts = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t p = begin; p < end; ++p) {
            const Part& part = parts_[p];
            std::span<PairReport> mine = hits.subspan(part.begin, part.end - part.begin);
            // The median A of hits at an even stride, or the middle of the range for a part too
            // small to sample. Any key in [lo, hi] splits correctly; the median keeps halves even.
            std::uint32_t middle = part.lo + (part.hi - part.lo) / 2;
            if (mine.size() >= kSample) {
                std::array<std::uint32_t, kSample> sample;
                for (std::size_t k = 0; k < kSample; ++k) sample[k] = mine[k * mine.size() / kSample].a;
                std::nth_element(sample.begin(), sample.begin() + kSample / 2, sample.end());
                middle = sample[kSample / 2];
            }
            middle = std::clamp(middle, part.lo, part.hi);
            auto at =
                std::partition(mine.begin(), mine.end(), [&](const PairReport& h) { return h.a < middle; });
            std::size_t cut = part.begin + static_cast<std::size_t>(at - mine.begin());
            next_[2 * p] = {part.begin, cut, part.lo, middle};
            next_[2 * p + 1] = {cut, part.end, middle, part.hi};
        }
    };
    if (parts_.size() > 1)
        parallelFor(*tasks, static_cast<std::uint32_t>(parts_.size()), 1, splitParts);
    else
        splitParts(0, 1, 0);
    parts_.swap(next_);
}

void HitOrder::sortPart(std::span<PairReport> hits, const Part& part, std::size_t countsAt) {
    std::span<PairReport> mine = hits.subspan(part.begin, part.end - part.begin);
    std::span<std::uint32_t> rank = std::span<std::uint32_t>(rank_).subspan(part.begin, mine.size());
    // Counting sort by A: where each hit goes, then that permutation applied in place.
    CountingSort byA(std::span<std::uint32_t>(counts_).subspan(countsAt, part.hi - part.lo + 1));
    for (const PairReport& h : mine) byA.count(h.a - part.lo);
    byA.startRuns();
    for (std::size_t k = 0; k < mine.size(); ++k) rank[k] = byA.place(mine[k].a - part.lo);
    permuteInPlace(mine, rank);
    // Within one A, order by B: runs are short, so insertion sort.
    for (std::size_t begin = 0; begin < mine.size();) {
        std::size_t end = begin + 1;
        while (end < mine.size() && mine[end].a == mine[begin].a) ++end;
        for (std::size_t i = begin + 1; i < end; ++i)
            for (std::size_t j = i; j > begin && mine[j].b < mine[j - 1].b; --j)
                std::swap(mine[j], mine[j - 1]);
        begin = end;
    }
}

std::size_t HitOrder::bytes() const {
    return (parts_.capacity() + next_.capacity()) * sizeof(Part) +
           (counts_.capacity() + rank_.capacity()) * sizeof(std::uint32_t);
}

}  // namespace polar
