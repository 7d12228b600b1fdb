#pragma once
#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>

namespace polar {

// The objects of a step's hits joined into groups: two objects share a group when a chain of hits
// links them (the contact graph's connected components), and a group is named by its lowest index.
//
// Why groups? A response reads and writes both its objects, so the order of the hits on one object
// decides its bits. Hits of different groups share no object, directly or through others: each group
// may run on its own thread, in pair order, and every object sees its hits in the order one thread
// gives them. A pile that touches end to end is one group, and runs on one thread.
//
// Why lock-free? Workers join the pairs of their own blocks of hits at once. A root is only ever
// linked under a lower root, by compare-and-swap, so whatever the interleaving the groups come out
// the same and each one's root is its lowest index. Finding a root halves the path as it goes (a
// node is pointed at its grandparent, still an ancestor), which races harmlessly with other finds.
class ContactGroups {
  public:
    // Room for `objects` objects, each its own group. Between runs every object is its own group
    // again (the runs undo their joins with ungroup), so only new room is written.
    void resize(std::size_t objects) {
        if (objects > capacity_) {
            // Grown between runs, on one thread: the old entries move over as they are.
            std::size_t capacity = std::max(objects, 2 * capacity_);
            auto grown = std::make_unique<std::atomic<std::uint32_t>[]>(capacity);
            for (std::size_t i = 0; i < size_; ++i)
                grown[i].store(parent_[i].load(std::memory_order_relaxed), std::memory_order_relaxed);
            parent_ = std::move(grown);
            capacity_ = capacity;
        }
        for (std::size_t i = size_; i < objects; ++i)
            parent_[i].store(static_cast<std::uint32_t>(i), std::memory_order_relaxed);
        size_ = objects;
    }
    // Makes x its own group again. Once every object of a group is ungrouped, the group is gone.
    void ungroup(std::uint32_t x) { ref(x).store(x, std::memory_order_relaxed); }

    // Puts a and b in one group; safe on several threads at once.
    void join(std::uint32_t a, std::uint32_t b) {
        for (;;) {
            a = root(a);
            b = root(b);
            if (a == b) return;
            if (a > b) std::swap(a, b);
            // b is a root above a: point it at a, unless another thread linked it first.
            std::uint32_t expected = b;
            if (ref(b).compare_exchange_strong(expected, a, std::memory_order_acq_rel)) return;
        }
    }

    // The lowest index of x's group, once every join is done (during joins: some root above x).
    std::uint32_t root(std::uint32_t x) {
        for (;;) {
            std::uint32_t parent = ref(x).load(std::memory_order_acquire);
            if (parent == x) return x;
            std::uint32_t grandparent = ref(parent).load(std::memory_order_acquire);
            if (grandparent != parent) ref(x).store(grandparent, std::memory_order_release);
            x = grandparent;
        }
    }

    // Asks for x's entry ahead of a join or root that will read it.
    void prefetch(std::uint32_t x) const { __builtin_prefetch(&parent_[x]); }

    std::size_t bytes() const { return capacity_ * sizeof(std::uint32_t); }

  private:
    // An array of atomics rather than std::atomic_ref over plain numbers: the web build's standard
    // library (Debian's emscripten) has no atomic_ref.
    std::atomic<std::uint32_t>& ref(std::uint32_t x) { return parent_[x]; }

    std::unique_ptr<std::atomic<std::uint32_t>[]> parent_;
    std::size_t size_ = 0;
    std::size_t capacity_ = 0;
};

}  // namespace polar
