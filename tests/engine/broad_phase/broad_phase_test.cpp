#include "polar/broad_phase.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstring>
#include <span>

#include "bits.h"
#include "broad_phase/step_data.h"
#include "polar/authoring/random_scene.h"
#include "polar/world.h"

namespace polar {
namespace {

// Debug builds (with sanitizers, ten to fifty times slower in the all-pairs reference) check the same
// properties on smaller scenes; Release runs the full sizes.
#ifdef NDEBUG
constexpr std::size_t kSizeDivisor = 1;
#else
constexpr std::size_t kSizeDivisor = 5;
#endif

// Bit-for-bit equality of two pair reports (NaN equals NaN with the same payload).
void expectSameReports(std::span<const PairReport> expected, std::span<const PairReport> actual,
                       const std::string& where) {
    ASSERT_EQ(expected.size(), actual.size()) << where;
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const PairReport& e = expected[k];
        const PairReport& a = actual[k];
        ASSERT_EQ(e.a, a.a) << where << " report " << k;
        ASSERT_EQ(e.b, a.b) << where << " report " << k;
        ASSERT_EQ(e.test.hit, a.test.hit) << where;
        ASSERT_EQ(e.test.kind, a.test.kind) << where;
        ASSERT_EQ(e.test.radiiA, a.test.radiiA) << where;
        ASSERT_EQ(e.test.radiiB, a.test.radiiB) << where;
        ASSERT_EQ(bits(e.test.distance), bits(a.test.distance)) << where;
        ASSERT_EQ(bits(e.test.ra), bits(a.test.ra)) << where;
        ASSERT_EQ(bits(e.test.rb), bits(a.test.rb)) << where;
        ASSERT_EQ(bits(e.test.penetration), bits(a.test.penetration)) << where;
        ASSERT_EQ(bits(e.test.normal.x()), bits(a.test.normal.x())) << where;
        ASSERT_EQ(bits(e.test.normal.y()), bits(a.test.normal.y())) << where;
    }
}

void expectSameObjects(const World& expected, const World& actual, const std::string& where) {
    ASSERT_EQ(expected.objects().size(), actual.objects().size());
    for (std::size_t i = 0; i < expected.objects().size(); ++i) {
        const GameObject& e = expected.objects()[i];
        const GameObject& a = actual.objects()[i];
        ASSERT_EQ(bits(e.transform.position().x()), bits(a.transform.position().x()))
            << where << " " << e.name;
        ASSERT_EQ(bits(e.transform.position().y()), bits(a.transform.position().y()))
            << where << " " << e.name;
        ASSERT_EQ(bits(e.transform.rotation()), bits(a.transform.rotation())) << where << " " << e.name;
        ASSERT_EQ(bits(e.velocity.x()), bits(a.velocity.x())) << where << " " << e.name;
        ASSERT_EQ(bits(e.velocity.y()), bits(a.velocity.y())) << where << " " << e.name;
        ASSERT_THAT(actual.collidedWith(a.id), testing::ElementsAreArray(expected.collidedWith(e.id)))
            << where << " " << e.name;
    }
}

struct Coverage {
    std::size_t hits = 0, containerHits = 0, ghostHits = 0, compoundHits = 0, largeHits = 0;
};

void count(const World& world, Coverage& c) {
    for (const PairReport& hit : world.hits()) {
        const GameObject& a = world.objects()[hit.a];
        const GameObject& b = world.objects()[hit.b];
        ++c.hits;
        if (hit.test.kind == ContactKind::Container) ++c.containerHits;
        if (a.has(kGhost) || b.has(kGhost)) ++c.ghostHits;
        if (a.boundsOrEmpty().size() > 1 || b.boundsOrEmpty().size() > 1) ++c.compoundHits;
        if (a.boundsOrEmpty()[0].maxRadius() > 100 || b.boundsOrEmpty()[0].maxRadius() > 100) ++c.largeHits;
    }
}

GeneratedScene withMethod(GeneratedScene scene, BroadPhase method) {
    scene.def.broadPhase = method;
    return scene;
}

// Steps one world per broad phase side by side and checks every step's hits and the resulting
// objects against all-pairs, bit for bit.
Coverage expectSameAsAllPairs(const GeneratedScene& scene, int steps, const std::string& name,
                              bool expectCulling = true) {
    Coverage coverage;
    World reference = buildWorld(withMethod(scene, BroadPhase::AllPairs));
    std::vector<World> others;
    for (BroadPhase method : {BroadPhase::Grid, BroadPhase::SortAndSweep})
        others.push_back(buildWorld(withMethod(scene, method)));
    for (int s = 0; s < steps; ++s) {
        reference.step(1.0 / 60.0);
        count(reference, coverage);
        for (World& other : others) {
            std::string where = std::string(broadPhaseName(other.def().broadPhase)) + " " + name + " step " +
                                std::to_string(s);
            other.step(1.0 / 60.0);
            expectSameReports(reference.hits(), other.hits(), where);
            expectSameObjects(reference, other, where);
            if (expectCulling) {
                EXPECT_LT(other.lastStepStats().pairsTested, reference.lastStepStats().pairsTested) << where;
            }
        }
    }
    return coverage;
}

Coverage expectSameAsAllPairs(std::uint64_t seed, std::size_t n, int steps) {
    return expectSameAsAllPairs(makeMixedScene(seed, n, BroadPhase::AllPairs), steps,
                                "seed " + std::to_string(seed) + " n " + std::to_string(n));
}

TEST(BroadPhase, NamesRoundTrip) {
    for (BroadPhase method : kAllBroadPhases) EXPECT_EQ(broadPhaseFromName(broadPhaseName(method)), method);
    EXPECT_FALSE(broadPhaseFromName("quadtree"));
}

TEST(BroadPhase, SameHitsAndResponsesAsAllPairsOnSmallScenes) {
    Coverage total;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        Coverage c = expectSameAsAllPairs(seed, 250, 20 / static_cast<int>(kSizeDivisor));
        total.hits += c.hits;
        total.containerHits += c.containerHits;
        total.ghostHits += c.ghostHits;
        total.compoundHits += c.compoundHits;
        total.largeHits += c.largeHits;
    }
    // The scenes exercise what they claim to.
    EXPECT_GT(total.hits, 1000u / kSizeDivisor);
    EXPECT_GT(total.containerHits, 50u / kSizeDivisor);
    EXPECT_GT(total.ghostHits, 100u / kSizeDivisor);
    EXPECT_GT(total.compoundHits, 300u / kSizeDivisor);
    EXPECT_GT(total.largeHits, 20u / kSizeDivisor);
    std::printf("[          ] %zu hits: %zu container, %zu ghost, %zu compound, %zu with giants\n",
                total.hits, total.containerHits, total.ghostHits, total.compoundHits, total.largeHits);
}

TEST(BroadPhase, SameHitsFarFromTheOriginAndAtExtremeScales) {
    for (double offset : {1e6, 1e15, 1e60, 1e200}) {
        GeneratedScene scene = makeMixedScene(31, 150, BroadPhase::AllPairs);
        SceneRandom random(7);
        for (ObjectDef& o : scene.objects) {
            o.transform.translate(offset, -offset);
            double pick = random.uniform(0.0, 1.0);
            if (pick < 0.05)
                o.transform.setScale(o.transform.scaleFactors() * 1e3);
            else if (pick < 0.1)
                o.transform.setScale(o.transform.scaleFactors() * 1e-3);
        }
        // At 10^60 and beyond a coordinate's last bit exceeds the scene: every object is at one point,
        // every pair hits, and there is nothing left to cull. The hits must still agree.
        Coverage c = expectSameAsAllPairs(scene, 3, "offset " + std::to_string(offset), offset < 1e20);
        EXPECT_GT(c.hits, 50u) << offset;
    }
    // An object larger than the grid's deepest tier (2^63 base cells) is paired linearly.
    GeneratedScene scene = makeMixedScene(32, 150, BroadPhase::AllPairs);
    std::size_t huge = 20;
    while (!scene.objects[huge].bounds || (scene.objects[huge].flags & kContainer)) ++huge;
    scene.objects[huge].transform.setScale(Vec2(1e25, 2e25));
    scene.objects[huge].flags = kCollisions | kGhost;
    Coverage c = expectSameAsAllPairs(scene, 2, "a huge object", false);
    EXPECT_GT(c.hits, 250u);
}

TEST(BroadPhase, SameHitsAndResponsesAsAllPairsAt1000) {
    expectSameAsAllPairs(77, 1000 / kSizeDivisor, 3);
}

TEST(BroadPhase, SameHitsAndResponsesAsAllPairsAt5000) {
    Coverage c = expectSameAsAllPairs(2024, 5000 / kSizeDivisor, 1);
    EXPECT_GT(c.hits, 1000u / kSizeDivisor);
}

TEST(BroadPhase, SameHitsAsAllPairsOnARockField) {
    const std::size_t n = 1500 / kSizeDivisor;
    World reference = buildWorld(makeRockField(5, n, 4.0, BroadPhase::AllPairs));
    World grid = buildWorld(makeRockField(5, n, 4.0, BroadPhase::Grid));
    for (int s = 0; s < 2; ++s) {
        reference.step(1.0 / 60.0);
        grid.step(1.0 / 60.0);
        expectSameReports(reference.hits(), grid.hits(), "rock field step " + std::to_string(s));
        expectSameObjects(reference, grid, "rock field");
    }
    EXPECT_GT(grid.hits().size(), 400u / kSizeDivisor);
    // The grid tests a small multiple of the hits, all-pairs every pair.
    EXPECT_LT(grid.lastStepStats().pairsTested, 4 * grid.hits().size());
    EXPECT_EQ(reference.lastStepStats().pairsTested, n * (n - 1) / 2);
}

TEST(BroadPhase, SameHitsAsAllPairsWhenBoundsChangeBetweenSteps) {
    // Each grid step plans the next from its own slots (SlotPlan); bounds swapped between steps
    // (hot reload) must not leak through the plan, on one thread or two.
    const std::size_t n = 2600 / kSizeDivisor;
    World reference = buildWorld(makeRockField(8, n, 4.0, BroadPhase::AllPairs));
    GeneratedScene scene = makeRockField(8, n, 4.0, BroadPhase::Grid);
    scene.def.workers = 2;
    scene.def.parallelMin = 1;
    World two = buildWorld(scene);
    scene.def.workers = 1;
    World one = buildWorld(scene);
    BoundsPtr single, compound;
    for (const GameObject& o : reference.objects())
        (o.boundsOrEmpty().size() == 1 ? single : compound) = o.bounds;
    ASSERT_TRUE(single && compound);
    for (int s = 0; s < 8; ++s) {
        for (World* world : {&reference, &one, &two}) {
            std::span<GameObject> objects = world->objects();
            if (s == 2) objects[n / 3].bounds = nullptr;
            if (s == 3)
                objects[n / 2].bounds = objects[n / 2].boundsOrEmpty().size() == 1 ? compound : single;
            if (s == 4) objects[n / 3].bounds = compound;
            if (s == 5) objects[7].flags |= kFast;
            world->step(1.0 / 60.0);
        }
        expectSameReports(reference.hits(), one.hits(), "one thread, step " + std::to_string(s));
        expectSameReports(reference.hits(), two.hits(), "two threads, step " + std::to_string(s));
        expectSameObjects(reference, two, "two threads, step " + std::to_string(s));
    }
    EXPECT_GT(two.hits().size(), 500u / kSizeDivisor);
}

TEST(BroadPhase, DetectAgreesWithAllPairs) {
    World world = buildWorld(makeMixedScene(9, 800 / kSizeDivisor, BroadPhase::Grid));
    std::vector<PairReport> all = world.detect(true);
    std::vector<PairReport> hits;
    for (const PairReport& r : all)
        if (r.test.hit) hits.push_back(r);
    expectSameReports(hits, world.detect(false), "detect");
}

ObjectDef circleAt(const std::string& name, double x, double y, double radius) {
    ObjectDef o;
    o.name = name;
    o.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), radius)});
    o.transform.setPosition(Vec2(x, y));
    o.flags = kCollisions;
    return o;
}

// Each broad phase's hits, which must all equal all-pairs'.
std::vector<PairReport> expectSameHitsByEveryMethod(World& world, const std::string& where) {
    world.setBroadPhase(BroadPhase::AllPairs);
    std::vector<PairReport> expected = world.detect(false);
    for (BroadPhase method : {BroadPhase::Grid, BroadPhase::SortAndSweep}) {
        world.setBroadPhase(method);
        expectSameReports(expected, world.detect(false), where + " " + broadPhaseName(method));
    }
    return expected;
}

TEST(BroadPhase, SameHitsAtExactContact) {
    // Circles that touch exactly, in exactly representable numbers: the narrow phase calls
    // |u| = rA + rB a hit, so every broad phase must hand it these pairs. A 16 × 16 lattice of
    // radius 1 at pitch 2 (each touches its edge neighbours; diagonals are 2√2 apart), and pairs
    // of radius 2.5 whose centres are (3, 4) apart (|u|² = 25 = 5²), far from the origin.
    World world(WorldDef{kEffectCollisions, 0.8});
    for (int row = 0; row < 16; ++row)
        for (int column = 0; column < 16; ++column)
            world.add(circleAt("lattice-" + std::to_string(row) + "-" + std::to_string(column),
                               1024.0 + 2 * column, -512.0 + 2 * row, 1.0));
    for (int k = 0; k < 20; ++k) {
        double x = 65536.0 + 16 * k, y = 4096.0 + 0.25 * k;
        world.add(circleAt("a-" + std::to_string(k), x, y, 2.5));
        world.add(circleAt("b-" + std::to_string(k), x + 3, y + 4, 2.5));
    }
    std::vector<PairReport> hits = expectSameHitsByEveryMethod(world, "exact contact");
    EXPECT_EQ(hits.size(), 2u * 16 * 15 + 20u);
    for (const PairReport& hit : hits) EXPECT_EQ(hit.test.penetration, 0.0);
}

TEST(BroadPhase, SameHitsWhereReachCirclesTouchExactly) {
    // Pairs of circles placed so that their reach circles (radius plus margin) touch exactly: A at
    // (0, y), B at (d, y) with d the sum of radii and margins to the bit, so the centre distance is d
    // exactly. Culling then sits on its boundary, where only the narrow phase may decide (here: a
    // miss, the circles being the margins apart). B's margin grows with its coordinates, so d is
    // settled by placing B again until the margins stop changing.
    constexpr std::uint32_t kPairs = 40;
    auto build = [&](const std::vector<double>& d) {
        World world(WorldDef{kEffectCollisions, 0.8});
        for (std::uint32_t k = 0; k < kPairs; ++k) {
            world.add(circleAt("a-" + std::to_string(k), 0.0, 8.0 * k, 1.0));
            world.add(circleAt("b-" + std::to_string(k), d[k], 8.0 * k, 1.0));
        }
        return world;
    };
    auto stepData = [&](const World& world) {
        StepData data;
        std::vector<std::uint32_t> indices(world.objects().size()), others;
        for (std::uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        std::vector<GameObject> objects(world.objects().begin(), world.objects().end());
        data.build({.objects = objects,
                    .candidates = indices,
                    .containers = false,
                    .accuracy = Accuracy::Bounds,
                    .fastStarts = {}},
                   others);
        return data;
    };
    auto reachSums = [&](const StepData& data) {
        std::vector<double> sums(kPairs);
        for (std::uint32_t k = 0; k < kPairs; ++k) {
            const ReachCircle& a = data.reach[2 * k];
            const ReachCircle& b = data.reach[2 * k + 1];
            sums[k] = a.radius + b.radius + (static_cast<double>(a.margin) + static_cast<double>(b.margin));
        }
        return sums;
    };
    std::vector<double> gaps(kPairs, 2.0);
    for (int round = 0; round < 10; ++round) {
        std::vector<double> sums = reachSums(stepData(build(gaps)));
        if (sums == gaps) break;
        gaps = sums;
    }
    World world = build(gaps);
    StepData data = stepData(world);
    ASSERT_EQ(reachSums(data), gaps) << "the margins settle";
    for (std::uint32_t k = 0; k < kPairs; ++k) {
        EXPECT_GT(gaps[k], 2.0);
        EXPECT_TRUE(data.mayHit(2 * k, 2 * k + 1)) << "touching reach circles may hit";
    }
    EXPECT_TRUE(expectSameHitsByEveryMethod(world, "reach contact").empty());
    // An ulp closer the reach circles overlap; an ulp farther they are apart. Same hits again.
    for (double direction : {0.0, double(INFINITY)}) {
        std::vector<double> moved = gaps;
        for (double& d : moved) d = std::nextafter(d, direction);
        World other = build(moved);
        EXPECT_TRUE(expectSameHitsByEveryMethod(other, "an ulp off reach contact").empty());
    }
}

}  // namespace
}  // namespace polar
