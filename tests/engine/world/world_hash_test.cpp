#include "polar/world_hash.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "polar/world.h"

namespace polar {
namespace {

constexpr Effects kEverything = kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers;

ObjectDef rock(const std::string& name, Vec2 position, Vec2 velocity, double spin) {
    ObjectDef d;
    d.name = name;
    d.transform = Transform(position, 0.25, Vec2(1, 1));
    d.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), 3.0)});
    d.velocity = velocity;
    d.spin = spin;
    d.damping = 0.1;
    d.flags = kPhysics | kCollisions;
    return d;
}

World twoRocks() {
    World w(WorldDef{kEverything, 0.8});
    w.add(rock("a", Vec2(0, 0), Vec2(2, 0), 0.5));
    w.add(rock("b", Vec2(10, 1), Vec2(-2, 0), -0.5));
    return w;
}

TEST(WorldHash, SameStateSameHashAndItFollowsTheSteps) {
    World a = twoRocks(), b = twoRocks();
    EXPECT_EQ(a.hash(), b.hash());
    std::uint64_t before = a.hash();
    for (int i = 0; i < 120; ++i) {
        a.step(1.0 / 60);
        b.step(1.0 / 60);
        ASSERT_EQ(a.hash(), b.hash()) << "step " << i;
    }
    EXPECT_NE(a.hash(), before);
}

// Every part of an object's state is covered, down to the last bit of each double.
TEST(WorldHash, EveryFieldChangesItToTheLastBit) {
    const std::uint64_t base = twoRocks().hash();
    const std::function<void(GameObject&)> changes[] = {
        [](GameObject& o) {
            o.transform.setPosition(o.transform.position() + Vec2(std::ldexp(1.0, -40), 0));
        },
        [](GameObject& o) {
            o.transform.setPosition(Vec2(o.transform.position().x(), std::nextafter(1.0, 2.0)));
        },
        [](GameObject& o) { o.transform.setRotation(std::nextafter(o.transform.rotation(), 1.0)); },
        [](GameObject& o) { o.transform.setScale(Vec2(1, std::nextafter(1.0, 2.0))); },
        [](GameObject& o) { o.velocity.x() = std::nextafter(o.velocity.x(), 0.0); },
        [](GameObject& o) { o.velocity.y() = -0.0; },  // a different bit pattern, though -0 == 0
        [](GameObject& o) { o.spin = std::nextafter(o.spin, 0.0); },
        [](GameObject& o) { o.damping = 0.2; },
        [](GameObject&) {},  // flags, below (through setFlags, which keeps the world's lists right)
    };
    for (std::size_t i = 0; i < std::size(changes); ++i) {
        World w = twoRocks();
        changes[i](w.objects()[1]);
        if (i + 1 == std::size(changes)) w.setFlags(w.objects()[1].id, w.objects()[1].flags | kGhost);
        EXPECT_NE(w.hash(), base) << "change " << i;
        EXPECT_NE(objectHash(w.objects()[1]), objectHash(twoRocks().objects()[1])) << "change " << i;
        EXPECT_EQ(objectHash(w.objects()[0]), objectHash(twoRocks().objects()[0]))
            << "the other object is untouched";
    }
}

TEST(WorldHash, CreationOrderAndRemovalsCount) {
    World ab(WorldDef{kEverything, 0.8}), ba(WorldDef{kEverything, 0.8});
    ab.add(rock("a", Vec2(0, 0), Vec2(2, 0), 0.5));
    ab.add(rock("b", Vec2(10, 1), Vec2(-2, 0), -0.5));
    ba.add(rock("b", Vec2(10, 1), Vec2(-2, 0), -0.5));
    ba.add(rock("a", Vec2(0, 0), Vec2(2, 0), 0.5));
    EXPECT_NE(ab.hash(), ba.hash()) << "objects are hashed in creation order with their ids";

    // Removing an object and adding it back gives it a new id: not the same world.
    World again = twoRocks();
    ObjectId b = again.objects()[1].id;
    again.remove(b);
    again.add(rock("b", Vec2(10, 1), Vec2(-2, 0), -0.5));
    EXPECT_NE(again.hash(), twoRocks().hash());
}

TEST(WorldHash, TheRulesAreCovered) {
    World bouncy(WorldDef{kEverything, 0.8}), dull(WorldDef{kEverything, 0.5});
    EXPECT_NE(bouncy.hash(), dull.hash());
    World still(WorldDef{kEffectCollisions, 0.8});
    EXPECT_NE(bouncy.hash(), still.hash());
    WorldDef exactDef{kEverything, 0.8};
    exactDef.accuracy = Accuracy::Exact;
    EXPECT_NE(World(exactDef).hash(), bouncy.hash()) << "the narrow phase's accuracy decides the future";
    WorldDef sweepDef{kEverything, 0.8};
    sweepDef.broadPhase = BroadPhase::SortAndSweep;
    EXPECT_EQ(World(sweepDef).hash(), bouncy.hash()) << "the broad phase only changes the speed";
}

// A fixed expected value: the hash is FNV-1a over a defined byte sequence (little-endian words),
// so it is the same on every compiler, build and run. (Whether stepping is deterministic is the
// golden replays' test.) If World::hash is changed on purpose, update this number.
TEST(WorldHash, IsAFixedFunctionOfTheState) {
    EXPECT_EQ(twoRocks().hash(), 0x3bd1716b818b09f4u) << std::hex << twoRocks().hash();
}

}  // namespace
}  // namespace polar
