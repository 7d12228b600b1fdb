// A step allocates nothing once the world is warm: every per-step buffer keeps its capacity.
// This file replaces the global allocation functions for the whole test program with counting
// ones; they only count, so other tests are unaffected.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <cstring>
#include <new>

#include "polar/authoring/random_scene.h"
#include "polar/world.h"

namespace {
std::atomic<std::uint64_t> allocations{0};

void* countedAllocate(std::size_t size, std::size_t alignment = 0) {
    allocations.fetch_add(1, std::memory_order_relaxed);
    if (size == 0) size = 1;
    void* p = alignment > alignof(std::max_align_t)
                  ? std::aligned_alloc(alignment, (size + alignment - 1) / alignment * alignment)
                  : std::malloc(size);
    if (!p) throw std::bad_alloc();
    return p;
}
}  // namespace

void* operator new(std::size_t size) {
    return countedAllocate(size);
}
void* operator new[](std::size_t size) {
    return countedAllocate(size);
}
void* operator new(std::size_t size, std::align_val_t a) {
    return countedAllocate(size, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t size, std::align_val_t a) {
    return countedAllocate(size, static_cast<std::size_t>(a));
}
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return countedAllocate(size);
    } catch (...) {
        return nullptr;
    }
}
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept {
    try {
        return countedAllocate(size);
    } catch (...) {
        return nullptr;
    }
}
void operator delete(void* p) noexcept {
    std::free(p);
}
void operator delete[](void* p) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete(void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept {
    std::free(p);
}

namespace polar {
namespace {

constexpr double kDt = 1.0 / 60.0;

bool sameBits(const Vec2& a, const Vec2& b) {
    return std::memcmp(a.data(), b.data(), sizeof(double) * 2) == 0;
}

struct Motion {
    Transform transform;
    Vec2 velocity;
    double spin;
};

// Warms a world up, steps it through a stretch, then puts every object back where the stretch began
// and counts the allocations of stepping through it again. The replay follows the same trajectory
// (checked), so every buffer already has the size the stretch needs: any allocation would be one
// that a step makes every time, which is what must not happen. (A first run can allocate when a
// step has more hits than any before it: the hit list and the collided lists grow once.)
std::uint64_t allocationsOfAReplayedStretch(World& world, int warmSteps, int stretch) {
    for (int s = 0; s < warmSteps; ++s) world.step(kDt);
    std::vector<Motion> start;
    for (const GameObject& o : world.objects()) start.push_back({o.transform, o.velocity, o.spin});
    for (int s = 0; s < stretch; ++s) world.step(kDt);
    std::vector<Motion> end;
    for (const GameObject& o : world.objects()) end.push_back({o.transform, o.velocity, o.spin});

    for (std::size_t i = 0; i < start.size(); ++i) {
        GameObject& o = world.objects()[i];
        o.transform = start[i].transform;
        o.velocity = start[i].velocity;
        o.spin = start[i].spin;
    }
    std::uint64_t before = allocations.load();
    for (int s = 0; s < stretch; ++s) world.step(kDt);
    std::uint64_t counted = allocations.load() - before;
    for (std::size_t i = 0; i < end.size(); ++i) {
        const GameObject& o = world.objects()[i];
        EXPECT_TRUE(sameBits(o.transform.position(), end[i].transform.position())) << o.name;
        EXPECT_TRUE(sameBits(o.velocity, end[i].velocity)) << o.name;
    }
    return counted;
}

TEST(Allocation, TheCounterSeesAllocations) {
    std::uint64_t before = allocations.load();
    auto* p = new std::vector<int>(100);
    delete p;
    EXPECT_GE(allocations.load() - before, 2u);
}

TEST(Allocation, ASteadyStepAllocatesNothingOnTheGrid) {
    World world = buildRockField(3, 3000, 4.0, BroadPhase::Grid);
    world.setTiming(true);
    EXPECT_EQ(allocationsOfAReplayedStretch(world, 20, 40), 0u);
    EXPECT_GT(world.hits().size(), 0u);
}

TEST(Allocation, ASteadyStepAllocatesNothingWithEveryEffect) {
    for (BroadPhase method : kAllBroadPhases) {
#ifdef NDEBUG
        GeneratedScene scene = makeMixedScene(8, 300, method);
#else
        GeneratedScene scene = makeMixedScene(8, 100, method);  // sanitized Debug: all-pairs is slow
#endif
        scene.def.effects |= kEffectCcd;
        for (int k = 0; k < 20; ++k) {
            ObjectDef b;
            b.name = "bullet-" + std::to_string(k);
            b.bounds = std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), 2.0)});
            b.transform.setPosition(Vec2(40.0 * k, 20.0 * k));
            b.velocity = Vec2(3000.0, 2000.0 - 200.0 * k);
            b.flags = kPhysics | kCollisions | kFast;
            scene.objects.push_back(b);
        }
        World world = buildWorld(scene);
        EXPECT_EQ(allocationsOfAReplayedStretch(world, 20, 40), 0u) << broadPhaseName(method);
        EXPECT_GT(world.totalStats()[kEffectCcd].pairs, 0u);
        EXPECT_GT(world.totalStats()[kEffectContainers].pairs, 0u);
    }
}

// The same at any worker count, through every parallel path (parallelMin 1): the hit list the
// workers claim positions in and their queues keep their capacity too, and the pool allocates
// nothing per task.
TEST(Allocation, ASteadyStepAllocatesNothingOnWorkers) {
    for (std::uint32_t workers : {2u, 3u, 4u, 16u}) {
        GeneratedScene scene = makeMixedScene(8, 300, BroadPhase::Grid);
        scene.def.effects |= kEffectCcd;
        scene.def.workers = workers;
        scene.def.parallelMin = 1;
        World world = buildWorld(scene);
        EXPECT_EQ(world.workerCount(), workers);
        EXPECT_EQ(allocationsOfAReplayedStretch(world, 20, 40), 0u) << workers << " workers";
        EXPECT_GT(world.totalStats()[kEffectContainers].pairs, 0u);
        EXPECT_GT(world.hits().size(), 0u);

        GeneratedScene field = makeRockField(3, 6000, 4.0, BroadPhase::Grid);
        field.def.workers = workers;
        World big = buildWorld(field);
        EXPECT_EQ(allocationsOfAReplayedStretch(big, 10, 20), 0u) << workers << " workers, default threshold";
    }
}

}  // namespace
}  // namespace polar
