// Effects: a scene runs only the systems it lists; an absent effect costs nothing.
#include "polar/effects.h"

#include <gtest/gtest.h>

#include <cstring>

#include "bits.h"
#include "polar/authoring/random_scene.h"
#include "polar/scene_file.h"
#include "polar/world.h"

namespace polar {
namespace {

constexpr double kDt = 1.0 / 60.0;

TEST(Effects, NamesRoundTripAndIndexTheirTable) {
    for (std::size_t i = 0; i < kEffectCount; ++i) {
        Effect e = kAllEffects[i];
        EXPECT_EQ(effectFromName(effectName(e)), e);
        EXPECT_EQ(effectIndex(e), i);
    }
    EXPECT_FALSE(effectFromName("gravity"));
    EXPECT_EQ(flagFromName("fast"), kFast);
}

// The mixed scene with every flag in use plus fast bullets, under a chosen set of effects.
World richWorld(Effects effects) {
    GeneratedScene scene = makeMixedScene(21, 300, BroadPhase::Grid);
    scene.def.effects = effects;
    for (int k = 0; k < 10; ++k) {
        ObjectDef b;
        b.name = "bullet-" + std::to_string(k);
        b.bounds = std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), 2.0)});
        b.transform.setPosition(Vec2(30.0 * k, 50.0));
        b.velocity = Vec2(5000.0, 300.0 * k);
        b.flags = kPhysics | kCollisions | kFast;
        scene.objects.push_back(b);
    }
    return buildWorld(scene);
}

TEST(Effects, StaticSpritesWithoutEffectsCostNothing) {
    World world;  // no effects
    for (int i = 0; i < 1000; ++i) {
        ObjectDef sprite;
        sprite.name = "sprite-" + std::to_string(i);
        sprite.bounds = std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), 10.0)});
        sprite.transform.setPosition(Vec2(i % 40, i / 40));
        world.add(sprite);
    }
    for (int s = 0; s < 5; ++s) world.step(kDt);
    for (Effect e : kAllEffects) EXPECT_TRUE(world.totalStats()[e].idle()) << effectName(e);
    EXPECT_EQ(world.totalStats().candidates, 0u);
    EXPECT_TRUE(world.hits().empty());
}

TEST(Effects, EveryAbsentEffectMakesNoPassAndHoldsNoMemory) {
    Effects all = 0;
    for (Effect e : kAllEffects) all |= e;
    for (Effect absent : kAllEffects) {
        World world = richWorld(all & ~absent);
        world.setTiming(true);
        for (int s = 0; s < 5; ++s) world.step(kDt);
        const StepStats& total = world.totalStats();
        EXPECT_TRUE(total[absent].idle())
            << effectName(absent) << ": calls " << total[absent].calls << ", objects "
            << total[absent].objects << ", pairs " << total[absent].pairs << ", bytes " << total[absent].bytes
            << ", ns " << total[absent].nanoseconds;
        // The effects that do run, and have something to work on, do work.
        for (Effect present : kAllEffects) {
            if (present == absent) continue;
            bool canRun = present == kEffectPhysics || absent != kEffectCollisions;
            if (!canRun) continue;
            EXPECT_GT(total[present].calls, 0u) << effectName(present) << " without " << effectName(absent);
        }
    }
}

TEST(Effects, EveryEffectRunningCountsItsWork) {
    Effects all = 0;
    for (Effect e : kAllEffects) all |= e;
    World world = richWorld(all);
    world.setTiming(true);
    world.step(kDt);
    const StepStats& stats = world.lastStepStats();
    EXPECT_EQ(stats[kEffectPhysics].calls, 1u);
    EXPECT_GT(stats[kEffectPhysics].nanoseconds, 0u);
    EXPECT_GT(stats[kEffectCollisions].pairs, 0u);
    EXPECT_GT(stats[kEffectCollisions].bytes, 0u);
    EXPECT_GT(stats[kEffectContainers].pairs, 0u);
    EXPECT_EQ(stats[kEffectResponse].pairs, world.hits().size());
    EXPECT_EQ(stats.hits, world.hits().size());
    EXPECT_GT(stats[kEffectCcd].objects, 0u);
    EXPECT_EQ(stats.pairsTested,
              stats[kEffectCollisions].pairs + stats[kEffectContainers].pairs + stats[kEffectCcd].pairs);
}

TEST(Effects, TimingNeverChangesResults) {
    Effects all = kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers | kEffectCcd;
    World timed = richWorld(all), untimed = richWorld(all);
    timed.setTiming(true);
    for (int s = 0; s < 20; ++s) {
        timed.step(kDt);
        untimed.step(kDt);
    }
    EXPECT_EQ(untimed.totalStats()[kEffectCollisions].nanoseconds, 0u);
    EXPECT_GT(timed.totalStats()[kEffectCollisions].nanoseconds, 0u);
    ASSERT_EQ(timed.hits().size(), untimed.hits().size());
    for (std::size_t i = 0; i < timed.objects().size(); ++i) {
        EXPECT_EQ(bits(timed.objects()[i].transform.position().x()),
                  bits(untimed.objects()[i].transform.position().x()));
        EXPECT_EQ(bits(timed.objects()[i].velocity.y()), bits(untimed.objects()[i].velocity.y()));
    }
}

TEST(Effects, ObjectsThatNeverMoveCostOnlyAsCandidates) {
    WorldDef def;
    def.effects = kEffectPhysics | kEffectCollisions | kEffectResponse;
    World world(def);
    BoundsPtr rock = std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), 5.0)});
    for (int i = 0; i < 2000; ++i) {
        ObjectDef o;
        o.name = "scenery-" + std::to_string(i);
        o.bounds = rock;
        o.transform.setPosition(Vec2(100.0 * (i % 50), 100.0 * (i / 50)));
        o.flags = i < 1000 ? ObjectFlags{0}
                           : ObjectFlags{kCollisions};  // half pure decoration, half static obstacles
        world.add(o);
    }
    for (int i = 0; i < 10; ++i) {
        ObjectDef o;
        o.name = "ship-" + std::to_string(i);
        o.bounds = rock;
        o.transform.setPosition(Vec2(-500.0, 30.0 * i));
        o.velocity = Vec2(60.0, 0.0);
        o.flags = kPhysics | kCollisions;
        world.add(o);
    }
    world.step(kDt);
    const StepStats& stats = world.lastStepStats();
    EXPECT_EQ(stats[kEffectPhysics].objects, 10u);  // only the movers are integrated
    EXPECT_EQ(stats.candidates, 1010u);             // decoration is not even a candidate
    EXPECT_EQ(stats[kEffectResponse].calls, 0u);    // nothing touched: no response pass
    EXPECT_EQ(stats[kEffectCollisions].pairs, 0u);  // and no pair worth a narrow-phase test

    // setFlags keeps the lists right: a piece of scenery starts moving.
    world.find(world.objects()[5].id)->velocity = Vec2(1.0, 0.0);
    ASSERT_TRUE(world.setFlags(world.objects()[5].id, kPhysics | kCollisions));
    world.step(kDt);
    EXPECT_EQ(world.lastStepStats()[kEffectPhysics].objects, 11u);
    EXPECT_EQ(world.lastStepStats().candidates, 1011u);
    EXPECT_NEAR(world.objects()[5].transform.position().x(), 500.0 + kDt, 1e-12);
    ASSERT_TRUE(world.remove(world.objects()[3].id));
    world.step(kDt);
    EXPECT_EQ(world.lastStepStats()[kEffectPhysics].objects, 11u);
    EXPECT_NEAR(world.objects()[4].transform.position().x(), 500.0 + 2 * kDt, 1e-12);
}

// Scene files: effect names, the broad_phase key and the flags that need effects.
Result<SceneDef> parse(const std::string& text) {
    return parseScene(SourceFile{"scene.json", text}, [](const std::string&) { return std::nullopt; });
}

TEST(Effects, SceneFilesNameEffectsAndBroadPhase) {
    Result<SceneDef> scene = parse(R"({"format": 1, "effects": ["physics", "collisions", "ccd"],
        "broad_phase": "all-pairs",
        "objects": [{"name": "bullet", "flags": ["physics", "collisions", "fast"]}]})");
    ASSERT_TRUE(scene) << scene.error().message();
    EXPECT_EQ(scene->world.effects, kEffectPhysics | kEffectCollisions | kEffectCcd);
    EXPECT_EQ(scene->world.broadPhase, BroadPhase::AllPairs);
    EXPECT_EQ(scene->objects[0].flags, kPhysics | kCollisions | kFast);
    EXPECT_EQ(parse(R"({"format": 1})")->world.broadPhase, BroadPhase::Grid);
}

TEST(Effects, SceneFileMistakesNameTheirPlace) {
    struct Case {
        const char* text;
        int line;
        int column;
        const char* what;
    };
    const Case cases[] = {
        {"{\"format\": 1,\n \"effects\": [\"physics\", \"gravity\"]}", 2, 25, "unknown effect \"gravity\""},
        {"{\"format\": 1,\n \"broad_phase\": \"quadtree\"}", 2, 17, "unknown broad phase \"quadtree\""},
        {"{\"format\": 1,\n \"effects\": [\"collisions\", \"ccd\"]}", 2, 28, "\"ccd\" casts"},
        {"{\"format\": 1, \"effects\": [\"physics\", \"collisions\"],\n \"objects\": [{\"name\": \"b\", "
         "\"flags\": "
         "[\"fast\"]}]}",
         2, 38, "flag \"fast\" needs the \"ccd\" effect"},
        {"{\"format\": 1, \"effects\": [\"collisions\"],\n \"objects\": [{\"name\": \"b\", \"flags\": "
         "[\"physics\"]}]}",
         2, 38, "flag \"physics\" needs the \"physics\" effect"},
        {"{\"format\": 1,\n \"effects\": [\"response\"]}", 2, 14,
         "\"response\" acts on what detection finds, but \"collisions\" is not listed"},
        {"{\"format\": 1,\n \"effects\": [\"physics\", \"containers\"]}", 2, 25,
         "\"containers\" acts on what detection finds, but \"collisions\" is not listed"},
        {"{\"format\": 1,\n \"effects\": [\"ccd\", \"collisions\"]}", 2, 14, "\"ccd\" casts"},
        {"{\"format\": 1,\n \"effects\": [\"ccd\", \"physics\"]}", 2, 14, "\"ccd\" casts"},
        {"{\"format\": 1, \"effects\": [\"physics\", \"collisions\"],\n \"objects\": [{\"name\": \"b\", "
         "\"flags\": [\"collisions\", \"container\"]}]}",
         2, 52, "flag \"container\" needs the \"containers\" effect"},
        {"{\"format\": 1, \"effects\": [\"physics\"],\n \"objects\": [{\"name\": \"b\", \"flags\": "
         "[\"physics\", \"collisions\"]}]}",
         2, 49, "flag \"collisions\" needs the \"collisions\" effect"},
    };
    for (const Case& c : cases) {
        Result<SceneDef> scene = parse(c.text);
        ASSERT_FALSE(scene) << c.text;
        EXPECT_EQ(scene.error().line, c.line) << scene.error().message();
        EXPECT_EQ(scene.error().column, c.column) << scene.error().message();
        EXPECT_NE(scene.error().what.find(c.what), std::string::npos) << scene.error().message();
        EXPECT_FALSE(scene.error().expected.empty());
    }
}

}  // namespace
}  // namespace polar

namespace polar {
namespace {

TEST(Effects, StatsTableNamesEveryEffectWithItsAverages) {
    StepStats total;
    total[kEffectPhysics].calls = 10;
    total[kEffectPhysics].objects = 5000;
    total[kEffectCollisions].nanoseconds = 30'000'000;
    total.hits = 70;
    std::string table = formatStepStats(total, 10);
    for (Effect e : kAllEffects) EXPECT_NE(table.find(effectName(e)), std::string::npos) << table;
    EXPECT_NE(table.find("500.0"), std::string::npos) << table;  // physics objects per step
    EXPECT_NE(table.find("3.000"), std::string::npos) << table;  // collisions ms per step
    EXPECT_NE(table.find("7.0 hits"), std::string::npos) << table;
}

}  // namespace
}  // namespace polar
