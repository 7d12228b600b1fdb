#include "polar/world.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <random>

namespace polar {
namespace {

using testing::ElementsAre;
using testing::ElementsAreArray;

constexpr double kDt = 1.0 / 60.0;
constexpr Effects kEverything = kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers;

ObjectDef ball(const std::string& name, Vec2 position, double radius, ObjectFlags flags,
               Vec2 velocity = Vec2::Zero()) {
    ObjectDef d;
    d.name = name;
    d.transform = Transform(position, 0.0, Vec2(1, 1));
    d.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), radius)});
    d.flags = flags;
    d.velocity = velocity;
    return d;
}

World world(Effects effects, double restitution = 0.8) {
    return World(WorldDef{effects, restitution});
}

Vec2 pos(World& w, ObjectId id) {
    return w.find(id)->transform.position();
}

TEST(World, AddFindRemoveKeepCreationOrder) {
    World w = world(kEverything);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 1, kCollisions));
    ObjectId b = w.add(ball("b", Vec2(5, 0), 1, kCollisions));
    ObjectId c = w.add(ball("c", Vec2(9, 0), 1, kCollisions));
    EXPECT_LT(a, b);
    EXPECT_LT(b, c);
    EXPECT_EQ(w.find(b)->name, "b");
    EXPECT_EQ(w.findByName("c")->id, c);
    EXPECT_EQ(w.findByName("zz"), nullptr);
    EXPECT_TRUE(w.nameTaken("a"));
    EXPECT_TRUE(w.remove(b));
    EXPECT_FALSE(w.remove(b));
    EXPECT_EQ(w.find(b), nullptr);
    EXPECT_FALSE(w.nameTaken("b"));
    ObjectId d = w.add(ball("b", Vec2(1, 1), 1, kCollisions));  // the name is free again; the id is new
    EXPECT_GT(d, c);
    ASSERT_EQ(w.objects().size(), 3u);
    EXPECT_EQ(w.objects()[0].id, a);
    EXPECT_EQ(w.objects()[1].id, c);
    EXPECT_EQ(w.objects()[2].id, d);
    EXPECT_EQ(w.find(d)->transform.position(), Vec2(1, 1));
}

// The objects touched in a step are listed in hit order, not index order; removing one of them
// between steps must still leave every other object's list cleared by the next step (a stale index
// once cleared the wrong object, or memory past the end, and left a phantom collision behind).
// Between steps, removing and adding objects keeps every other object's list as the step left it.
TEST(World, CollidedListsSurviveRemovingAndAddingObjects) {
    World w = world(kEffectCollisions);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 2, kCollisions));
    ObjectId b = w.add(ball("b", Vec2(3, 0), 2, kCollisions));   // touches a
    ObjectId c = w.add(ball("c", Vec2(50, 0), 2, kCollisions));  // touches d
    ObjectId d = w.add(ball("d", Vec2(53, 0), 2, kCollisions));
    w.step(kDt);
    ASSERT_TRUE(w.remove(b));
    ObjectId e = w.add(ball("e", Vec2(-50, 0), 2, kCollisions));
    EXPECT_THAT(w.collidedWith(a), ElementsAre(b));  // the partner is gone but was touched
    EXPECT_TRUE(w.collidedWith(b).empty());          // no such object
    EXPECT_THAT(w.collidedWith(c), ElementsAre(d));
    EXPECT_THAT(w.collidedWith(d), ElementsAre(c));
    EXPECT_TRUE(w.collidedWith(e).empty());
    w.step(kDt);
    EXPECT_TRUE(w.collidedWith(a).empty());
    EXPECT_THAT(w.collidedWith(c), ElementsAre(d));
}

TEST(World, RemovingATouchedObjectClearsEveryCollidedList) {
    World w = world(kEffectCollisions);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 2, kCollisions));
    ObjectId b = w.add(ball("b", Vec2(6, 0), 2, kCollisions));
    ObjectId c = w.add(ball("c", Vec2(3, 0), 2, kCollisions));  // touches a and b; a and b miss
    w.step(kDt);
    ASSERT_THAT(w.collidedWith(a), ElementsAre(c));
    ASSERT_THAT(w.collidedWith(b), ElementsAre(c));
    ASSERT_TRUE(w.remove(c));
    w.step(kDt);
    EXPECT_TRUE(w.collidedWith(a).empty());
    EXPECT_TRUE(w.collidedWith(b).empty());
}

TEST(WorldPhysics, IntegratesVelocityAndSpinWithDamping) {
    World w = world(kEffectPhysics);
    ObjectDef d = ball("a", Vec2(10, 20), 1, kPhysics, Vec2(30, -12));
    d.spin = 2.0;
    d.damping = 0.5;
    ObjectId a = w.add(d);
    w.step(kDt);
    // v ← v / (1 + dt·c), then θ += spin·dt and p += v·dt.
    double keep = 1.0 / (1.0 + kDt * 0.5);
    const GameObject& o = *w.find(a);
    EXPECT_DOUBLE_EQ(o.velocity.x(), 30 * keep);
    EXPECT_DOUBLE_EQ(o.velocity.y(), -12 * keep);
    EXPECT_DOUBLE_EQ(o.spin, 2.0 * keep);
    EXPECT_DOUBLE_EQ(o.transform.position().x(), 10 + 30 * keep * kDt);
    EXPECT_DOUBLE_EQ(o.transform.position().y(), 20 - 12 * keep * kDt);
    EXPECT_DOUBLE_EQ(o.transform.rotation(), 2.0 * keep * kDt);
}

TEST(WorldPhysics, UndampedMotionIsExactOverASecond) {
    World w = world(kEffectPhysics);
    ObjectDef d = ball("a", Vec2(-5, 5), 1, kPhysics, Vec2(60, 30));
    d.spin = kHalfPi;
    ObjectId a = w.add(d);
    for (int i = 0; i < 60; ++i) w.step(kDt);
    EXPECT_NEAR(pos(w, a).x(), 55, 1e-11);
    EXPECT_NEAR(pos(w, a).y(), 35, 1e-11);
    EXPECT_NEAR(w.find(a)->transform.rotation(), kHalfPi, 1e-13);
    EXPECT_EQ(w.find(a)->velocity, Vec2(60, 30));
}

TEST(WorldPhysics, DampingSlowsOverTime) {
    World w = world(kEffectPhysics);
    ObjectDef d = ball("a", Vec2(0, 0), 1, kPhysics, Vec2(100, 0));
    d.damping = 1.0;
    ObjectId a = w.add(d);
    double previous = 100;
    for (int i = 0; i < 120; ++i) {
        w.step(kDt);
        double v = w.find(a)->velocity.x();
        ASSERT_LT(v, previous);
        ASSERT_GT(v, 0);
        previous = v;
    }
    // After 2 s: 100 / (1 + 1/60)^120, close to 100·e⁻².
    EXPECT_NEAR(previous, 100 / std::pow(1 + kDt, 120), 1e-10);
    EXPECT_NEAR(previous, 100 * std::exp(-2.0), 0.3);
}

TEST(WorldPhysics, OnlyPhysicsObjectsMoveAndOnlyWithTheEffect) {
    World w = world(kEffectPhysics | kEffectCollisions);
    ObjectId still = w.add(ball("still", Vec2(0, 0), 1, kCollisions, Vec2(100, 0)));  // no physics flag
    ObjectId moving = w.add(ball("moving", Vec2(0, 50), 1, kPhysics, Vec2(100, 0)));
    w.step(kDt);
    EXPECT_EQ(pos(w, still), Vec2(0, 0));
    EXPECT_NEAR(pos(w, moving).x(), 100 * kDt, 1e-15);
    World off = world(kEffectCollisions | kEffectResponse);
    ObjectId p = off.add(ball("p", Vec2(0, 0), 1, kPhysics, Vec2(100, 0)));
    off.step(kDt);
    EXPECT_EQ(pos(off, p), Vec2(0, 0));
}

TEST(WorldResponse, GhostIsNeverMoved) {
    World w = world(kEverything);
    ObjectId ghost = w.add(ball("ghost", Vec2(0, 0), 10, kCollisions | kGhost | kPhysics));
    ObjectId mover = w.add(ball("mover", Vec2(15, 0), 10, kCollisions));
    w.step(kDt);
    EXPECT_EQ(pos(w, ghost), Vec2(0, 0));
    EXPECT_EQ(w.find(ghost)->velocity, Vec2(0, 0));
    // The mover takes all of the correction: from 15 apart to (nearly) 20.
    EXPECT_GT(pos(w, mover).x(), 19.9);
    EXPECT_LE(pos(w, mover).x(), 20.0);
    EXPECT_EQ(pos(w, mover).y(), 0.0);
    // Two ghosts: both marked, neither moved.
    World g = world(kEverything);
    ObjectId g1 = g.add(ball("g1", Vec2(0, 0), 10, kCollisions | kGhost, Vec2(0, 0)));
    ObjectId g2 = g.add(ball("g2", Vec2(5, 0), 10, kCollisions | kGhost | kPhysics, Vec2(-60, 0)));
    g.step(kDt);
    EXPECT_EQ(pos(g, g1), Vec2(0, 0));
    EXPECT_EQ(pos(g, g2), Vec2(4, 0));  // only its own motion
    EXPECT_EQ(g.find(g2)->velocity, Vec2(-60, 0));
    EXPECT_THAT(g.collidedWith(g1), ElementsAre(g2));
}

TEST(WorldResponse, TwoMoversShareTheCorrection) {
    World w = world(kEverything);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 10, kCollisions));
    ObjectId b = w.add(ball("b", Vec2(9, 12), 10, kCollisions));  // |u| = 15, overlap 5 along (0.6, 0.8)
    w.step(kDt);
    Vec2 da = pos(w, a) - Vec2(0, 0), db = pos(w, b) - Vec2(9, 12);
    EXPECT_NEAR(da.x(), -db.x(), 1e-12);  // equal and opposite
    EXPECT_NEAR(da.y(), -db.y(), 1e-12);
    EXPECT_NEAR(cross(db, Vec2(0.6, 0.8)), 0.0, 1e-12);  // along u
    EXPECT_GT(db.dot(Vec2(0.6, 0.8)), 2.4);              // half of the overlap of 5
    EXPECT_LE(db.dot(Vec2(0.6, 0.8)), 2.5);
    double apart = (pos(w, b) - pos(w, a)).norm();
    EXPECT_LE(apart, 20.0);  // still touching: a resting contact stays a hit
    EXPECT_GT(apart, 19.9);
}

TEST(WorldResponse, PhysicsMoversReflectWithRestitution) {
    World w = world(kEverything, 0.5);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 10, kCollisions | kPhysics, Vec2(10, 3)));
    ObjectId b = w.add(ball("b", Vec2(19.9, 0), 10, kCollisions | kPhysics, Vec2(-10, 3)));
    w.step(kDt);
    // Normal (1, 0): relative normal speed −20 becomes +0.5·20, split evenly; y is untouched.
    EXPECT_NEAR(w.find(a)->velocity.x(), -5, 1e-12);
    EXPECT_NEAR(w.find(b)->velocity.x(), 5, 1e-12);
    EXPECT_EQ(w.find(a)->velocity.y(), 3);
    EXPECT_EQ(w.find(b)->velocity.y(), 3);
}

TEST(WorldResponse, LoneMoverBouncesOffAGhostOrANonPhysicsObject) {
    for (ObjectFlags wallFlags : {kCollisions | kGhost, ObjectFlags(kCollisions)}) {
        World w = world(kEverything, 0.75);
        ObjectId wall = w.add(ball("wall", Vec2(0, 0), 50, wallFlags));
        ObjectId p = w.add(ball("p", Vec2(0, 60.5), 10, kCollisions | kPhysics, Vec2(0, -60)));
        w.step(kDt);
        EXPECT_NEAR(w.find(p)->velocity.y(), 45, 1e-12) << wallFlags;  // −(−60)·0.75
        EXPECT_EQ(w.find(p)->velocity.x(), 0);
        EXPECT_EQ(w.find(wall)->velocity, Vec2(0, 0));
        EXPECT_THAT(w.collidedWith(p), ElementsAre(wall));
    }
}

TEST(WorldResponse, SeparatingObjectsAreNotReflected) {
    World w = world(kEverything, 1.0);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 10, kCollisions | kPhysics, Vec2(-30, 0)));
    ObjectId b = w.add(ball("b", Vec2(12, 0), 10, kCollisions | kPhysics, Vec2(30, 0)));
    w.step(kDt);
    EXPECT_EQ(w.hits().size(), 1u);  // still overlapping after moving
    EXPECT_EQ(w.find(a)->velocity, Vec2(-30, 0));
    EXPECT_EQ(w.find(b)->velocity, Vec2(30, 0));
}

// The equality of the approach rule: a pair moving side by side (relative normal speed exactly 0)
// is not approaching, so no impulse is applied. An impulse of 0 would change nothing but the sign
// of a zero (−0 − (−0·n) is +0), and the state hash reads every bit of a velocity, so a replay would
// see it: a velocity of −0 stays −0.
TEST(WorldResponse, ObjectsMovingSideBySideKeepTheirVelocitiesToTheBit) {
    World w = world(kEverything, 0.8);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 10, kCollisions | kPhysics, Vec2(-0.0, 7)));
    ObjectId b = w.add(ball("b", Vec2(19, 0), 10, kCollisions | kPhysics, Vec2(-0.0, 7)));
    w.step(kDt);
    EXPECT_EQ(w.hits().size(), 1u);  // they overlap, and the overlap is corrected
    EXPECT_GT(pos(w, b).x() - pos(w, a).x(), 19.0);
    for (ObjectId id : {a, b}) {
        const Vec2 v = w.find(id)->velocity;
        EXPECT_EQ(v, Vec2(0, 7)) << id;
        EXPECT_TRUE(std::signbit(v.x()))
            << "object " << id << ": velocity x became +0, as an impulse of 0 makes it";
    }
}

TEST(WorldResponse, ResponseOffMarksButMovesNothing) {
    World w = world(kEffectPhysics | kEffectCollisions);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 10, kCollisions | kPhysics, Vec2(6, 0)));
    ObjectId b = w.add(ball("b", Vec2(15, 0), 10, kCollisions | kPhysics, Vec2(-6, 0)));
    w.step(kDt);
    EXPECT_EQ(w.find(a)->velocity, Vec2(6, 0));
    EXPECT_NEAR(pos(w, a).x(), 0.1, 1e-15);
    EXPECT_NEAR(pos(w, b).x(), 14.9, 1e-14);
    EXPECT_THAT(w.collidedWith(a), ElementsAre(b));
    EXPECT_THAT(w.collidedWith(b), ElementsAre(a));
}

TEST(WorldResponse, ContainerPushesBackInsideAndReflects) {
    for (bool containerFirst : {true, false}) {
        World w = world(kEverything, 0.8);
        ObjectId box = 0, p = 0;
        ObjectDef boxDef = ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost);
        ObjectDef ballDef = ball("ball", Vec2(85, 0), 10, kCollisions | kPhysics, Vec2(600, 0));
        if (containerFirst) {
            box = w.add(boxDef);
            p = w.add(ballDef);
        } else {
            p = w.add(ballDef);
            box = w.add(boxDef);
        }
        w.step(kDt);  // moves to 95: |u| + r = 105 ≥ 100
        EXPECT_EQ(pos(w, box), Vec2(0, 0));
        // Back inside, but for the response's slop (1e-4 of the radius sum), which keeps a resting
        // contact a hit: |u| + r ≤ R + 1e-4·(R + r).
        EXPECT_LE(pos(w, p).x(), 90.0 + 1e-4 * 110 * (1 + 1e-9)) << containerFirst;
        EXPECT_GT(pos(w, p).x(), 89.9) << containerFirst;
        EXPECT_NEAR(w.find(p)->velocity.x(), -480, 1e-9) << containerFirst;  // −0.8·600
        EXPECT_THAT(w.collidedWith(p), ElementsAre(box));
        EXPECT_THAT(w.collidedWith(box), ElementsAre(p));
    }
}

// The wall is measured again after the contacts: a contact pushes a held ball further into the
// wall than the snapshot saw it (1 deep before the push, 2 after), and the wall takes it all back,
// so the ball ends the step inside. With the snapshot's depth it would end 1 unit outside.
TEST(WorldResponse, AWallIsMeasuredAgainAfterTheContactsBeforeIt) {
    for (bool containerFirst : {true, false}) {
        World w = world(kEverything);
        ObjectDef boxDef = ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost);
        ObjectDef innerDef = ball("inner", Vec2(73, 0), 10, kCollisions);
        ObjectDef outerDef = ball("outer", Vec2(91, 0), 10, kCollisions);  // |u| + r = 101
        ObjectId box = 0, inner = 0, outer = 0;
        if (containerFirst) box = w.add(boxDef);
        inner = w.add(innerDef);
        outer = w.add(outerDef);
        if (!containerFirst) box = w.add(boxDef);
        w.step(kDt);
        EXPECT_THAT(w.collidedWith(outer), testing::UnorderedElementsAre(inner, box));
        // The contact (overlap 2) moved it to 92; the wall, measured there, back to 90, but for the
        // slop of 1e-4·(R + r).
        EXPECT_LE(pos(w, outer).x() + 10, 100 + 1e-4 * 110 * (1 + 1e-9)) << containerFirst;
        EXPECT_GT(pos(w, outer).x(), 89.9) << containerFirst;
        EXPECT_NEAR(pos(w, inner).x(), 72.0, 1e-2) << containerFirst;
        EXPECT_EQ(pos(w, box), Vec2(0, 0));
    }
}

TEST(WorldResponse, ContainersEffectOffLetsObjectsLeave) {
    World w = world(kEffectPhysics | kEffectCollisions | kEffectResponse);
    w.add(ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost));
    ObjectId p = w.add(ball("ball", Vec2(85, 0), 10, kCollisions | kPhysics, Vec2(600, 0)));
    for (int i = 0; i < 10; ++i) w.step(kDt);
    EXPECT_NEAR(pos(w, p).x(), 185, 1e-9);
    EXPECT_TRUE(w.hits().empty());
    EXPECT_TRUE(w.detect(true).empty());  // the pair is not even tested
}

TEST(WorldResponse, IgnoreContainersPassesThroughTheWall) {
    World w = world(kEverything);
    w.add(ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost));
    ObjectId p =
        w.add(ball("ball", Vec2(85, 0), 10, kCollisions | kPhysics | kIgnoreContainers, Vec2(600, 0)));
    for (int i = 0; i < 10; ++i) w.step(kDt);
    EXPECT_NEAR(pos(w, p).x(), 185, 1e-9);
    EXPECT_TRUE(w.collidedWith(p).empty());
}

// Runs `steps` steps and checks that every one reports exactly `pairs` hits and that no object
// moves by more than `tolerance` from where it was after the first step.
void expectRestingContact(
    World& w, std::size_t pairs, int steps, double tolerance,
    const std::function<void()>& beforeStep = [] {}) {
    beforeStep();
    w.step(kDt);
    std::vector<Vec2> settled;
    for (const GameObject& o : w.objects()) settled.push_back(o.transform.position());
    double worst = 0;
    for (int i = 0; i < steps; ++i) {
        beforeStep();
        w.step(kDt);
        ASSERT_EQ(w.hits().size(), pairs) << "step " << i << ": the contact flickered";
        for (std::size_t k = 0; k < settled.size(); ++k)
            worst = std::max(worst, (w.objects()[k].transform.position() - settled[k]).norm());
    }
    EXPECT_LE(worst, tolerance) << "the contact jittered";
}

TEST(WorldResting, OverlappingMoversSettleAndStayTouching) {
    // Off-axis directions and radii with no exact binary form, so that rounding cannot keep an exact
    // tangency a hit by luck.
    for (int k = 0; k < 40; ++k) {
        World w = world(kEverything);
        double a = 0.1 + k * 0.157;
        w.add(ball("a", Vec2(0.3, -0.7), 10.1, kCollisions));
        w.add(ball("b", Vec2(0.3, -0.7) + 16.3 * Vec2(std::cos(a), std::sin(a)), 7.3, kCollisions));
        expectRestingContact(w, 1, 200, 1e-9);
    }
}

TEST(WorldResting, BallStoppedAgainstAWallStaysPut) {
    World w = world(kEverything, 0.0);
    w.add(ball("wall", Vec2(0, 0), 50, kCollisions | kGhost));
    ObjectId p = w.add(ball("p", Vec2(0, 60.5), 10, kCollisions | kPhysics, Vec2(0, -60)));
    expectRestingContact(w, 1, 600, 1e-9);
    EXPECT_NEAR(w.find(p)->velocity.y(), 0, 1e-12);
}

TEST(WorldResting, BallHeldOnAFloorByGravityDoesNotJitter) {
    // Game logic adds gravity each step; the ball sits on a huge ghost circle with no bounce.
    World w = world(kEverything, 0.0);
    w.add(ball("floor", Vec2(0, -1000), 1000, kCollisions | kGhost));
    ObjectId p = w.add(ball("p", Vec2(0, 10), 10, kCollisions | kPhysics));
    expectRestingContact(w, 1, 600, 1e-9, [&] { w.find(p)->velocity.y() -= 500 * kDt; });
    // The same off the top of the floor, where the normal is not an axis: it slides, but every
    // step stays a hit (until, further down the curve, it flies off as a real ball would: a body
    // sliding on a sphere leaves it where cos θ = 2/3; here after about 150 steps).
    World slope = world(kEverything, 0.0);
    slope.add(ball("floor", Vec2(0, -1000), 1000, kCollisions | kGhost));
    ObjectId q = slope.add(
        ball("q", Vec2(0, -1000) + 1010.0 * Vec2(std::sin(0.3), std::cos(0.3)), 10, kCollisions | kPhysics));
    for (int i = 0; i < 90; ++i) {
        slope.find(q)->velocity.y() -= 500 * kDt;
        slope.step(kDt);
        ASSERT_EQ(slope.hits().size(), 1u) << "step " << i;
        ASSERT_NEAR((pos(slope, q) - Vec2(0, -1000)).norm(), 1010, 0.2) << "step " << i;
    }
    // It rests within the response's slop (a ten-thousandth of the radius sum) of the surface.
    EXPECT_GT(pos(w, p).y(), 10 - 1e-3 * 1010);
}

TEST(WorldResting, BallRestingOnAContainerWallFromInside) {
    World w = world(kEverything, 0.8);
    w.add(ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost));
    ObjectId p = w.add(ball("p", Vec2(0, -90), 10, kCollisions | kPhysics));
    auto gravity = [&] { w.find(p)->velocity.y() -= 500 * kDt; };
    for (int i = 0; i < 60; ++i) gravity(), w.step(kDt);
    expectRestingContact(w, 1, 600, 1e-9, gravity);
    EXPECT_NEAR(pos(w, p).y(), -90, 0.05);
    EXPECT_EQ(pos(w, p).x(), 0);
}

TEST(WorldResting, ARowOfBallsInAContainerSettles) {
    // Three balls squeezed together in a box: after a short while nothing moves and every contact stays.
    World w = world(kEverything, 0.0);
    w.add(ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost));
    w.add(ball("a", Vec2(-15, 0), 10, kCollisions | kPhysics));
    w.add(ball("b", Vec2(0, 0), 10, kCollisions | kPhysics));
    w.add(ball("c", Vec2(15, 0), 10, kCollisions | kPhysics));
    for (int i = 0; i < 120; ++i) w.step(kDt);
    expectRestingContact(w, 2, 600, 1e-9);
}

// The largest amount by which any held object sticks out of the circular container at the origin.
double worstEscape(const World& w, double wall) {
    double worst = -INFINITY;
    for (const GameObject& o : w.objects()) {
        if (o.has(kContainer)) continue;
        double r = o.boundsOrEmpty()[0].maxRadius();
        worst = std::max(worst, o.transform.position().norm() + r - wall);
    }
    return worst;
}

TEST(WorldContainer, NothingTunnelsThroughTheWallAtArcadeSpeeds) {
    for (double radius : {10.0, 2.0, 0.5}) {  // 0.5: it moves 20 diameters per step at 600 units/s
        for (double restitution : {0.0, 0.8, 1.0}) {
            World w = world(kEverything, restitution);
            w.add(ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost));
            for (int k = 0; k < 16; ++k) {
                double a = k * kTwoPi / 16 + 0.1;
                double speed = 150 + 30 * k;  // up to 600 units/s
                std::string name = "b";
                name += std::to_string(k);
                w.add(ball(name, Vec2(k - 8, 8 - k) * 3, radius, kCollisions | kPhysics,
                           speed * Vec2(std::cos(a), std::sin(a))));
            }
            double worstAfterStep = -INFINITY;
            for (int i = 0; i < 600; ++i) {
                w.step(kDt);
                worstAfterStep = std::max(worstAfterStep, worstEscape(w, 100));
            }
            // Balls bump each other first and a wall they touched has the last word, measured where the
            // bumps left them. A bump can still shove a ball that was clear of the wall a little
            // past it for one step; it must never get more than its own radius out, and never
            // escape for good.
            EXPECT_LT(worstAfterStep, radius) << "radius " << radius << ", restitution " << restitution;
            RecordProperty("worst_escape_r" + std::to_string(radius) + "_e" + std::to_string(restitution),
                           std::to_string(worstAfterStep));
            for (const GameObject& o : w.objects())
                EXPECT_LT(o.transform.position().norm(), 100 + radius) << o.name;
        }
    }
}

TEST(WorldContainer, ALoneFastBallEndsEveryStepInside) {
    for (double angle = 0.05; angle < kTwoPi; angle += 0.7) {
        World w = world(kEverything, 1.0);
        w.add(ball("box", Vec2(0, 0), 100, kCollisions | kContainer | kGhost));
        ObjectId p = w.add(
            ball("p", Vec2(0, 0), 0.5, kCollisions | kPhysics, 600 * Vec2(std::cos(angle), std::sin(angle))));
        for (int i = 0; i < 600; ++i) {
            w.step(kDt);
            ASSERT_LE(pos(w, p).norm() + 0.5, 100 + 1e-4 * 100.5 * (1 + 1e-9)) << "step " << i;
        }
        EXPECT_NEAR(w.find(p)->velocity.norm(), 600, 1e-6);
    }
}

TEST(WorldContainer, ALoneFastBallStaysInsideAnIrregularTurningContainer) {
    World w = world(kEverything, 1.0);
    ObjectDef box;
    box.name = "box";
    box.bounds = std::make_shared<const Bounds>(Bounds{
        Bound::fromDegrees(Vec2::Zero(), {{0, 120}, {60, 90}, {130, 140}, {200, 100}, {280, 130}}, true)});
    box.transform = Transform(Vec2(500, -300), 0.3, Vec2(1.2, 0.9));
    box.flags = kCollisions | kContainer | kGhost;
    ObjectId boxId = w.add(box);
    ObjectId p = w.add(ball("p", Vec2(500, -300), 3, kCollisions | kPhysics, Vec2(600 * 0.8, 600 * 0.6)));
    for (int i = 0; i < 1200; ++i) {
        w.find(boxId)->transform.rotate(0.01);  // game logic turns the arena
        w.step(kDt);
        const GameObject& c = *w.find(boxId);
        Vec2 u = pos(w, p) - c.transform.position();
        double wall = c.boundsOrEmpty()[0].worldRadius(c.transform.linear(), u);
        ASSERT_LE(u.norm() + 3, wall + 1e-4 * (wall + 3) * (1 + 1e-9))
            << "step " << i;  // inside, but for the slop
    }
    EXPECT_NEAR(w.find(p)->velocity.norm(), 600, 1e-6);  // restitution 1 keeps the speed
}

TEST(WorldCollisions, CollidedWithThisFrameListsThisStepsPartners) {
    World w = world(kEffectCollisions);
    ObjectId a = w.add(ball("a", Vec2(0, 0), 10, kCollisions));
    ObjectId b = w.add(ball("b", Vec2(15, 0), 10, kCollisions));
    ObjectId c = w.add(ball("c", Vec2(-15, 0), 10, kCollisions));
    ObjectId d = w.add(ball("d", Vec2(0, 100), 10, kCollisions));
    ObjectId e = w.add(ball("e", Vec2(0, -15), 10, kPhysics));  // no collisions flag
    w.step(kDt);
    EXPECT_THAT(w.collidedWith(a), ElementsAre(b, c));
    EXPECT_THAT(w.collidedWith(b), ElementsAre(a));
    EXPECT_THAT(w.collidedWith(c), ElementsAre(a));
    EXPECT_TRUE(w.collidedWith(d).empty());
    EXPECT_TRUE(w.collidedWith(e).empty());
    ASSERT_EQ(w.hits().size(), 2u);
    EXPECT_EQ(w.hits()[0].a, 0u);  // indices in creation order, a < b, pair order
    EXPECT_EQ(w.hits()[0].b, 1u);
    EXPECT_EQ(w.hits()[1].a, 0u);
    EXPECT_EQ(w.hits()[1].b, 2u);
    // The next step starts afresh.
    w.find(b)->transform.setPosition(Vec2(50, 0));
    w.step(kDt);
    EXPECT_THAT(w.collidedWith(a), ElementsAre(c));
    EXPECT_TRUE(w.collidedWith(b).empty());
}

TEST(WorldCollisions, DetectMovesNothingAndAllListsEveryTestedPair) {
    World w = world(kEverything);
    w.add(ball("a", Vec2(0, 0), 10, kCollisions | kPhysics, Vec2(5, 5)));
    w.add(ball("b", Vec2(15, 0), 10, kCollisions));
    w.add(ball("c", Vec2(100, 0), 10, kCollisions));
    w.add(ball("d", Vec2(5, 0), 10, kPhysics));
    std::vector<PairReport> hits = w.detect(false), all = w.detect(true);
    ASSERT_EQ(hits.size(), 1u);
    ASSERT_EQ(all.size(), 3u);  // a-b, a-c, b-c; d has no collisions flag
    EXPECT_EQ(all[0].a, 0u);
    EXPECT_EQ(all[0].b, 1u);
    EXPECT_TRUE(all[0].test.hit);
    EXPECT_EQ(all[1].b, 2u);
    EXPECT_FALSE(all[1].test.hit);
    EXPECT_EQ(all[2].a, 1u);
    EXPECT_EQ(w.objects()[0].transform.position(), Vec2(0, 0));
    EXPECT_TRUE(w.collidedWith(w.objects()[0].id).empty());
}

// A busy scene: a container, rocks with irregular bounds, spins, damping, ghosts.
World busyWorld() {
    World w = world(kEverything, 0.9);
    w.add(ball("arena", Vec2(0, 0), 400, kCollisions | kContainer | kGhost));
    auto rock = std::make_shared<const Bounds>(
        Bounds{Bound::fromDegrees(Vec2::Zero(), {{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true),
               Bound(Vec2(25, 0), 8)});
    std::mt19937_64 rng(42);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 24; ++i) {
        ObjectDef d;
        d.name = "rock-" + std::to_string(i);
        d.bounds = rock;
        d.transform =
            Transform(Vec2(u(rng) * 250, u(rng) * 250), u(rng) * kPi, Vec2(0.5 + 0.3 * (i % 3), 0.6));
        d.velocity = Vec2(u(rng), u(rng)) * 400;
        d.spin = u(rng) * 3;
        d.damping = (i % 4) * 0.05;
        d.flags = kCollisions | kPhysics | (i % 7 == 0 ? ObjectFlags(kGhost) : ObjectFlags(0));
        w.add(d);
    }
    return w;
}

bool sameBits(double a, double b) {
    return std::memcmp(&a, &b, sizeof a) == 0;
}

void expectIdentical(const World& x, const World& y) {
    ASSERT_EQ(x.objects().size(), y.objects().size());
    for (std::size_t i = 0; i < x.objects().size(); ++i) {
        const GameObject& a = x.objects()[i];
        const GameObject& b = y.objects()[i];
        EXPECT_TRUE(sameBits(a.transform.position().x(), b.transform.position().x())) << a.name;
        EXPECT_TRUE(sameBits(a.transform.position().y(), b.transform.position().y())) << a.name;
        EXPECT_TRUE(sameBits(a.transform.rotation(), b.transform.rotation())) << a.name;
        EXPECT_TRUE(sameBits(a.velocity.x(), b.velocity.x())) << a.name;
        EXPECT_TRUE(sameBits(a.velocity.y(), b.velocity.y())) << a.name;
        EXPECT_TRUE(sameBits(a.spin, b.spin)) << a.name;
        EXPECT_THAT(x.collidedWith(a.id), ElementsAreArray(y.collidedWith(b.id))) << a.name;
    }
}

TEST(WorldDeterminism, TwoIdenticalRunsGiveBitIdenticalStates) {
    World first = busyWorld(), second = busyWorld();
    std::size_t hits = 0;
    for (int i = 0; i < 300; ++i) {
        first.step(kDt);
        second.step(kDt);
        hits += first.hits().size();
    }
    expectIdentical(first, second);
    EXPECT_GT(hits, 100u);  // the run really collided things
    // A copy taken mid-run carries on identically: a step depends on nothing but the state.
    World copy = first;
    for (int i = 0; i < 100; ++i) {
        first.step(kDt);
        copy.step(kDt);
    }
    expectIdentical(first, copy);
}

}  // namespace
}  // namespace polar
