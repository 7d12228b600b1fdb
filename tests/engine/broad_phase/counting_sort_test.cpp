#include "broad_phase/counting_sort.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

namespace polar {
namespace {

// Sorts `keys` with CountingSort the way its callers do (count, start, place, rewind) and returns
// the item indices in sorted order; `starts` holds the runs.
std::vector<std::uint32_t> countingOrder(const std::vector<std::uint32_t>& keys, std::size_t keyCount,
                                         std::vector<std::uint32_t>& starts) {
    CountingSort sort(starts, keyCount);
    for (std::uint32_t k : keys) sort.count(k);
    sort.startRuns();
    std::vector<std::uint32_t> order(keys.size(), ~0u);
    for (std::uint32_t i = 0; i < keys.size(); ++i) order[sort.place(keys[i])] = i;
    sort.rewindRuns();
    return order;
}

// The same order by the standard library: by key, equal keys in their input order.
std::vector<std::uint32_t> stableOrder(const std::vector<std::uint32_t>& keys) {
    std::vector<std::uint32_t> order(keys.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return keys[a] < keys[b]; });
    return order;
}

TEST(CountingSort, IsStableAndItsRunsHoldEachKey) {
    std::mt19937_64 rng(3);
    std::vector<std::uint32_t> starts;
    for (std::size_t keyCount : {1u, 2u, 7u, 100u, 5000u}) {
        for (std::size_t n : {0u, 1u, 13u, 1000u}) {
            std::uniform_int_distribution<std::uint32_t> key(0, static_cast<std::uint32_t>(keyCount - 1));
            std::vector<std::uint32_t> keys(n);
            for (std::uint32_t& k : keys) k = key(rng);
            if (n > 1) keys[0] = 0, keys[1] = static_cast<std::uint32_t>(keyCount - 1);  // both extremes
            std::vector<std::uint32_t> order = countingOrder(keys, keyCount, starts);
            EXPECT_EQ(order, stableOrder(keys)) << keyCount << " keys, " << n << " items";
            ASSERT_EQ(starts.size(), keyCount + 1);
            EXPECT_EQ(starts[0], 0u);
            EXPECT_EQ(starts[keyCount], n);
            for (std::size_t k = 0; k < keyCount; ++k) {
                ASSERT_LE(starts[k], starts[k + 1]);
                for (std::uint32_t p = starts[k]; p < starts[k + 1]; ++p) ASSERT_EQ(keys[order[p]], k);
            }
        }
    }
}

TEST(CountingSort, StartsRunsBeforePlacingAndEndsThemAfter) {
    // Keys 2, 0, 2, 3 over 5 keys: runs 0:[0,1) 1:[1,1) 2:[1,3) 3:[3,4) 4:[4,4).
    std::vector<std::uint32_t> keys{2, 0, 2, 3}, starts;
    CountingSort sort(starts, 5);
    for (std::uint32_t k : keys) sort.count(k);
    EXPECT_EQ(starts, (std::vector<std::uint32_t>{0, 1, 0, 2, 1, 0}));  // counts, one place on
    sort.startRuns();
    EXPECT_EQ(starts, (std::vector<std::uint32_t>{0, 1, 1, 3, 4, 4}));
    EXPECT_EQ(sort.place(2), 1u);
    EXPECT_EQ(sort.place(0), 0u);
    EXPECT_EQ(sort.place(2), 2u);
    EXPECT_EQ(sort.place(3), 3u);
    EXPECT_EQ(starts, (std::vector<std::uint32_t>{1, 1, 3, 4, 4, 4}));  // each run's end
    sort.rewindRuns();
    EXPECT_EQ(starts, (std::vector<std::uint32_t>{0, 1, 1, 3, 4, 4}));
}

TEST(CountingSort, ReusesTheCallersMemory) {
    std::vector<std::uint32_t> starts;
    std::vector<std::uint32_t> keys{4, 1, 1, 0};
    countingOrder(keys, 64, starts);
    const std::uint32_t* memory = starts.data();
    std::size_t capacity = starts.capacity();
    for (int round = 0; round < 3; ++round) {
        std::vector<std::uint32_t> order = countingOrder(keys, 64 - round, starts);
        EXPECT_EQ(order, stableOrder(keys));
        EXPECT_EQ(starts.data(), memory);
        EXPECT_EQ(starts.capacity(), capacity);
    }
}

TEST(PermuteInPlace, MovesEachItemToItsTarget) {
    std::mt19937_64 rng(9);
    for (std::size_t n : {0u, 1u, 2u, 17u, 1000u}) {
        std::vector<std::uint32_t> to(n);
        std::iota(to.begin(), to.end(), 0u);
        std::shuffle(to.begin(), to.end(), rng);
        std::vector<std::pair<int, int>> items(n), moved;
        for (std::size_t k = 0; k < n; ++k) items[k] = {static_cast<int>(k), static_cast<int>(3 * k)};
        std::vector<std::pair<int, int>> expected(n);
        for (std::size_t k = 0; k < n; ++k) expected[to[k]] = items[k];
        permuteInPlace(std::span<std::pair<int, int>>(items), std::span<std::uint32_t>(to));
        EXPECT_EQ(items, expected) << n;
        for (std::uint32_t k = 0; k < n; ++k) EXPECT_EQ(to[k], k) << "the permutation is used up";
    }
}

TEST(PermuteInPlace, AppliesACountingSortsPlaces) {
    // The detector's use: sort records by a key through their places, without a second array.
    std::vector<std::pair<std::uint32_t, char>> items{{3, 'a'}, {1, 'b'}, {3, 'c'}, {0, 'd'}, {1, 'e'}};
    std::vector<std::uint32_t> starts, to(items.size());
    CountingSort sort(starts, 4);
    for (const auto& item : items) sort.count(item.first);
    sort.startRuns();
    for (std::size_t k = 0; k < items.size(); ++k) to[k] = sort.place(items[k].first);
    permuteInPlace(std::span(items), std::span(to));
    std::vector<std::pair<std::uint32_t, char>> expected{{0, 'd'}, {1, 'b'}, {1, 'e'}, {3, 'a'}, {3, 'c'}};
    EXPECT_EQ(items, expected);
}

}  // namespace
}  // namespace polar
