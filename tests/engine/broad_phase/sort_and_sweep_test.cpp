#include "broad_phase/sort_and_sweep.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "disc_step_data.h"

namespace polar {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

// The contract: visit(i, j) with i < j once for every pair of built slots whose boxes overlap
// (touching counts), and for no other pair.
void expectExactlyTheOverlappingPairs(const SortAndSweep& sweep, const StepData& data,
                                      const std::vector<std::uint32_t>& slots) {
    std::map<Pair, int> found;
    sweep.forEachPair([&](std::uint32_t i, std::uint32_t j) {
        EXPECT_LT(i, j);
        ++found[{i, j}];
    });
    std::set<Pair> expected;
    for (std::size_t a = 0; a < slots.size(); ++a)
        for (std::size_t b = a + 1; b < slots.size(); ++b)
            if (data.box(slots[a]).overlaps(data.box(slots[b])))
                expected.insert({std::min(slots[a], slots[b]), std::max(slots[a], slots[b])});
    for (const auto& [pair, times] : found) {
        EXPECT_EQ(times, 1) << pair.first << "," << pair.second;
        EXPECT_TRUE(expected.count(pair)) << pair.first << "," << pair.second << " do not overlap";
    }
    for (const Pair& pair : expected)
        EXPECT_TRUE(found.count(pair)) << pair.first << "," << pair.second << " missed";
}

std::vector<Disc> randomDiscs(std::mt19937_64& rng, int n, double extent) {
    std::uniform_real_distribution<double> position(0.0, extent), logRadius(std::log(0.5), std::log(30.0));
    std::vector<Disc> discs;
    for (int k = 0; k < n; ++k) discs.push_back({position(rng), position(rng), std::exp(logRadius(rng))});
    return discs;
}

TEST(SortAndSweep, YieldsExactlyThePairsWhoseBoxesOverlap) {
    std::mt19937_64 rng(41);
    std::vector<Disc> discs = randomDiscs(rng, 1500, 800.0);
    StepData data = stepDataOf(discs);
    SortAndSweep sweep;
    sweep.build(data, data.regularSlots);
    expectExactlyTheOverlappingPairs(sweep, data, data.regularSlots);
}

TEST(SortAndSweep, BoxesTouchingExactlyArePairs) {
    // Squares of side 2 (radius 1) on a grid of pitch 2, in exactly representable coordinates:
    // each touches its neighbours along an edge and its diagonal neighbours at a corner. Equal left
    // edges (a column) are ties for the sort. A second layer a pitch and an ulp away touches nothing.
    std::vector<Disc> discs;
    for (int row = 0; row < 8; ++row)
        for (int column = 0; column < 8; ++column) discs.push_back({2.0 * column, 2.0 * row, 1.0});
    // The column that would touch the last one sits at x = 16; this one starts an ulp past its edge.
    double apart = std::nextafter(16.0, INFINITY);
    for (int row = 0; row < 8; ++row) discs.push_back({apart, 2.0 * row, 1.0});
    StepData data = stepDataOf(discs);
    SortAndSweep sweep;
    sweep.build(data, data.regularSlots);
    expectExactlyTheOverlappingPairs(sweep, data, data.regularSlots);
    std::size_t lattice = 0, across = 0;
    sweep.forEachPair([&](std::uint32_t i, std::uint32_t j) {
        lattice += j < 64 ? 1 : 0;
        across += i < 64 && j >= 64 ? 1 : 0;
    });
    // An 8 × 8 lattice: 2·8·7 edge neighbours and 2·7·7 diagonal ones.
    EXPECT_EQ(lattice, 2u * 8 * 7 + 2u * 7 * 7);
    EXPECT_EQ(across, 0u);
}

TEST(SortAndSweep, RepairsItsOrderAsBoxesMove) {
    // Objects drift a little each step: the order from the last build is repaired (insertion sort),
    // and the pairs stay exact.
    std::mt19937_64 rng(43);
    std::vector<Disc> discs = randomDiscs(rng, 800, 600.0);
    StepData data = stepDataOf(discs);
    SortAndSweep sweep;
    std::normal_distribution<double> drift(0.0, 3.0);
    for (int step = 0; step < 10; ++step) {
        sweep.build(data, data.regularSlots);
        expectExactlyTheOverlappingPairs(sweep, data, data.regularSlots);
        for (ReachCircle& c : data.reach) c.x += drift(rng), c.y += drift(rng);
    }
}

TEST(SortAndSweep, StartsAfreshWhenTheSlotsChange) {
    std::mt19937_64 rng(47);
    std::vector<Disc> discs = randomDiscs(rng, 600, 500.0);
    StepData data = stepDataOf(discs);
    SortAndSweep sweep;
    sweep.build(data, data.regularSlots);
    std::vector<std::uint32_t> fewer;
    for (std::uint32_t s = 0; s < discs.size(); ++s)
        if (s % 3 != 0) fewer.push_back(s);
    sweep.build(data, fewer);
    expectExactlyTheOverlappingPairs(sweep, data, fewer);
    sweep.build(data, data.regularSlots);
    expectExactlyTheOverlappingPairs(sweep, data, data.regularSlots);
}

}  // namespace
}  // namespace polar
