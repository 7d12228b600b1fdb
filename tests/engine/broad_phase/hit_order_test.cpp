// HitOrder puts hits in pair order, whatever order they arrive in and however many parts it splits
// them into.
#include "broad_phase/hit_order.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <vector>

namespace polar {
namespace {

// Distinct pairs a < b of `objects` objects, shuffled; `sameA` of them share A = 3 (a long run).
std::vector<PairReport> shuffledHits(std::size_t count, std::uint32_t objects, std::size_t sameA,
                                     std::uint32_t seed) {
    std::mt19937 random(seed);
    std::set<std::uint64_t> distinct;
    for (std::uint32_t b = 4; b < objects && distinct.size() < sameA; ++b) distinct.insert((3ull << 32) | b);
    while (distinct.size() < count + sameA) {
        std::uint32_t a = random() % objects, b = random() % objects;
        if (a == b) continue;
        if (a > b) std::swap(a, b);
        distinct.insert((std::uint64_t(a) << 32) | b);
    }
    std::vector<std::uint64_t> keys(distinct.begin(), distinct.end());
    std::shuffle(keys.begin(), keys.end(), random);
    std::vector<PairReport> hits;
    for (std::uint64_t key : keys) {
        PairReport h;
        h.a = static_cast<std::uint32_t>(key >> 32);
        h.b = static_cast<std::uint32_t>(key);
        h.test.distance = static_cast<double>(h.a) * 1000.0 + h.b;  // travels with its pair
        hits.push_back(h);
    }
    return hits;
}

void expectPairOrder(const std::vector<PairReport>& sorted, std::vector<PairReport> input,
                     const std::string& what) {
    std::sort(input.begin(), input.end(),
              [](const PairReport& x, const PairReport& y) { return x.a != y.a ? x.a < y.a : x.b < y.b; });
    ASSERT_EQ(sorted.size(), input.size()) << what;
    for (std::size_t k = 0; k < sorted.size(); ++k) {
        ASSERT_EQ(sorted[k].a, input[k].a) << what << ", hit " << k;
        ASSERT_EQ(sorted[k].b, input[k].b) << what << ", hit " << k;
        ASSERT_EQ(sorted[k].test.distance, input[k].test.distance) << what << ", hit " << k;
    }
}

TEST(HitOrder, SortsIntoPairOrderInAnyNumberOfParts) {
    ThreadPool pool(8);  // as many workers as the most parts asked for below
    HitOrder order;      // one, reused, as the detector keeps it
    struct Case {
        std::size_t count;
        std::uint32_t objects;
        std::size_t sameA;
    };
    for (Case c : {Case{3000, 5000, 0}, Case{3000, 400, 0}, Case{2000, 3000, 900}, Case{40, 10, 0},
                   Case{0, 10, 0}, Case{1, 2, 0}}) {
        std::vector<PairReport> input = shuffledHits(c.count, c.objects, c.sameA, 7 + c.count);
        for (std::uint32_t parts : {1u, 2u, 3u, 4u, 8u}) {  // at most, with the pool
            for (TaskSystem* tasks : {static_cast<TaskSystem*>(nullptr), static_cast<TaskSystem*>(&pool)}) {
                std::vector<PairReport> hits = input;
                order.sort(hits, c.objects, tasks, parts);
                expectPairOrder(hits, input,
                                std::to_string(hits.size()) + " hits of " + std::to_string(c.objects) +
                                    " objects, " + std::to_string(parts) + " parts" +
                                    (tasks ? ", pool" : ""));
            }
        }
    }
}

TEST(HitOrder, HitsAllOfOneObjectStillSort) {
    // Every hit has the same A: the sampled median cannot split them, and one part takes them all.
    std::vector<PairReport> input;
    for (std::uint32_t b = 1000; b > 1; --b) input.push_back({1, b, {}});
    ThreadPool pool(2);
    HitOrder order;
    std::vector<PairReport> hits = input;
    order.sort(hits, 1001, &pool, 8);
    expectPairOrder(hits, input, "one A");
}

}  // namespace
}  // namespace polar
