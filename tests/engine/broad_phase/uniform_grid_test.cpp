#include "broad_phase/uniform_grid.h"

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

// Makes slot `slot` fast: it ends where its reach circle is and started `start`; its box covers
// both circles, as StepData::build makes it.
void makeFast(StepData& data, std::uint32_t slot, double startX, double startY) {
    ReachCircle before = data.reach[slot];
    before.x = startX;
    before.y = startY;
    Box box = Box::around(data.reach[slot]).merged(Box::around(before));
    data.reach[slot].fast = static_cast<std::uint32_t>(data.fastSlots.size());
    data.fastSlots.push_back({slot, startX, startY, box});
}

// Every pair (i < j) the grid yields, each counted; slots in sorted().
std::map<Pair, int> gridPairs(const UniformGrid& grid) {
    std::map<Pair, int> pairs;
    for (std::size_t p = 0; p < grid.sorted().size(); ++p) {
        std::uint32_t i = grid.sorted()[p];
        grid.forEachPartner(p, [&](std::uint32_t j) { ++pairs[{std::min(i, j), std::max(i, j)}]; });
    }
    return pairs;
}

// The pairs of entered (not huge) slots whose discs touch, by brute force.
std::set<Pair> touchingPairs(const std::vector<Disc>& discs, const UniformGrid& grid) {
    std::vector<bool> entered(discs.size(), false);
    for (std::uint32_t s : grid.sorted()) entered[s] = true;
    std::set<Pair> pairs;
    for (std::uint32_t i = 0; i < discs.size(); ++i)
        for (std::uint32_t j = i + 1; j < discs.size(); ++j)
            if (entered[i] && entered[j] && discs[i].touches(discs[j])) pairs.insert({i, j});
    return pairs;
}

// The grid's contract: every touching pair exactly once, and no other pair.
void expectExactlyTheTouchingPairs(const std::vector<Disc>& discs, const UniformGrid& grid) {
    std::map<Pair, int> found = gridPairs(grid);
    std::set<Pair> expected = touchingPairs(discs, grid);
    for (const auto& [pair, times] : found) {
        EXPECT_EQ(times, 1) << "pair " << pair.first << "," << pair.second << " visited more than once";
        EXPECT_TRUE(expected.count(pair)) << "pair " << pair.first << "," << pair.second << " does not touch";
    }
    for (const Pair& pair : expected)
        EXPECT_TRUE(found.count(pair)) << "touching pair " << pair.first << "," << pair.second << " missed";
}

// Groups of five discs: A; B touching A on its right (dx = ra + rb) and C below it, exactly, in
// exactly representable numbers (multiples of 1/16 well inside 2⁵³); D one ulp farther right than
// B (the centre distance's square then exceeds the radius sum's); E touching A along a 3-4-5
// diagonal (centres (3u, 4u) apart, radii summing to 5u). Returns how many pairs touch.
std::size_t addExactContacts(std::vector<Disc>& discs, std::mt19937_64& rng, double extent, int count) {
    std::uniform_int_distribution<int> eighths(0, static_cast<int>(extent) * 8), sixteenths(8, 160),
        extra(1, 40);
    std::size_t touching = 0;
    for (int k = 0; k < count; ++k) {
        double x = eighths(rng) / 8.0, y = eighths(rng) / 8.0;
        double ra = sixteenths(rng) / 16.0, rb = sixteenths(rng) / 16.0;
        double u = (std::ceil(ra * 16.0 / 5.0) + extra(rng)) / 16.0;  // 5u > ra
        discs.push_back({x, y, ra});
        discs.push_back({x + (ra + rb), y, rb});
        discs.push_back({x, y - (ra + rb), rb});
        discs.push_back({std::nextafter(x + (ra + rb), INFINITY), y, rb});
        discs.push_back({x + 3 * u, y + 4 * u, 5 * u - ra});
        touching += 3;
    }
    return touching;
}

TEST(UniformGrid, YieldsExactlyThePairsWhoseDiscsTouch) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> position(0.0, 1000.0), logRadius(std::log(0.5), std::log(60.0));
    std::vector<Disc> discs;
    for (int k = 0; k < 2000; ++k) discs.push_back({position(rng), position(rng), std::exp(logRadius(rng))});
    std::size_t designed = addExactContacts(discs, rng, 1000.0, 150);
    StepData data = stepDataOf(discs);
    UniformGrid grid;
    grid.build(data, data.regularSlots, 1.5);
    EXPECT_TRUE(grid.dense());
    EXPECT_GE(grid.tierCount(), 3u) << "mixed sizes use several tiers";
    EXPECT_TRUE(grid.huge().empty());
    ASSERT_EQ(grid.sorted().size(), discs.size());
    expectExactlyTheTouchingPairs(discs, grid);

    // The designed contacts are among the pairs, and the ulp-apart ones are not.
    std::map<Pair, int> found = gridPairs(grid);
    std::size_t first = 2000, contacts = 0;
    for (std::uint32_t a = static_cast<std::uint32_t>(first); a < discs.size(); a += 5) {
        for (std::uint32_t b : {a + 1, a + 2, a + 4})
            ASSERT_TRUE(discs[a].touches(discs[b])) << a << "," << b;
        contacts += found.count({a, a + 1}) + found.count({a, a + 2}) + found.count({a, a + 4});
        ASSERT_FALSE(discs[a].touches(discs[a + 3])) << a;
        EXPECT_FALSE(found.count({a, a + 3})) << "an ulp apart";
    }
    EXPECT_EQ(contacts, designed);
}

TEST(UniformGrid, SortsEveryEnteredSlotOnce) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> position(-300.0, 300.0), radius(0.5, 8.0);
    std::vector<Disc> discs;
    for (int k = 0; k < 500; ++k) discs.push_back({position(rng), position(rng), radius(rng)});
    StepData data = stepDataOf(discs);
    // Build over every other slot: the rest are not the grid's.
    std::vector<std::uint32_t> slots;
    for (std::uint32_t s = 0; s < discs.size(); s += 2) slots.push_back(s);
    UniformGrid grid;
    grid.build(data, slots, 1.5);
    std::vector<std::uint32_t> sorted(grid.sorted().begin(), grid.sorted().end());
    std::sort(sorted.begin(), sorted.end());
    EXPECT_EQ(sorted, slots);
}

TEST(UniformGrid, HashedCellsFarApartGiveTheSamePairs) {
    // Clusters across an extent far wider than 8 cells per object: the grid hashes its cells.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> centre(-1e7, 1e7), near(-15.0, 15.0), radius(0.5, 3.0);
    std::vector<Disc> discs;
    for (int c = 0; c < 60; ++c) {
        double cx = centre(rng), cy = centre(rng);
        for (int k = 0; k < 25; ++k) discs.push_back({cx + near(rng), cy + near(rng), radius(rng)});
    }
    StepData data = stepDataOf(discs);
    UniformGrid grid;
    grid.build(data, data.regularSlots, 1.5);
    EXPECT_FALSE(grid.dense());
    expectExactlyTheTouchingPairs(discs, grid);
    EXPECT_GT(touchingPairs(discs, grid).size(), 100u);
}

TEST(UniformGrid, CellsPastTheClampStillGiveExactlyTheTouchingPairs) {
    // Small discs spread over some 10^10 base cells: cell coordinates are clamped at 2^26 from the
    // grid's corner (the home is packed in 8 bytes), so the far clusters share the edge cells.
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> near(-12.0, 12.0), radius(0.5, 3.0);
    std::vector<Disc> discs;
    for (double cx : {0.0, 3e8, 7e9, 2e10, 2e10 + 60.0, 4e10})
        for (double cy : {0.0, 5e9, 4e10})
            for (int k = 0; k < 20; ++k) discs.push_back({cx + near(rng), cy + near(rng), radius(rng)});
    StepData data = stepDataOf(discs);
    for (double factor : {1.5, 40.0}) {
        UniformGrid grid;
        grid.build(data, data.regularSlots, factor);
        expectExactlyTheTouchingPairs(discs, grid);
        EXPECT_GT(touchingPairs(discs, grid).size(), 100u);
    }
}

// Built on workers (the sort in blocks of slots and ranges of keys), the grid lists its slots in the
// one-thread order, cell by cell, dense or hashed, with huge slots left out, at any worker count.
TEST(UniformGrid, SortsAsOneThreadDoesOnAnyWorkerCount) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> position(0.0, 800.0), far(-1e7, 1e7), radius(0.5, 12.0);
    std::vector<Disc> dense, hashed;
    for (int k = 0; k < 3000; ++k) dense.push_back({position(rng), position(rng), radius(rng)});
    for (int c = 0; c < 40; ++c) {
        double cx = far(rng), cy = far(rng);
        for (int k = 0; k < 40; ++k) hashed.push_back({cx + radius(rng), cy + radius(rng), radius(rng)});
    }
    hashed.push_back({0.0, 0.0, 1e25});  // huge
    for (const std::vector<Disc>* discs : {&dense, &hashed}) {
        StepData data = stepDataOf(*discs);
        UniformGrid one;
        one.build(data, data.regularSlots, 1.5);
        EXPECT_EQ(one.dense(), discs == &dense);
        const std::vector<std::uint32_t> order(one.sorted().begin(), one.sorted().end());
        for (std::uint32_t workers : {2u, 3u, 7u, 16u, 64u}) {
            ThreadPool pool(workers);
            UniformGrid shared;
            shared.setTasks(&pool, 1);
            shared.build(data, data.regularSlots, 1.5);
            EXPECT_EQ(std::vector<std::uint32_t>(shared.sorted().begin(), shared.sorted().end()), order)
                << workers << " workers, " << (discs == &dense ? "dense" : "hashed");
            EXPECT_EQ(shared.huge(), one.huge());
            EXPECT_EQ(shared.huge().size(), discs == &dense ? 0u : 1u);
            EXPECT_EQ(gridPairs(shared), gridPairs(one));
        }
    }
}

TEST(UniformGrid, LeavesHugeSlotsOutOfTheGrid) {
    std::mt19937_64 rng(23);
    std::uniform_real_distribution<double> position(0.0, 200.0), radius(0.5, 2.0);
    std::vector<Disc> discs;
    for (int k = 0; k < 300; ++k) discs.push_back({position(rng), position(rng), radius(rng)});
    discs.push_back({100.0, 100.0, 1e25});  // a side beyond c·2⁶³ for a cell of a few units
    auto giant = static_cast<std::uint32_t>(discs.size() - 1);
    StepData data = stepDataOf(discs);
    UniformGrid grid;
    grid.build(data, data.regularSlots, 1.5);
    ASSERT_EQ(grid.huge().size(), 1u);
    EXPECT_EQ(grid.huge()[0], giant);
    EXPECT_EQ(std::count(grid.sorted().begin(), grid.sorted().end(), giant), 0);
    expectExactlyTheTouchingPairs(discs, grid);
}

TEST(UniformGrid, KeepsItsCellUnlessTheSizesChangeByHalf) {
    std::vector<Disc> discs;
    for (int k = 0; k < 100; ++k) discs.push_back({4.0 * k, 0.0, 1.0});
    StepData data = stepDataOf(discs);
    UniformGrid grid;
    grid.build(data, data.regularSlots, 1.5);
    EXPECT_EQ(grid.cellSize(), 1.5 * 2.0);  // 1.5 × the median box side
    for (ReachCircle& c : data.reach) c.radius = 1.4;
    grid.build(data, data.regularSlots, 1.5);
    EXPECT_EQ(grid.cellSize(), 3.0) << "within 1.5×: the homes stay put";
    for (ReachCircle& c : data.reach) c.radius = 2.5;
    grid.build(data, data.regularSlots, 1.5);
    EXPECT_EQ(grid.cellSize(), 1.5 * 5.0);
}

TEST(UniformGrid, FindsEveryBoxOverlappingAQuery) {
    std::mt19937_64 rng(29);
    std::uniform_real_distribution<double> position(0.0, 500.0), logRadius(std::log(0.5), std::log(40.0));
    std::vector<Disc> discs;
    for (int k = 0; k < 1500; ++k) discs.push_back({position(rng), position(rng), std::exp(logRadius(rng))});
    StepData data = stepDataOf(discs);
    UniformGrid grid;
    grid.build(data, data.regularSlots, 1.5);
    std::uniform_real_distribution<double> corner(-50.0, 550.0), side(0.0, 60.0);
    for (int q = 0; q < 200; ++q) {
        double x = corner(rng), y = corner(rng);
        // The last queries are wider than the whole scene (every home of a tier is tested instead).
        double w = q < 190 ? side(rng) : 2000.0, h = q < 190 ? side(rng) : 3000.0;
        Box query{x, y, x + w, y + h};
        std::map<std::uint32_t, int> visited;
        grid.forEachOverlapping(query, [&](std::uint32_t j) { ++visited[j]; });
        for (const auto& [j, times] : visited) EXPECT_EQ(times, 1) << "slot " << j;
        for (std::uint32_t j = 0; j < discs.size(); ++j) {
            if (!data.box(j).overlaps(query)) continue;
            EXPECT_TRUE(visited.count(j)) << "query " << q << " slot " << j;
        }
    }
}

TEST(UniformGrid, AFastSlotMeetsWhatItsReachTouchesAnywhereOnItsCast) {
    std::mt19937_64 rng(31);
    std::uniform_real_distribution<double> position(0.0, 400.0), radius(0.5, 4.0), unit(0.0, 1.0);
    std::vector<Disc> discs;
    for (int k = 0; k < 600; ++k) discs.push_back({position(rng), position(rng), radius(rng)});
    // The bullet ends at (300, 250) and started at (60, 90).
    discs.push_back({300.0, 250.0, 1.0});
    auto bullet = static_cast<std::uint32_t>(discs.size() - 1);
    StepData data = stepDataOf(discs);
    makeFast(data, bullet, 60.0, 90.0);
    UniformGrid grid;
    grid.build(data, data.regularSlots, 1.5);
    std::set<std::uint32_t> partners;
    for (const auto& [pair, times] : gridPairs(grid)) {
        if (pair.first == bullet) partners.insert(pair.second);
        if (pair.second == bullet) partners.insert(pair.first);
    }
    std::size_t touched = 0;
    for (int sample = 0; sample <= 1000; ++sample) {
        double t = sample / 1000.0;
        Disc at{60.0 + t * 240.0, 90.0 + t * 160.0, 1.0};
        for (std::uint32_t j = 0; j < bullet; ++j) {
            if (!at.touches(discs[j])) continue;
            ++touched;
            EXPECT_TRUE(partners.count(j)) << "slot " << j << " touches the cast at t = " << t;
        }
    }
    EXPECT_GT(touched, 0u);
}

}  // namespace
}  // namespace polar
