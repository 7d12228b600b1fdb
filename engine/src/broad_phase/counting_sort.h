#pragma once
#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace polar {

// A stable counting sort by small integer keys, k ∈ [0, keyCount), over a caller-owned array of
// run starts, in two passes over the items in the same order:
//   1. count(k) for every item;             startRuns(): starts[k] = #items with key < k
//   2. place(k) for every item, in order:   its position, starts[k]++ (equal keys keep their order)
//   3. rewindRuns(), when the runs are wanted: place() left starts[k] at the end of run k (the start
//      of run k + 1), so shift back. Then run k is [starts[k], starts[k + 1]), starts[keyCount] = #items.
//
// Why a view over the caller's vector? The broad phase sorts every step (cells, hits, pairs, each
// object's partners), and a step in a steady state allocates nothing: the vector keeps its capacity
// from step to step, and this only writes into it.
class CountingSort {
  public:
    // Zeroes keyCount + 1 run starts.
    CountingSort(std::vector<std::uint32_t>& starts, std::size_t keyCount)
        : starts_(zeroed(starts, keyCount + 1)), keyCount_(keyCount) {}
    // The same over a part of a caller's array: keys [0, starts.size() − 1). Zeroes it.
    explicit CountingSort(std::span<std::uint32_t> starts)
        : starts_(starts.data()), keyCount_(starts.size() - 1) {
        assert(!starts.empty());
        std::fill(starts.begin(), starts.end(), 0u);
    }

    void count(std::size_t key) {
        assert(key < keyCount_);
        ++starts_[key + 1];
    }
    // Turns the counts into the start of each key's run.
    void startRuns() {
        for (std::size_t k = 1; k <= keyCount_; ++k) starts_[k] += starts_[k - 1];
    }
    // The sorted position of the next item with this key.
    std::uint32_t place(std::size_t key) { return starts_[key]++; }
    // After every item is placed: each run's start again.
    void rewindRuns() {
        for (std::size_t k = keyCount_; k > 0; --k) starts_[k] = starts_[k - 1];
        starts_[0] = 0;
    }

  private:
    static std::uint32_t* zeroed(std::vector<std::uint32_t>& v, std::size_t size) {
        v.assign(size, 0);
        return v.data();
    }

    std::uint32_t* starts_;
    std::size_t keyCount_;
};

// Moves items[k] to items[to[k]] for every k, in place, where `to` is a permutation of the
// positions (it is consumed: it ends as the identity). Each swap puts one item where it belongs,
// so no second array of items is needed.
//
// The swaps follow a cycle of the permutation, each waiting for the item the last one named. The
// cycle's next few positions are read ahead in `to` (a small array, in cache; the part of a cycle
// not yet walked is unchanged), so that the items they name are fetched while earlier swaps run.
template <class T>
void permuteInPlace(std::span<T> items, std::span<std::uint32_t> to) {
    assert(items.size() == to.size());
    constexpr int kAhead = 4;
    for (std::uint32_t k = 0; k < items.size(); ++k) {
        while (to[k] != k) {
            std::uint32_t target = to[k];
            std::uint32_t ahead = target;
            for (int d = 0; d < kAhead && to[ahead] != k; ++d) ahead = to[ahead];
            __builtin_prefetch(&items[ahead]);
            __builtin_prefetch(reinterpret_cast<const char*>(&items[ahead]) + sizeof(T) - 1);
            std::swap(items[k], items[target]);
            std::swap(to[k], to[target]);
        }
    }
}

}  // namespace polar
