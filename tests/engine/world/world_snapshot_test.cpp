// restoreSnapshot(saveSnapshot(world)) is the world: the same hash at once, and stepped on, the same
// bits as the world that was never saved (hashes, hits, collidedWith), at 1 and 2 workers, on random
// scenes with objects coming and going between steps. A buffer cut off or damaged is refused and
// leaves the world as it was.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "polar/authoring/random_scene.h"
#include "polar/world.h"
#include "polar/world_snapshot.h"

namespace polar {
namespace {

constexpr double kDt = 1.0 / 60.0;

// Everything a step leaves that a game may read: the hash, every hit's bits, every object's
// collidedWith list, the step count and the counters of the last step.
std::vector<std::uint64_t> observed(const World& world) {
    std::vector<std::uint64_t> bits{world.hash(), world.stepCount(), world.lastStepStats().hits,
                                    world.lastStepStats().pairsTested, world.totalStats().pairsTested};
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
    for (const GameObject& o : world.objects()) {
        bits.push_back(0xC0FFEE);
        for (ObjectId id : world.collidedWith(o.id)) bits.push_back(id);
        bits.push_back(std::hash<std::string>{}(o.name) ^ o.userData);
        bits.push_back(reinterpret_cast<std::uintptr_t>(o.bounds.get()));
    }
    return bits;
}

// Between steps, as a game does: now and then an object leaves and a named one arrives.
void churn(World& world, SceneRandom& random, int step) {
    if (world.objects().empty() || !random.chance(0.3)) return;
    const GameObject& victim =
        world.objects()[random.below(static_cast<std::uint32_t>(world.objects().size()))];
    ObjectDef def;
    def.name = "new" + std::to_string(step);
    def.userData = victim.userData;
    def.bounds = victim.bounds;
    def.flags = victim.flags;
    def.transform = victim.transform;
    def.velocity = Vec2(random.uniform(-50, 50), random.uniform(-50, 50));
    world.remove(victim.id);
    world.add(def);
}

// Runs `scene` for `steps`, saving at `saveAt`, and returns what each step after it left.
struct Run {
    std::vector<std::vector<std::uint64_t>> after;  // per step after the save
    WorldSnapshot snapshot;
    std::vector<std::uint64_t> atSave;
};

Run straight(const GeneratedScene& scene, int saveAt, int steps, std::uint64_t seed) {
    World world = buildWorld(scene);
    SceneRandom random(seed);
    Run run;
    for (int s = 0; s < steps; ++s) {
        if (s == saveAt) {
            saveSnapshot(world, run.snapshot);
            run.atSave = observed(world);
        }
        world.step(kDt);
        churn(world, random, s);
        if (s >= saveAt) run.after.push_back(observed(world));
    }
    return run;
}

void checkResumes(GeneratedScene scene, std::uint32_t workers, std::uint64_t seed) {
    scene.def.workers = workers;
    scene.def.parallelMin = 1;
    SceneRandom pick(seed);
    constexpr int kSteps = 40;
    int saveAt = static_cast<int>(pick.below(kSteps - 5));
    Run run = straight(scene, saveAt, kSteps, seed);

    // Into the same kind of world that went elsewhere first, and into an empty default world.
    World elsewhere = buildWorld(scene);
    for (int s = 0; s < 7; ++s) elsewhere.step(kDt);
    World empty(WorldDef{.workers = workers, .parallelMin = 1});
    for (World* target : {&elsewhere, &empty}) {
        std::optional<Error> error = restoreSnapshot(*target, run.snapshot);
        ASSERT_FALSE(error) << error->message();
        ASSERT_EQ(observed(*target), run.atSave) << "seed " << seed << " at step " << saveAt;
        EXPECT_EQ(target->def().effects, scene.def.effects);
        SceneRandom random(seed);
        // The churn's draws before the save, replayed so the same objects come and go after it.
        World replay = buildWorld(scene);
        for (int s = 0; s < saveAt; ++s) {
            replay.step(kDt);
            churn(replay, random, s);
        }
        for (int s = saveAt; s < kSteps; ++s) {
            target->step(kDt);
            churn(*target, random, s);
            ASSERT_EQ(observed(*target), run.after[static_cast<std::size_t>(s - saveAt)])
                << "seed " << seed << ", " << workers << " workers, saved at " << saveAt << ", step " << s;
        }
    }
}

TEST(WorldSnapshot, ARestoredMixedSceneStepsAsTheOriginal) {
    for (std::uint64_t seed = 1; seed <= 12; ++seed)
        for (std::uint32_t workers : {1u, 2u})
            checkResumes(makeMixedScene(seed, 150 + 20 * seed, BroadPhase::Grid), workers, seed);
}

TEST(WorldSnapshot, ARestoredRockFieldStepsAsTheOriginal) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed)
        for (std::uint32_t workers : {1u, 2u})
            for (BroadPhase method : kAllBroadPhases)
                checkResumes(makeRockField(seed, 250, 3.0, method), workers, seed);
}

TEST(WorldSnapshot, ASaveIntoAWarmSnapshotIsTheSameAsIntoAFreshOne) {
    World world = buildWorld(makeMixedScene(3, 300, BroadPhase::Grid));
    WorldSnapshot warm;
    saveSnapshot(World(), warm);  // other contents first
    for (int s = 0; s < 5; ++s) world.step(kDt);
    saveSnapshot(world, warm);
    WorldSnapshot fresh;
    saveSnapshot(world, fresh);
    EXPECT_EQ(warm.bytes, fresh.bytes);
    EXPECT_EQ(warm.bounds, fresh.bounds);
    EXPECT_GT(warm.bounds.size(), 1u);
    EXPECT_LT(warm.bounds.size(), world.objects().size());  // shared bounds are listed once
}

// The game's user data rides along: copied by a snapshot, never hashed, never read by a step.
TEST(WorldSnapshot, UserDataIsKeptButNotHashed) {
    World world = buildWorld(makeMixedScene(3, 40, BroadPhase::Grid));
    World marked = world;
    for (GameObject& o : marked.objects()) o.userData = 0x9E3779B97F4A7C15ull * (o.id + 1);
    EXPECT_EQ(marked.hash(), world.hash());
    for (int s = 0; s < 10; ++s) {
        world.step(kDt);
        marked.step(kDt);
    }
    EXPECT_EQ(marked.hash(), world.hash()) << "a step never reads userData";
    WorldSnapshot snapshot;
    saveSnapshot(marked, snapshot);
    World restored;
    ASSERT_FALSE(restoreSnapshot(restored, snapshot));
    ASSERT_EQ(restored.objects().size(), marked.objects().size());
    for (std::size_t i = 0; i < marked.objects().size(); ++i)
        EXPECT_EQ(restored.objects()[i].userData, marked.objects()[i].userData) << "object " << i;
}

// Damage: every cut, and one flipped bit at each of many places, is an error, and the world
// restored into keeps its state.
TEST(WorldSnapshot, ACutOrDamagedBufferIsRefusedAndChangesNothing) {
    World world = buildWorld(makeMixedScene(5, 40, BroadPhase::Grid));
    for (int s = 0; s < 10; ++s) world.step(kDt);
    WorldSnapshot good;
    saveSnapshot(world, good);

    World target = buildWorld(makeMixedScene(6, 30, BroadPhase::Grid));
    target.step(kDt);
    const std::vector<std::uint64_t> before = observed(target);
    for (std::size_t cut = 0; cut < good.bytes.size(); ++cut) {
        WorldSnapshot bad = good;
        bad.bytes.resize(cut);
        bad.bytes.shrink_to_fit();  // so a read past the end is a read past the allocation (ASan)
        std::optional<Error> error = restoreSnapshot(target, bad);
        ASSERT_TRUE(error) << "cut to " << cut << " bytes";
        EXPECT_FALSE(error->what.empty());
    }
    for (std::size_t at = 0; at < good.bytes.size(); at += 7) {
        WorldSnapshot bad = good;
        bad.bytes[at] ^= static_cast<std::uint8_t>(1u << (at % 8));
        ASSERT_TRUE(restoreSnapshot(target, bad)) << "bit flipped at byte " << at;
    }
    WorldSnapshot shortTable = good;
    shortTable.bounds.pop_back();
    EXPECT_TRUE(restoreSnapshot(target, shortTable));
    WorldSnapshot longer = good;
    longer.bytes.push_back(0);
    EXPECT_TRUE(restoreSnapshot(target, longer));
    EXPECT_EQ(observed(target), before);

    ASSERT_FALSE(restoreSnapshot(target, good));
    EXPECT_EQ(target.hash(), world.hash());
}

TEST(WorldSnapshot, ErrorsSayWhatIsWrong) {
    WorldSnapshot snapshot;
    saveSnapshot(World(), snapshot);
    World world;
    snapshot.bytes[4] = 99;  // the version
    std::optional<Error> error = restoreSnapshot(world, snapshot);
    ASSERT_TRUE(error);
    EXPECT_EQ(error->message().rfind("world snapshot", 0), 0u) << error->message();
    EXPECT_NE(error->message().find("version 99"), std::string::npos) << error->message();
}

}  // namespace
}  // namespace polar
