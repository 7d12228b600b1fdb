#pragma once
#include <algorithm>
#include <atomic>
#include <bit>
#include <cassert>
#include <cstddef>
#include <span>
#include <vector>

#include "polar/collision.h"

namespace polar {

// The hits of a detection pass: the first size() elements of an array whose rest is spare room.
//
// Why not a std::vector<PairReport> of exactly the hits? Workers write their hits at once, each at
// positions it claims, so the positions must exist before the pass: a vector's size would have to
// grow over them first, writing every new element, the whole spare room once per step. Here the
// room is written once, when it grows, and it only grows (a steady step allocates nothing). A pass
// that cannot know its hits in advance claims past the room; those hits wait in the worker's spill
// and join the list when the pass ends. The order of claims is the workers' race, so a list filled
// by claims is sorted into pair order afterwards: its contents never depend on who won.
class HitList {
  public:
    std::size_t size() const { return count_; }
    bool empty() const { return count_ == 0; }
    std::span<PairReport> items() { return {room_.data(), count_}; }
    std::span<const PairReport> items() const { return {room_.data(), count_}; }
    void clear() { count_ = 0; }

    // Room for `count` hits in all, grown on the calling thread.
    void reserve(std::size_t count) { grow(count); }
    // Appends, on the calling thread.
    void push(const PairReport& hit) {
        grow(count_ + 1);
        room_[count_++] = hit;
    }
    void append(std::span<const PairReport> hits) {
        grow(count_ + hits.size());
        std::copy(hits.begin(), hits.end(), room_.begin() + static_cast<std::ptrdiff_t>(count_));
        count_ += hits.size();
    }

    std::size_t capacity() const { return room_.capacity(); }
    std::size_t bytes() const { return room_.capacity() * sizeof(PairReport); }

  private:
    // The room is the vector's size, grown only as far as it is asked; the capacity past it stays
    // unwritten, out of the process's resident set. The capacity grows to powers of two, as
    // push_back would grow it, so that appending one run at a time costs nothing extra.
    void grow(std::size_t count) {
        if (count <= room_.size()) return;
        if (count > room_.capacity()) room_.reserve(std::bit_ceil(count));
        room_.resize(count);
    }

    friend class HitSink;
    std::vector<PairReport> room_;
    std::size_t count_ = 0;
};

// Where a run of hits goes: appended to a list by the one thread filling it, or, from one of several
// workers filling it at once, written at positions claimed in it.
class HitSink {
  public:
    // The calling thread alone fills `list`.
    explicit HitSink(HitList& list) : list_(&list) {}
    // Workers fill `list` together: positions are claimed from `next` (the list's size when the pass
    // began), and a hit claimed past the room goes to `spill`, this worker's own.
    HitSink(HitList& list, std::atomic<std::size_t>& next, std::vector<PairReport>& spill)
        : list_(&list), next_(&next), spill_(&spill) {}

    // Claims `count` positions and returns the first.
    std::size_t claim(std::size_t count) {
        if (!next_) {
            std::size_t first = list_->count_;
            list_->grow(first + count);
            list_->count_ += count;
            return first;
        }
        return next_->fetch_add(count, std::memory_order_relaxed);
    }
    // Writes a hit at a claimed position.
    void put(std::size_t position, const PairReport& hit) {
        if (position < list_->room_.size())
            list_->room_[position] = hit;
        else
            spill_->push_back(hit);
    }

    // After every worker's last put: the list holds every claimed hit, the spills' last.
    static void finishClaims(HitList& list, std::size_t claimed, std::span<std::vector<PairReport>> spills) {
        list.count_ = std::min(claimed, list.room_.size());
        for (std::vector<PairReport>& spill : spills) {
            list.append(spill);
            // The list now has room for them: a spill is rare, so its memory goes back.
            if (!spill.empty()) spill = {};
        }
        assert(list.count_ == claimed);
    }

  private:
    HitList* list_;
    std::atomic<std::size_t>* next_ = nullptr;
    std::vector<PairReport>* spill_ = nullptr;
};

}  // namespace polar
