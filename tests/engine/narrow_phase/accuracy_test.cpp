// Accuracy levels: names, the scene key "accuracy", and what each level means for a world.
#include "polar/accuracy.h"

#include <gtest/gtest.h>

#include "narrow_phase/pair_test.h"
#include "polar/scene_file.h"
#include "polar/world.h"

namespace polar {
namespace {

TEST(Accuracy, NamesRoundTrip) {
    for (Accuracy a : kAllAccuracies) EXPECT_EQ(accuracyFromName(accuracyName(a)), a);
    EXPECT_EQ(accuracyFromName("all-radii"), Accuracy::AllRadii);
    EXPECT_FALSE(accuracyFromName("Exact"));
    EXPECT_FALSE(accuracyFromName(""));
    EXPECT_EQ(accuracyNameList(), "\"bounds\", \"circle\", \"nearest\", \"chord\", \"all-radii\", \"exact\"");
}

Result<SceneDef> parse(const std::string& text) {
    return parseScene(SourceFile{"game/scene.json", text}, [](const std::string&) { return std::nullopt; });
}

TEST(Accuracy, SceneKeySelectsTheLevel) {
    Result<SceneDef> none = parse(R"({"format": 1, "objects": []})");
    ASSERT_TRUE(none.ok()) << none.error().message();
    EXPECT_EQ(none->world.accuracy, Accuracy::Bounds);  // default: each bounds file's interpolate flag
    for (Accuracy a : kAllAccuracies) {
        Result<SceneDef> r = parse(std::string(R"({"format": 1, "accuracy": ")") + accuracyName(a) + "\"}");
        ASSERT_TRUE(r.ok()) << r.error().message();
        EXPECT_EQ(r->world.accuracy, a);
        EXPECT_EQ(buildWorld(*r).def().accuracy, a);
    }
}

TEST(Accuracy, SceneKeyErrorsNameThePlace) {
    Result<SceneDef> r = parse("{\"format\": 1,\n  \"accuracy\": \"precise\"}");
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(
        r.error().message(),
        "game/scene.json:2:15: unknown accuracy level \"precise\"; expected one of \"bounds\", \"circle\", "
        "\"nearest\", \"chord\", \"all-radii\", \"exact\"");
    Result<SceneDef> number = parse("{\"format\": 1, \"accuracy\": 3}");
    ASSERT_FALSE(number.ok());
    EXPECT_EQ(number.error().line, 1);
    EXPECT_EQ(number.error().column, 27);
    EXPECT_NE(number.error().message().find("accuracy level name"), std::string::npos)
        << number.error().message();
}

// Two rods crossed like a plus sign, their centres off each other's axis: only the levels that look
// beyond the line of centres see the crossing. And a rod with a dumbbell: only all-radii sees its
// far radius.
TEST(Accuracy, LevelsDecideDifferentlyInAWorld) {
    auto rod = std::make_shared<const Bounds>(Bounds{
        Bound::fromDegrees(Vec2::Zero(), {{0.5, 100}, {179.5, 100}, {180.5, 100}, {359.5, 100}}, true)});
    auto world = [&](Accuracy level) {
        World w(WorldDef{kEffectCollisions, 0.8, level});
        ObjectDef a;
        a.name = "a";
        a.bounds = rod;
        a.flags = kCollisions;
        w.add(a);
        ObjectDef b = a;
        b.name = "b";
        b.transform = Transform(Vec2(60, 30), kHalfPi, Vec2(1, 1));
        w.add(b);
        return w;
    };
    EXPECT_TRUE(world(Accuracy::Bounds).detect(false).empty());
    EXPECT_TRUE(world(Accuracy::Chord).detect(false).empty());
    EXPECT_TRUE(world(Accuracy::AllRadii).detect(false).empty());
    EXPECT_EQ(world(Accuracy::Exact).detect(false).size(), 1u);
    EXPECT_EQ(world(Accuracy::Circle).detect(false).size(), 1u);  // circles of radius 100: a hit
    World stepped = world(Accuracy::Exact);
    stepped.step(1.0 / 60);
    ASSERT_EQ(stepped.hits().size(), 1u);
    EXPECT_EQ(stepped.collidedWith(stepped.objects()[0].id).size(), 1u);
}

TEST(Accuracy, AllRadiiTestsEveryPair) {
    // A has a small radii at its centre and a big one 50 to the right; B sits near the big one but
    // closer to A's position than to the big radii's centre... the seed picks the closest pair only.
    auto a = std::make_shared<const Bounds>(Bounds{Bound(Vec2(0, 0), 5.0), Bound(Vec2(50, 0), 30.0)});
    auto b = std::make_shared<const Bounds>(Bounds{Bound(Vec2(0, 0), 5.0)});
    for (Accuracy level : {Accuracy::Bounds, Accuracy::AllRadii}) {
        World w(WorldDef{kEffectCollisions, 0.8, level});
        ObjectDef oa;
        oa.name = "a";
        oa.bounds = a;
        oa.flags = kCollisions;
        w.add(oa);
        ObjectDef ob = oa;
        ob.name = "b";
        ob.bounds = b;
        ob.transform = Transform(Vec2(24, 12), 0, Vec2(1, 1));  // 26.8 from A, 28.8 from the big centre
        w.add(ob);
        std::vector<PairReport> hits = w.detect(false);
        if (level == Accuracy::Bounds) {
            EXPECT_TRUE(hits.empty());  // A's small radii is the closest to B: 5 + 5 < 26.8
        } else {
            ASSERT_EQ(hits.size(), 1u);
            EXPECT_EQ(hits[0].test.radiiA, 1u);  // the big radii decided: 30 + 5 ≥ 28.8
        }
    }
}

TEST(Accuracy, ContainerMeaningsAtEveryLevel) {
    // A square room (half-width 100) holds a ball of radius 5. At x = 90 the ball's side is 5 short
    // of the wall; toward the corner the room is deeper than its inscribed circle.
    Bounds room{Bound::fromDegrees(Vec2::Zero(),
                                   {{45, 100 * std::sqrt(2.0)},
                                    {135, 100 * std::sqrt(2.0)},
                                    {225, 100 * std::sqrt(2.0)},
                                    {315, 100 * std::sqrt(2.0)}},
                                   true)};
    Bounds ball{Bound(Vec2::Zero(), 5.0)};
    ObjectPose box(Vec2::Zero(), Mat2::Identity(), &room, kCollisions | kContainer);
    auto at = [&](Vec2 p) { return ObjectPose(p, Mat2::Identity(), &ball, kCollisions); };
    for (Accuracy level : kAllAccuracies) {
        EXPECT_FALSE(testPair(box, at(Vec2(90, 0)), level).hit) << accuracyName(level);
        // Read by nearest, the room is a star of arcs of radius 141 (its corners' radius): roomier.
        EXPECT_EQ(testPair(box, at(Vec2(96, 0)), level).hit, level != Accuracy::Nearest)
            << accuracyName(level);
    }
    // Deep in the corner (x = y = 92): inside the square, outside its inscribed circle of radius 100.
    EXPECT_TRUE(testPair(box, at(Vec2(92, 92)), Accuracy::Circle).hit);
    EXPECT_FALSE(testPair(box, at(Vec2(92, 92)), Accuracy::Exact).hit);
    // A rod 210 long at (0, 50) pokes through both side walls; along its line of centres (up) the
    // rule sees 50 + 1 < 100. Only exact sees it leave.
    Bounds square{Bound::fromDegrees(
        Vec2::Zero(),
        {{45, std::sqrt(2.0)}, {135, std::sqrt(2.0)}, {225, std::sqrt(2.0)}, {315, std::sqrt(2.0)}}, true)};
    ObjectPose rod(Vec2(0, 50), Vec2(105, 1).asDiagonal().toDenseMatrix(), &square, kCollisions);
    EXPECT_FALSE(testPair(box, rod, Accuracy::Bounds).hit);
    EXPECT_FALSE(testPair(box, rod, Accuracy::AllRadii).hit);
    EXPECT_TRUE(testPair(box, rod, Accuracy::Exact).hit);
    EXPECT_TRUE(testPair(rod, box, Accuracy::Exact).hit);  // either order
    ObjectPose shorter(Vec2(0, 50), Vec2(99, 1).asDiagonal().toDenseMatrix(), &square, kCollisions);
    EXPECT_FALSE(testPair(box, shorter, Accuracy::Exact).hit);
}

}  // namespace
}  // namespace polar
