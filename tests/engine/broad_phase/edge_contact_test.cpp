// Pairs at exact contact, for every broad phase: discs that touch edge to edge (so their boxes touch
// edge to edge too), boxes that touch only at a corner, touching points on grid cell borders, and
// the same one ulp apart. Touching counts everywhere (|u| ≤ rA + rB, box edges ≤), so every broad
// phase, at every cell size and thread count, must hand the narrow phase exactly what all-pairs
// would: one strict comparison in a sweep or a grid loses the pairs here.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <utility>
#include <vector>

#include "bits.h"
#include "broad_phase/sort_and_sweep.h"
#include "broad_phase/uniform_grid.h"
#include "disc_step_data.h"
#include "polar/world.h"

namespace polar {
namespace {

using Pair = std::pair<std::uint32_t, std::uint32_t>;

// Discs whose touching points and box edges sit on whole numbers, the cell borders of any grid
// whose cell side is a power of two: radius-1 discs at odd centres (pitch 2, boxes [2m, 2m + 2]),
// touching their row and column neighbours and meeting their diagonal ones box corner to box
// corner only; pairs of radii 0.5 and 1.5 meeting at x = 8k; 3-4-5 pairs (radii 2 and 3, centres
// (3, 4) apart); and each kind once more a hair (2⁻²⁰, exact at these coordinates) too far apart.
constexpr double kHair = 1.0 / (1 << 20);

std::vector<Disc> edgeContacts(double originX, double originY) {
    std::vector<Disc> discs;
    for (int row = 0; row < 6; ++row)
        for (int column = 0; column < 6; ++column)
            discs.push_back({originX + 1 + 2 * column, originY + 1 + 2 * row, 1.0});
    for (int k = 0; k < 6; ++k) {
        double x = originX + 8.0 * k, y = originY + 40.0;
        discs.push_back({x - 0.5, y, 0.5});
        discs.push_back({x + 1.5, y, 1.5});
        discs.push_back({x - 0.5, y + 8, 0.5});
        discs.push_back({x + 1.5 + kHair, y + 8, 1.5});
        discs.push_back({x, y + 16, 2.0});
        discs.push_back({x + 3, y + 20, 3.0});
        discs.push_back({x, y + 32, 2.0});
        discs.push_back({x + 3, y + 36 + kHair, 3.0});
    }
    return discs;
}

std::set<Pair> touchingPairs(const std::vector<Disc>& discs) {
    std::set<Pair> pairs;
    for (std::uint32_t i = 0; i < discs.size(); ++i)
        for (std::uint32_t j = i + 1; j < discs.size(); ++j)
            if (discs[i].touches(discs[j])) pairs.insert({i, j});
    return pairs;
}

Pair ordered(std::uint32_t i, std::uint32_t j) {
    return {std::min(i, j), std::max(i, j)};
}

TEST(EdgeContact, TheDiscsTouchAsPlanned) {
    std::vector<Disc> discs = edgeContacts(0, 0);
    // 6 × 6 lattice: 2·6·5 edge neighbours (diagonals are 2√2 apart); 6 pairs of each touching kind.
    EXPECT_EQ(touchingPairs(discs).size(), 2u * 6 * 5 + 6 + 6);
}

TEST(EdgeContact, TheSweepYieldsEveryPairWhoseBoxesTouch) {
    for (double origin : {0.0, -64.0, 1024.0}) {
        std::vector<Disc> discs = edgeContacts(origin, origin);
        StepData data = stepDataOf(discs);
        SortAndSweep sweep;
        sweep.build(data, data.regularSlots);
        std::set<Pair> yielded, touching, boxesTouching;
        sweep.forEachPair([&](std::uint32_t i, std::uint32_t j) {
            EXPECT_TRUE(yielded.insert(ordered(i, j)).second) << "pair yielded twice";
            if (discs[i].touches(discs[j])) touching.insert(ordered(i, j));
        });
        for (std::uint32_t i = 0; i < discs.size(); ++i)
            for (std::uint32_t j = i + 1; j < discs.size(); ++j)
                if (Box::around(data.reach[i]).overlaps(Box::around(data.reach[j])))
                    boxesTouching.insert({i, j});
        EXPECT_EQ(touching, touchingPairs(discs)) << "origin " << origin;
        EXPECT_EQ(yielded, boxesTouching) << "origin " << origin;
        EXPECT_GE(yielded.size() - touching.size(), 2u * 5 * 5)
            << "the lattice diagonals meet box corner to corner";
    }
}

TEST(EdgeContact, TheGridYieldsEveryTouchingPairOnCellBorders) {
    for (double cellFactor : {0.5, 1.0, 2.0, 4.0}) {
        for (double origin : {0.0, -64.0, 1024.0}) {
            std::vector<Disc> discs = edgeContacts(origin, origin);
            StepData data = stepDataOf(discs);
            UniformGrid grid;
            grid.build(data, data.regularSlots, cellFactor);
            double cell = grid.cellSize();
            int exponent = 0;
            ASSERT_EQ(std::frexp(cell, &exponent), 0.5) << "a power of two: whole numbers on cell borders";
            SCOPED_TRACE("cell factor " + std::to_string(cellFactor) + ", cell " + std::to_string(cell) +
                         ", origin " + std::to_string(origin));
            std::set<Pair> found;
            for (std::size_t p = 0; p < grid.sorted().size(); ++p) {
                std::uint32_t i = grid.sorted()[p];
                grid.forEachPartner(p, [&](std::uint32_t j) {
                    EXPECT_TRUE(found.insert(ordered(i, j)).second) << "pair visited twice";
                });
            }
            EXPECT_EQ(found, touchingPairs(discs));
        }
    }
}

ObjectDef disc(const Disc& d, std::size_t k) {
    ObjectDef o;
    o.name = "disc-" + std::to_string(k);
    o.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), d.reach)});
    o.transform.setPosition(Vec2(d.x, d.y));
    o.flags = kCollisions;
    return o;
}

// The same contacts in worlds with every broad phase at 1 to 4 threads (parallel paths forced on
// small worlds): the hits of a detection and of a step with response equal all-pairs' on one
// thread, bit for bit.
TEST(EdgeContact, EveryBroadPhaseAndThreadCountGivesTheSameHits) {
    std::vector<Disc> discs = edgeContacts(0, 0);
    std::vector<Disc> far = edgeContacts(65536.0, -4096.0);
    discs.insert(discs.end(), far.begin(), far.end());
    auto build = [&](BroadPhase method, std::uint32_t workers) {
        WorldDef def;
        def.effects = kEffectCollisions | kEffectResponse;
        def.broadPhase = method;
        def.workers = workers;
        def.parallelMin = 1;
        World world(def);
        for (std::size_t k = 0; k < discs.size(); ++k) world.add(disc(discs[k], k));
        return world;
    };
    World reference = build(BroadPhase::AllPairs, 1);
    std::vector<PairReport> expected = reference.detect(false);
    ASSERT_EQ(expected.size(), 2 * touchingPairs(edgeContacts(0, 0)).size());
    for (const PairReport& hit : expected) EXPECT_EQ(hit.test.penetration, 0.0);
    reference.step(1.0 / 60.0);
    for (BroadPhase method : {BroadPhase::AllPairs, BroadPhase::Grid, BroadPhase::SortAndSweep}) {
        for (std::uint32_t workers : {1u, 2u, 3u, 4u}) {
            std::string where = std::string(broadPhaseName(method)) + " at " + std::to_string(workers);
            World world = build(method, workers);
            std::vector<PairReport> hits = world.detect(false);
            ASSERT_EQ(hits.size(), expected.size()) << where;
            for (std::size_t k = 0; k < hits.size(); ++k) {
                EXPECT_EQ(hits[k].a, expected[k].a) << where;
                EXPECT_EQ(hits[k].b, expected[k].b) << where;
                EXPECT_EQ(bits(hits[k].test.penetration), bits(expected[k].test.penetration)) << where;
            }
            world.step(1.0 / 60.0);
            ASSERT_EQ(world.hits().size(), reference.hits().size()) << where;
            for (std::size_t i = 0; i < discs.size(); ++i) {
                const Vec2& p = world.objects()[i].transform.position();
                const Vec2& q = reference.objects()[i].transform.position();
                ASSERT_EQ(bits(p.x()), bits(q.x())) << where << " object " << i;
                ASSERT_EQ(bits(p.y()), bits(q.y())) << where << " object " << i;
            }
        }
    }
}

}  // namespace
}  // namespace polar
