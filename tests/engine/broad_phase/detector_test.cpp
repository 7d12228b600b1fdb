#include "broad_phase/detector.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "bits.h"
#include "polar/authoring/random_scene.h"
#include "polar/world.h"

namespace polar {
namespace {

struct Objects {
    std::vector<GameObject> objects;
    std::vector<std::uint32_t> collisions;  // indices of the objects flagged collisions, ascending
};

Objects mixedObjects(std::uint64_t seed, std::size_t n) {
    World world = buildWorld(makeMixedScene(seed, n, BroadPhase::AllPairs));
    Objects o{{world.objects().begin(), world.objects().end()}, {}};
    for (std::uint32_t i = 0; i < o.objects.size(); ++i)
        if (o.objects[i].has(kCollisions)) o.collisions.push_back(i);
    return o;
}

// One detection pass as the World runs it: prepare, the containers' pass, then the hits.
std::vector<PairReport> detect(Detector& detector, const Objects& o, BroadPhase method, Accuracy accuracy,
                               bool all = false, std::uint64_t layout = 1) {
    detector.prepare({.objects = o.objects,
                      .candidates = o.collisions,
                      .containers = true,
                      .accuracy = accuracy,
                      .fastStarts = {}},
                     method, layout);
    EffectStats stats, containerStats;
    detector.testContainers(containerStats);
    detector.findHits(all, o.objects.size(), stats, containerStats);
    return {detector.hits().begin(), detector.hits().end()};
}

void expectSameReports(const std::vector<PairReport>& expected, const std::vector<PairReport>& actual,
                       const std::string& where) {
    ASSERT_EQ(expected.size(), actual.size()) << where;
    for (std::size_t k = 0; k < expected.size(); ++k) {
        const PairTest& e = expected[k].test;
        const PairTest& a = actual[k].test;
        ASSERT_EQ(expected[k].a, actual[k].a) << where << " hit " << k;
        ASSERT_EQ(expected[k].b, actual[k].b) << where << " hit " << k;
        ASSERT_EQ(e.hit, a.hit) << where;
        ASSERT_EQ(e.kind, a.kind) << where;
        ASSERT_EQ(bits(e.distance), bits(a.distance)) << where;
        ASSERT_EQ(bits(e.penetration), bits(a.penetration)) << where;
        ASSERT_EQ(bits(e.normal.x()), bits(a.normal.x())) << where;
        ASSERT_EQ(bits(e.normal.y()), bits(a.normal.y())) << where;
    }
}

void expectPairOrder(const std::vector<PairReport>& hits, const std::string& where) {
    for (std::size_t k = 0; k < hits.size(); ++k) {
        ASSERT_LT(hits[k].a, hits[k].b) << where;
        if (k > 0) {
            bool ascending =
                hits[k - 1].a < hits[k].a || (hits[k - 1].a == hits[k].a && hits[k - 1].b < hits[k].b);
            ASSERT_TRUE(ascending) << where << " hit " << k;
        }
    }
}

TEST(Detector, HitsComeInPairOrderAndEqualAllPairs) {
    for (std::uint64_t seed : {2u, 3u, 4u}) {
        Objects o = mixedObjects(seed, 300);
        for (Accuracy accuracy : kAllAccuracies) {
            Detector reference;
            std::vector<PairReport> expected = detect(reference, o, BroadPhase::AllPairs, accuracy);
            std::string where = "seed " + std::to_string(seed) + " " + accuracyName(accuracy);
            expectPairOrder(expected, where);
            EXPECT_GT(expected.size(), 30u) << where;
            EXPECT_TRUE(std::any_of(expected.begin(), expected.end(), [](const PairReport& h) {
                return h.test.kind == ContactKind::Container;
            })) << where;
            for (BroadPhase method : {BroadPhase::Grid, BroadPhase::SortAndSweep}) {
                Detector detector;
                std::vector<PairReport> hits = detect(detector, o, method, accuracy);
                expectSameReports(expected, hits, where + " " + broadPhaseName(method));
            }
        }
    }
}

TEST(Detector, ContainerHitsEqualAllPairsWhereTheLevelChangesTheRule) {
    // Square containers by the nearest rule and by chord, read at every level (chord and nearest
    // override the file's rule), with held circles along the diagonal from well inside to past
    // every wall: the walls' inner circles must follow the rule each level reads.
    Objects o;
    for (bool interpolate : {false, true}) {
        std::vector<RadiusSample> square;
        for (int k = 0; k < 4; ++k) square.push_back({kHalfPi * k, 10.0});
        GameObject container;
        container.flags = kCollisions | kContainer;
        container.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), square, interpolate)});
        container.transform.setPosition(Vec2(interpolate ? 100.0 : 0.0, 0.0));
        o.objects.push_back(container);
        for (int k = 0; k < 40; ++k) {
            GameObject held;
            held.flags = kCollisions;
            held.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), 1.0)});
            double d = 4.0 + 0.15 * k;
            held.transform.setPosition(container.transform.position() + Vec2(d, d));
            o.objects.push_back(held);
        }
    }
    for (std::uint32_t i = 0; i < o.objects.size(); ++i) o.collisions.push_back(i);
    for (Accuracy accuracy : kAllAccuracies) {
        Detector reference;
        std::vector<PairReport> expected = detect(reference, o, BroadPhase::AllPairs, accuracy);
        EXPECT_GT(expected.size(), 20u) << accuracyName(accuracy);
        for (BroadPhase method : {BroadPhase::Grid, BroadPhase::SortAndSweep}) {
            Detector detector;
            expectSameReports(expected, detect(detector, o, method, accuracy),
                              std::string(accuracyName(accuracy)) + " " + broadPhaseName(method));
        }
    }
}

TEST(Detector, AllPairsWithAllReportsEveryTestedPair) {
    Objects o = mixedObjects(6, 150);
    Detector detector;
    std::vector<PairReport> reports = detect(detector, o, BroadPhase::AllPairs, Accuracy::Bounds, true);
    expectPairOrder(reports, "all");
    const StepData& data = detector.data();
    std::vector<PairReport> expected;
    for (std::uint32_t i = 0; i < data.size(); ++i)
        for (std::uint32_t j = i + 1; j < data.size(); ++j)
            if (pairIsTested(data.poses[i], data.poses[j], true))
                expected.push_back(
                    {data.objectIndex[i], data.objectIndex[j], testPair(data.poses[i], data.poses[j])});
    expectSameReports(expected, reports, "all");
    std::size_t misses =
        std::count_if(reports.begin(), reports.end(), [](const PairReport& r) { return !r.test.hit; });
    EXPECT_GT(misses, reports.size() / 2) << "most tested pairs miss";
}

TEST(Detector, ForEachNearVisitsEveryOverlappingBoxAndEveryContainer) {
    Objects o = mixedObjects(8, 300);
    for (BroadPhase method : kAllBroadPhases) {
        Detector detector;
        detect(detector, o, method, Accuracy::Bounds);
        const StepData& data = detector.data();
        for (std::uint32_t self = 0; self < data.size(); self += 5) {
            Box box = data.box(self);
            // Twice as wide, so that each query meets several boxes.
            double w = box.maxX - box.minX, h = box.maxY - box.minY;
            Box query{box.minX - w, box.minY - h, box.maxX + w, box.maxY + h};
            std::map<std::uint32_t, int> visited;
            detector.forEachNear(self, query, [&](std::uint32_t j) { ++visited[j]; });
            EXPECT_FALSE(visited.count(self));
            for (const auto& [j, times] : visited) EXPECT_EQ(times, 1) << broadPhaseName(method);
            for (std::uint32_t j : data.regularSlots) {
                if (j == self || !data.box(j).overlaps(query)) continue;
                EXPECT_TRUE(visited.count(j)) << broadPhaseName(method) << " slot " << j;
            }
            for (std::uint32_t j : data.containerSlots) {
                if (j == self) continue;
                EXPECT_TRUE(visited.count(j)) << broadPhaseName(method) << " container " << j;
            }
        }
    }
}

TEST(Detector, TheGridLaysOutTheNextStepInItsCellOrderWhileTheLayoutHolds) {
    Objects o = mixedObjects(10, 400);
    Detector detector;
    std::vector<PairReport> first = detect(detector, o, BroadPhase::Grid, Accuracy::Bounds, false, 7);
    const std::vector<std::uint32_t>& slots = detector.data().objectIndex;
    EXPECT_TRUE(std::is_sorted(slots.begin(), slots.end())) << "a new layout starts in creation order";
    std::vector<std::uint32_t> creationOrder = slots;

    std::vector<PairReport> second = detect(detector, o, BroadPhase::Grid, Accuracy::Bounds, false, 7);
    std::vector<std::uint32_t> cellOrder = detector.data().objectIndex;
    EXPECT_FALSE(std::is_sorted(cellOrder.begin(), cellOrder.end())) << "the last step's cell order";
    std::sort(cellOrder.begin(), cellOrder.end());
    EXPECT_EQ(cellOrder, creationOrder);
    expectSameReports(first, second, "the slot order changes nothing");

    detect(detector, o, BroadPhase::Grid, Accuracy::Bounds, false, 8);
    EXPECT_TRUE(std::is_sorted(detector.data().objectIndex.begin(), detector.data().objectIndex.end()))
        << "a changed layout forgets the order";
}

}  // namespace
}  // namespace polar
