// A step on several threads is the one-thread step to the bit: the same hits in the same order, the
// same responses, the same World::hash after every step, at 1, 2, 3, 4, 7 and 16 workers (and the
// collidedWith lists at every count from 1 to 64).
#include <gtest/gtest.h>

#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "polar/authoring/random_scene.h"
#include "polar/world.h"

namespace polar {
namespace {

constexpr double kDt = 1.0 / 60.0;
constexpr std::uint32_t kWorkerCounts[] = {1, 2, 3, 4, 7, 16};

// Every bit of a step's hits: pairs, and each PairTest field.
std::vector<std::uint64_t> hitBits(const World& world) {
    std::vector<std::uint64_t> bits;
    auto add = [&](double v) {
        std::uint64_t b = 0;
        std::memcpy(&b, &v, sizeof b);
        bits.push_back(b);
    };
    for (const PairReport& h : world.hits()) {
        bits.push_back((std::uint64_t(h.a) << 32) | h.b);
        add(h.test.normal.x());
        add(h.test.normal.y());
        add(h.test.distance);
        add(h.test.ra);
        add(h.test.rb);
        add(h.test.penetration);
        bits.push_back((std::uint64_t(h.test.radiiA) << 32) | h.test.radiiB);
        bits.push_back(static_cast<std::uint64_t>(h.test.kind) * 2 + (h.test.hit ? 1 : 0));
    }
    return bits;
}

// What a run leaves to compare: the hash and the hits' bits after every step, and the counters
// that do not depend on timing.
struct Trace {
    std::vector<std::uint64_t> hashes;
    std::vector<std::vector<std::uint64_t>> hits;
    std::uint64_t pairsTested = 0;
    std::uint64_t responses = 0;
};

Trace run(GeneratedScene scene, std::uint32_t workers, std::uint32_t parallelMin, int steps,
          TaskSystem* tasks = nullptr) {
    scene.def.workers = workers;
    scene.def.parallelMin = parallelMin;
    scene.def.tasks = tasks;
    World world = buildWorld(scene);
    EXPECT_EQ(world.workerCount(), tasks ? tasks->workerCount() : workers);
    Trace trace;
    for (int s = 0; s < steps; ++s) {
        world.step(kDt);
        trace.hashes.push_back(world.hash());
        trace.hits.push_back(hitBits(world));
    }
    trace.pairsTested = world.totalStats().pairsTested;
    trace.responses = world.totalStats()[kEffectResponse].pairs;
    return trace;
}

void expectSameTrace(const Trace& reference, const Trace& other, const std::string& what) {
    ASSERT_EQ(reference.hashes.size(), other.hashes.size()) << what;
    for (std::size_t s = 0; s < reference.hashes.size(); ++s) {
        ASSERT_EQ(reference.hashes[s], other.hashes[s]) << what << ", step " << s + 1;
        ASSERT_EQ(reference.hits[s], other.hits[s]) << what << ", step " << s + 1;
    }
    EXPECT_EQ(reference.pairsTested, other.pairsTested) << what;
    EXPECT_EQ(reference.responses, other.responses) << what;
}

// Bullets flagged fast, so that ccd's casts run between the parallel phases.
void addBullets(GeneratedScene& scene, int count) {
    scene.def.effects |= kEffectCcd;
    for (int k = 0; k < count; ++k) {
        ObjectDef b;
        b.name = "bullet-" + std::to_string(k);
        b.bounds = std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), 2.0)});
        b.transform.setPosition(Vec2(37.0 * k, 23.0 * k));
        b.velocity = Vec2(3000.0, 2000.0 - 150.0 * k);
        b.flags = kPhysics | kCollisions | kFast;
        scene.objects.push_back(b);
    }
}

// parallelMin 1 sends even small worlds through every parallel path (blocks of a few items, more
// blocks than items at 16 workers), where a split at the wrong place would show.
TEST(ParallelStep, MixedScenesAreBitIdenticalAtEveryWorkerCount) {
    for (BroadPhase method : kAllBroadPhases) {
        for (std::uint64_t seed : {3u, 11u}) {
            GeneratedScene scene = makeMixedScene(seed, method == BroadPhase::AllPairs ? 150 : 400, method);
            addBullets(scene, 12);
            Trace reference = run(scene, 1, 1, 40);
            EXPECT_GT(reference.responses, 0u);
            for (std::uint32_t workers : kWorkerCounts) {
                std::string what = std::string(broadPhaseName(method)) + ", seed " + std::to_string(seed) +
                                   ", " + std::to_string(workers) + " workers";
                expectSameTrace(reference, run(scene, workers, 1, 40), what);
            }
        }
    }
}

// A rock field above the default threshold, so the phases share their work as a game would.
TEST(ParallelStep, ALargeRockFieldIsBitIdenticalAtTheDefaultThreshold) {
#ifdef NDEBUG
    constexpr std::size_t kRocks = 12000;
#else
    constexpr std::size_t kRocks = 5000;  // sanitized Debug builds are slow
#endif
    static_assert(kRocks > WorldDef::kDefaultParallelMin);
    GeneratedScene scene = makeRockField(7, kRocks, 4.0, BroadPhase::Grid);
    Trace reference = run(scene, 1, WorldDef::kDefaultParallelMin, 12);
    EXPECT_GT(reference.responses, 0u);
    for (std::uint32_t workers : kWorkerCounts)
        expectSameTrace(reference, run(scene, workers, WorldDef::kDefaultParallelMin, 12),
                        std::to_string(workers) + " workers");
}

// Workers write their hits at positions claimed in a list sized by the last step. A step that finds
// far more than any before (the field squeezed to a tenth of its area) claims past that room: the
// spilled hits must join the list and sort into the same order as on one thread. A copy keeps them.
TEST(ParallelStep, AStepWithFarMoreHitsThanAnyBeforeIsBitIdentical) {
    auto squeezed = [](std::uint32_t workers) {
        GeneratedScene scene = makeRockField(5, 3000, 4.0, BroadPhase::Grid);
        scene.def.workers = workers;
        scene.def.parallelMin = 1;
        World world = buildWorld(scene);
        Trace trace;
        for (int s = 0; s < 16; ++s) {
            if (s == 8)
                for (GameObject& o : world.objects()) o.transform.setPosition(0.3 * o.transform.position());
            world.step(kDt);
            trace.hashes.push_back(world.hash());
            trace.hits.push_back(hitBits(world));
        }
        World copy = world;
        EXPECT_EQ(hitBits(copy), hitBits(world)) << workers << " workers: a copy keeps the last hits";
        return trace;
    };
    Trace reference = squeezed(1);
    ASSERT_GT(reference.hits[8].size(), 4 * reference.hits[7].size()) << "the squeeze must multiply the hits";
    for (std::uint32_t workers : {2u, 3u, 16u})
        expectSameTrace(reference, squeezed(workers), std::to_string(workers) + " workers");
}

// Every object's collidedWith list after a step, ids in order, one list after another.
std::vector<std::uint64_t> listBits(const World& world) {
    std::vector<std::uint64_t> bits;
    for (const GameObject& o : world.objects()) {
        const std::span<const ObjectId> touched = world.collidedWith(o.id);
        bits.push_back(touched.size());
        bits.insert(bits.end(), touched.begin(), touched.end());
    }
    return bits;
}

// From three workers on, the lists and the responses run as contact groups shared among the workers
// (SharedResponse): every worker count from 1 to 64 gives the one-thread hashes, hits and lists, on a
// packed rock field (many groups, some long chains) and on a mixed scene (containers, ghosts, ccd).
TEST(ParallelStep, ResponsesAndListsAreBitIdenticalAtEveryWorkerCountFrom1To64) {
    GeneratedScene rocks = makeRockField(13, 2500, 4.0, BroadPhase::Grid);
    GeneratedScene mixed = makeMixedScene(17, 400, BroadPhase::Grid);
    addBullets(mixed, 8);
    for (const GeneratedScene* scene : {&rocks, &mixed}) {
        const std::string name = scene == &rocks ? "rock field" : "mixed scene";
        auto trace = [&](std::uint32_t workers) {
            GeneratedScene s = *scene;
            s.def.workers = workers;
            s.def.parallelMin = 1;
            World world = buildWorld(s);
            std::vector<std::vector<std::uint64_t>> steps;
            for (int k = 0; k < 8; ++k) {
                world.step(kDt);
                std::vector<std::uint64_t> bits = hitBits(world);
                const std::vector<std::uint64_t> lists = listBits(world);
                bits.push_back(world.hash());
                bits.insert(bits.end(), lists.begin(), lists.end());
                steps.push_back(std::move(bits));
            }
            EXPECT_GT(world.totalStats()[kEffectResponse].pairs, 0u) << name;
            return steps;
        };
        const std::vector<std::vector<std::uint64_t>> reference = trace(1);
        for (std::uint32_t workers = 2; workers <= 64; ++workers) {
            const std::vector<std::vector<std::uint64_t>> other = trace(workers);
            for (std::size_t k = 0; k < reference.size(); ++k)
                ASSERT_EQ(other[k], reference[k]) << name << ", " << workers << " workers, step " << k + 1;
        }
    }
}

TEST(ParallelStep, AGivenTaskSystemGivesTheSameBits) {
    GeneratedScene scene = makeMixedScene(5, 400, BroadPhase::Grid);
    Trace reference = run(scene, 1, 1, 30);
    ThreadPool pool(3);
    expectSameTrace(reference, run(scene, 1, 1, 30, &pool), "a ThreadPool of 3 given as WorldDef::tasks");
}

// A copy of a world that owns its pool gets a pool of its own, with as many workers; a copy of a
// world given a task system shares it. Either way, the copy steps to the same bits.
TEST(ParallelStep, CopiesAndMovesKeepTheirWorkers) {
    GeneratedScene scene = makeMixedScene(9, 300, BroadPhase::Grid);
    scene.def.workers = 3;
    scene.def.parallelMin = 1;
    World original = buildWorld(scene);
    for (int s = 0; s < 5; ++s) original.step(kDt);
    World copy = original;
    EXPECT_EQ(copy.workerCount(), 3u);
    for (int s = 0; s < 10; ++s) {
        original.step(kDt);
        copy.step(kDt);
        ASSERT_EQ(original.hash(), copy.hash()) << "step " << s;
    }
    World moved = std::move(copy);
    EXPECT_EQ(moved.workerCount(), 3u);
    World assigned;
    assigned = moved;
    EXPECT_EQ(assigned.workerCount(), 3u);
    for (int s = 0; s < 10; ++s) {
        original.step(kDt);
        moved.step(kDt);
        assigned.step(kDt);
        ASSERT_EQ(original.hash(), moved.hash()) << "step " << s;
        ASSERT_EQ(original.hash(), assigned.hash()) << "step " << s;
    }

    ThreadPool pool(2);
    scene.def.tasks = &pool;
    World shared = buildWorld(scene);
    World sharedCopy = shared;
    EXPECT_EQ(sharedCopy.def().tasks, &pool);
    EXPECT_EQ(sharedCopy.workerCount(), 2u);
    for (int s = 0; s < 10; ++s) {
        shared.step(kDt);
        sharedCopy.step(kDt);
        ASSERT_EQ(shared.hash(), sharedCopy.hash()) << "step " << s;
    }
}

TEST(ParallelStep, OneWorkerStartsNoPool) {
    World world(WorldDef{kEffectPhysics | kEffectCollisions});
    EXPECT_EQ(world.workerCount(), 1u);
    WorldDef def;
    def.workers = 4;
    EXPECT_EQ(World(def).workerCount(), 4u);
}

}  // namespace
}  // namespace polar
