// The public API as a second game uses it: polar/polar.h alone, programs written against the older
// names still compiling and agreeing with the newer helpers, and what each helper promises.
#include "polar/polar.h"

#include <gtest/gtest.h>

// The older names come from the headers that define the newer ones (polar/collision_radii.h and
// polar/radii_outline.h are gone; engine/README.md says what replaces them).
#include "polar/bound.h"
#include "polar/bound_outline.h"
#include "polar/bounds_file.h"

#include <cmath>
#include <filesystem>
#include <memory>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace polar {
namespace {

constexpr double kDt = 1.0 / 60.0;

// A small game written as programs were before makeBounds, boundsOrEmpty and unnamed objects: every
// flag and every effect by name, bounds built by hand, objects found by id and walked as a list.
struct OldStyleGame {
    World world{
        WorldDef{kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers | kEffectCcd}};
    ObjectId arena = 0, left = 0, right = 0, bullet = 0;

    OldStyleGame() {
        ObjectDef def;
        def.name = "arena";
        def.bounds = std::make_shared<const std::vector<CollisionRadii>>(
            std::vector<CollisionRadii>{CollisionRadii(Vec2::Zero(), 200.0)});
        def.flags = kCollisions | kContainer | kGhost;
        arena = world.add(def);

        std::shared_ptr<const Bounds> rock = std::make_shared<const Bounds>(Bounds{
            CollisionRadii::fromDegrees(Vec2::Zero(), {{0, 12}, {90, 10}, {180, 12}, {270, 10}}, true)});
        def = ObjectDef{};
        def.name = "left";
        def.bounds = rock;
        def.transform = Transform(Vec2(-40.0, 0.0), 0.0, Vec2(1.0, 1.0));
        def.velocity = Vec2(90.0, 0.0);
        def.flags = kPhysics | kCollisions;
        left = world.add(def);
        def.name = "right";
        def.transform.setPosition(Vec2(40.0, 3.0));
        def.velocity = Vec2(-90.0, 0.0);
        right = world.add(def);

        def = ObjectDef{};
        def.name = "bullet";
        def.bounds = std::make_shared<Bounds>(Bounds{CollisionRadii(Vec2::Zero(), 1.0)});
        def.transform.translate(0.0, -150.0);
        def.velocity = Vec2(0.0, 3000.0);
        def.flags = kPhysics | kCollisions | kFast | kIgnoreContainers;
        bullet = world.add(def);
    }
};

// The same game through the helpers, the bullet unnamed.
World newStyleWorld() {
    WorldDef def;
    def.effects = effectsFor(kPhysics | kCollisions | kContainer | kFast) | kEffectResponse;
    World world(def);
    ObjectDef arena;
    arena.name = "arena";
    arena.bounds = circleBounds(200.0);
    arena.flags = kCollisions | kContainer | kGhost;
    world.add(arena);

    ObjectDef rock;
    rock.bounds =
        makeBounds(Bound::fromDegrees(Vec2::Zero(), {{0, 12}, {90, 10}, {180, 12}, {270, 10}}, true));
    rock.name = "left";
    rock.transform.setPosition(Vec2(-40.0, 0.0));
    rock.velocity = Vec2(90.0, 0.0);
    rock.flags = kPhysics | kCollisions;
    world.add(rock);
    rock.name = "right";
    rock.transform.setPosition(Vec2(40.0, 3.0));
    rock.velocity = Vec2(-90.0, 0.0);
    world.add(rock);

    ObjectDef bullet;
    bullet.bounds = circleBounds(1.0);
    bullet.transform.setPosition(Vec2(0.0, -150.0));
    bullet.velocity = Vec2(0.0, 3000.0);
    bullet.flags = kPhysics | kCollisions | kFast | kIgnoreContainers;
    world.add(bullet);
    return world;
}

TEST(Api, AProgramAgainstTheOlderNamesStillRunsAndHits) {
    OldStyleGame game;
    World& world = game.world;
    bool rocksMet = false;
    for (int s = 0; s < 60; ++s) {
        world.step(kDt);
        std::span<const ObjectId> touched = world.collidedWith(game.left);
        for (ObjectId other : touched) rocksMet = rocksMet || other == game.right;
    }
    EXPECT_TRUE(rocksMet);
    const GameObject* left = world.find(game.left);
    ASSERT_NE(left, nullptr);
    EXPECT_EQ(left->boundsOrEmpty().size(), 1u);
    EXPECT_LT(left->velocity.x(), 0.0) << "the rocks bounced";
    std::size_t count = 0;
    for (GameObject& object : world.objects()) count += object.has(kCollisions);
    EXPECT_EQ(count, world.objects().size());
    EXPECT_EQ(world.objects()[0].id, game.arena);

    OldStyleGame again;
    for (int s = 0; s < 60; ++s) again.world.step(kDt);
    EXPECT_EQ(again.world.hash(), world.hash());
}

TEST(Api, TheHelpersBuildTheSameWorldAsTheOlderNames) {
    static_assert(std::is_same_v<CollisionRadii, Bound>, "the seed's name for a bound stays an alias");
    OldStyleGame game;
    World helpers = newStyleWorld();
    EXPECT_EQ(helpers.def().effects, game.world.def().effects);
    EXPECT_EQ(helpers.hash(), game.world.hash());
    for (int s = 0; s < 90; ++s) {
        game.world.step(kDt);
        helpers.step(kDt);
        ASSERT_EQ(helpers.hits().size(), game.world.hits().size()) << "step " << s;
        ASSERT_EQ(helpers.hash(), game.world.hash()) << "step " << s;
    }
    EXPECT_GT(game.world.totalStats().hits, 0u);
    EXPECT_GT(game.world.totalStats()[kEffectCcd].objects, 0u);
}

TEST(Api, TheOlderBoundNamesGiveWhatTheNewOnesGive) {
    static_assert(std::is_same_v<RadiiSpec, BoundSpec>, "a bounds file's older name for one bound's spec");
    RadiiSpec old{Vec2(1, -2), false, {{0, 12}, {100, 8}, {200, 14}, {300, 9}}};
    BoundsSpec spec;
    spec.radii = {old, BoundSpec{Vec2(3, 1), true, {{45, 6}, {180, 7}, {270, 5}}}};
    const Bounds bounds = buildBounds(spec);
    ASSERT_EQ(bounds.size(), 2u);
    // A stretch, a turn and a shift, so the outline's chords and the sample points depend on the map.
    const Mat3 m = Transform(Vec2(40, -7), 0.6, Vec2(3.0, 1.5)).matrix();
    for (const Bound& bound : bounds) {
        const std::vector<Vec2> outline = boundOutline(bound, m);
        ASSERT_FALSE(outline.empty());
        EXPECT_EQ(radiiOutline(bound, m), outline);
        // The tolerance goes through: a finer one gives the new name's finer outline, not the default.
        const std::vector<Vec2> fine = boundOutline(bound, m, 0.01);
        EXPECT_EQ(radiiOutline(bound, m, 0.01), fine);
        const std::vector<Vec2> points = boundSamplePoints(bound, m);
        EXPECT_EQ(points.size(), bound.samples().size());
        EXPECT_EQ(radiiSamplePoints(bound, m), points);
    }
    EXPECT_NE(boundOutline(bounds[0], m, 0.01).size(), boundOutline(bounds[0], m).size());
}

TEST(Api, MakeBoundsSharesOneListInOrder) {
    BoundsPtr two = makeBounds({Bound(Vec2(-5, 0), 3.0), Bound(Vec2(5, 0), 4.0)});
    ASSERT_EQ(two->size(), 2u);
    EXPECT_EQ((*two)[0].centre(), Vec2(-5, 0));
    EXPECT_EQ((*two)[1].maxRadius(), 4.0);
    BoundsPtr one = makeBounds(Bound(Vec2(1, 2), 7.0));
    ASSERT_EQ(one->size(), 1u);
    EXPECT_EQ((*one)[0].maxRadius(), 7.0);
    BoundsPtr circle = circleBounds(2.5, Vec2(3, -1));
    ASSERT_EQ(circle->size(), 1u);
    EXPECT_EQ((*circle)[0].centre(), Vec2(3, -1));
    EXPECT_EQ((*circle)[0].radius(1.0), 2.5);
    EXPECT_EQ(circleBounds(1.0)->front().centre(), Vec2::Zero());

    ObjectDef a, b;
    a.bounds = b.bounds = two;
    World world;
    a.name = "a";
    b.name = "b";
    ObjectId first = world.add(a), second = world.add(b);
    EXPECT_EQ(&world.find(first)->boundsOrEmpty(), &world.find(second)->boundsOrEmpty())
        << "one list, shared";
}

TEST(Api, BoundsOrEmptyIsEmptyWithoutBounds) {
    GameObject object;
    EXPECT_TRUE(object.boundsOrEmpty().empty());
    EXPECT_TRUE(object.boundsOrEmpty().empty());
    object.bounds = circleBounds(4.0);
    EXPECT_EQ(object.boundsOrEmpty().size(), 1u);
    EXPECT_EQ(&object.boundsOrEmpty(), object.bounds.get());
}

TEST(Api, EffectsForNamesWhatEachFlagNeeds) {
    static_assert(effectsFor(0) == 0);
    EXPECT_EQ(effectsFor(kPhysics), Effects{kEffectPhysics});
    EXPECT_EQ(effectsFor(kCollisions), Effects{kEffectCollisions});
    EXPECT_EQ(effectsFor(kContainer), Effects{kEffectContainers | kEffectCollisions});
    EXPECT_EQ(effectsFor(kFast), Effects{kEffectCcd | kEffectPhysics | kEffectCollisions});
    EXPECT_EQ(effectsFor(kGhost | kIgnoreContainers), Effects{0});

    EXPECT_EQ(inertFlags(kPhysics | kCollisions, kEffectPhysics), ObjectFlags{kCollisions});
    EXPECT_EQ(inertFlags(kContainer, kEffectContainers), ObjectFlags{kContainer})
        << "containers need collisions";
    EXPECT_EQ(inertFlags(kFast | kPhysics, kEffectCcd | kEffectPhysics), ObjectFlags{kFast});
    EXPECT_EQ(inertFlags(kGhost | kIgnoreContainers, 0), ObjectFlags{0});
    // effectsFor is exactly enough: with it nothing is inert, and without any one of its effects
    // something is.
    for (ObjectFlags flags = 0; flags < (1u << std::size(kAllFlags)); ++flags) {
        Effects needed = effectsFor(flags);
        EXPECT_EQ(inertFlags(flags, needed), 0u) << flags;
        for (Effect e : kAllEffects) {
            if (!(needed & e)) continue;
            EXPECT_NE(inertFlags(flags, needed & ~e), 0u) << flags << " without " << effectName(e);
        }
    }
}

TEST(Api, InertFlagsReallyDoNothing) {
    // A container in a world without the containers effect holds nothing: its rock flies out.
    for (bool containers : {false, true}) {
        WorldDef def;
        def.effects = kEffectPhysics | kEffectCollisions | kEffectResponse |
                      (containers ? Effects{kEffectContainers} : Effects{0});
        World world(def);
        ObjectDef wall;
        wall.name = "wall";
        wall.bounds = circleBounds(50.0);
        wall.flags = kCollisions | kContainer | kGhost;
        world.add(wall);
        ObjectDef rock;
        rock.name = "rock";
        rock.bounds = circleBounds(5.0);
        rock.velocity = Vec2(100.0, 0.0);
        rock.flags = kPhysics | kCollisions;
        ObjectId id = world.add(rock);
        EXPECT_EQ(inertFlags(wall.flags, def.effects) != 0, !containers);
        for (int s = 0; s < 120; ++s) world.step(kDt);
        EXPECT_EQ(world.find(id)->transform.position().norm() < 50.0, containers);
    }
}

TEST(Api, UnnamedObjectsNeedNoNames) {
    World world(WorldDef{kEffectPhysics | kEffectCollisions});
    ObjectDef named;
    named.name = "ship";
    named.bounds = circleBounds(5.0);
    named.flags = kCollisions;
    ObjectId ship = world.add(named);
    std::vector<ObjectId> bullets;
    for (int i = 0; i < 20; ++i) {
        ObjectDef bullet;
        bullet.bounds = circleBounds(1.0);
        bullet.transform.setPosition(Vec2(-10.0 + i, 0.0));
        bullet.flags = kPhysics | kCollisions;
        bullets.push_back(world.add(bullet));
    }
    EXPECT_EQ(world.objects().size(), 21u);
    EXPECT_FALSE(world.nameTaken(""));
    EXPECT_EQ(world.findByName(""), nullptr);
    EXPECT_EQ(world.findByName("ship")->id, ship);
    const World& constWorld = world;
    EXPECT_EQ(constWorld.findByName("ship")->id, ship);
    EXPECT_EQ(constWorld.findByName("boat"), nullptr);
    for (std::size_t i = 0; i < bullets.size(); i += 2) EXPECT_TRUE(world.remove(bullets[i]));
    EXPECT_EQ(world.findByName("ship")->id, ship);
    world.step(kDt);
    // The ship (radius 5 at the origin) touches the bullets within 6 of it that are left.
    std::size_t expected = 0;
    for (std::size_t i = 1; i < bullets.size(); i += 2) expected += std::abs(-10.0 + double(i)) <= 6.0;
    EXPECT_EQ(world.collidedWith(ship).size(), expected);
    named.name = "";
    ObjectId another = world.add(named);
    EXPECT_NE(another, ship);
    EXPECT_EQ(world.findByName("ship")->id, ship);
}

TEST(Api, ObjectsAreASpanEditableInPlace) {
    static_assert(std::is_same_v<decltype(std::declval<World&>().objects()), std::span<GameObject>>);
    static_assert(
        std::is_same_v<decltype(std::declval<const World&>().objects()), std::span<const GameObject>>);
    World world(WorldDef{kEffectPhysics});
    ObjectDef def;
    def.name = "mover";
    def.flags = kPhysics;
    world.add(def);
    for (GameObject& object : world.objects()) object.velocity = Vec2(60.0, 0.0);
    world.step(kDt);
    EXPECT_DOUBLE_EQ(world.objects()[0].transform.position().x(), 1.0);
}

TEST(Api, PolarHeaderNamesTheWholeEngine) {
    // One call from each header polar.h gathers: these must compile through it alone.
    EXPECT_STREQ(accuracyName(Accuracy::Exact), "exact");
    EXPECT_STREQ(broadPhaseName(BroadPhase::Grid), "grid");
    EXPECT_STREQ(effectName(kEffectCcd), "ccd");
    EXPECT_STREQ(flagName(kIgnoreContainers), "ignore_containers");
    EXPECT_EQ(degToRad(180.0), kPi);
    Error error{"a.json", 1, 2, "bad", "good"};
    EXPECT_EQ(error.message(), "a.json:1:2: bad; expected good");
    StateHash hash;
    hash.add(1.0);
    EXPECT_NE(hash.value(), StateHash{}.value());
    GameObject object;
    EXPECT_NE(objectHash(object), 0u);
    EXPECT_FALSE(formatStepStats(StepStats{}, 1).empty());
    BoundsSpec spec;
    spec.radii.push_back(BoundSpec{Vec2::Zero(), false, {{0.0, 3.0}}});
    EXPECT_EQ(buildBounds(spec).size(), 1u);
    EXPECT_FALSE(boundsToJson(BoundsSpec{}).empty());
    EXPECT_GE(boundOutline(Bound(Vec2::Zero(), 1.0), Mat3::Identity()).size(), 8u);
    Result<SceneDef> scene =
        parseScene(SourceFile{"s.json", R"({"format": 1, "objects": []})"}, diskReader());
    ASSERT_TRUE(scene.ok()) << scene.error().message();
    EXPECT_TRUE(buildWorld(*scene).objects().empty());
    EXPECT_TRUE(JsonDoc::parse(SourceFile{"x.json", "{}"}).ok());
    object.bounds = circleBounds(1.0);
    GameObject other = object;
    EXPECT_TRUE(testObjects(object, other).hit);
    std::string path = ::testing::TempDir() + "polar_api_test.txt";
    ASSERT_FALSE(writeFileAtomically(path, "hello"));
    EXPECT_EQ(std::filesystem::file_size(path), 5u);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace polar
