// Continuous collision (the ccd effect): fast objects flagged `fast` are cast along their step.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "bits.h"
#include "polar/authoring/random_scene.h"
#include "polar/world.h"

namespace polar {
namespace {

constexpr double kDt = 1.0 / 60.0;

BoundsPtr circle(double r) {
    return std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), r)});
}

// A thin wall along y: 6 px thick, 200 px long, as straight edges between its corners and mid-sides.
BoundsPtr thinWall() {
    double corner = std::atan2(100.0, 3.0);  // angle of the corner (3, 100)
    double r = std::hypot(3.0, 100.0);
    std::vector<RadiusSample> samples{{0.0, 3.0},           {corner, r},         {kHalfPi, 100.0},
                                      {kPi - corner, r},    {kPi, 3.0},          {kPi + corner, r},
                                      {3 * kHalfPi, 100.0}, {kTwoPi - corner, r}};
    return std::make_shared<Bounds>(Bounds{Bound(Vec2::Zero(), samples, true)});
}

ObjectDef obstacle(const std::string& name, BoundsPtr bounds, ObjectFlags extra = 0) {
    ObjectDef o;
    o.name = name;
    o.bounds = std::move(bounds);
    o.flags = kCollisions | kGhost | extra;  // fixed in place: a collision never moves it
    return o;
}

ObjectDef bullet(const Vec2& position, const Vec2& velocity) {
    ObjectDef o;
    o.name = "bullet";
    o.bounds = circle(2.0);
    o.transform.setPosition(position);
    o.velocity = velocity;
    o.flags = kPhysics | kCollisions | kFast;
    return o;
}

WorldDef worldDef(bool ccd) {
    WorldDef def;
    def.effects =
        kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers | (ccd ? kEffectCcd : 0u);
    def.restitution = 1.0;
    return def;
}

struct Flight {
    bool hit = false;  // the bullet and the obstacle were ever reported as a hit
    double finalX = 0.0;
    double finalVx = 0.0;
};

// Fires the bullet from x = −54 toward +x at `pixelsPerStep` past an obstacle at the origin.
Flight fly(BoundsPtr obstacleBounds, double pixelsPerStep, bool ccd, int steps = 8) {
    World world(worldDef(ccd));
    world.add(obstacle("obstacle", std::move(obstacleBounds)));
    world.add(bullet(Vec2(-54.0, 0.0), Vec2(pixelsPerStep / kDt, 0.0)));
    Flight flight;
    for (int s = 0; s < steps; ++s) {
        world.step(kDt);
        flight.hit = flight.hit || !world.hits().empty();
    }
    flight.finalX = world.objects()[1].transform.position().x();
    flight.finalVx = world.objects()[1].velocity.x();
    return flight;
}

// The wall's hit zone along y = 0 is |x| ≤ 3 + 2. At 12 px per step the bullet's positions are
// −54, −42, …, −6, 6: it never meets the wall. That is the speed that tunnels; bullets go 10× faster.
constexpr double kTunnellingStep = 12.0;

TEST(Ccd, TheBaseSpeedTunnelsThroughAThinWallWithoutCcd) {
    Flight flight = fly(thinWall(), kTunnellingStep, false);
    EXPECT_FALSE(flight.hit);
    EXPECT_GT(flight.finalX, 5.0);
}

TEST(Ccd, TenTimesFasterTunnelsWithoutCcdAndIsCaughtWithIt) {
    Flight without = fly(thinWall(), 10 * kTunnellingStep, false);
    EXPECT_FALSE(without.hit);
    EXPECT_GT(without.finalX, 5.0);

    Flight with = fly(thinWall(), 10 * kTunnellingStep, true);
    EXPECT_TRUE(with.hit);
    EXPECT_LT(with.finalX, -5.0);  // bounced back: it stays on its own side
    EXPECT_LT(with.finalVx, 0.0);
}

TEST(Ccd, CatchesTheBaseSpeedToo) {
    Flight with = fly(thinWall(), kTunnellingStep, true);
    EXPECT_TRUE(with.hit);
    EXPECT_LT(with.finalX, -5.0);
}

TEST(Ccd, ARockIsNotCrossedEither) {
    Flight without = fly(circle(20.0), 10 * kTunnellingStep, false);
    EXPECT_FALSE(without.hit);
    EXPECT_GT(without.finalX, 22.0);
    Flight with = fly(circle(20.0), 10 * kTunnellingStep, true);
    EXPECT_TRUE(with.hit);
    EXPECT_LT(with.finalX, -22.0);
}

TEST(Ccd, StopsTheBulletWhereItFirstTouches) {
    // Response off for this check: the bullet is left where the cast put it.
    WorldDef noResponse = worldDef(true);
    noResponse.effects &= ~kEffectResponse;
    World still(noResponse);
    still.add(obstacle("wall", thinWall()));
    still.add(bullet(Vec2(-54.0, 0.0), Vec2(120.0 / kDt, 0.0)));
    still.step(kDt);
    ASSERT_EQ(still.hits().size(), 1u);
    double x = still.objects()[1].transform.position().x();
    // First contact is at x = −5; the cast samples every 2 px (the bullet's inner radius) and
    // bisects, so it stops just past the contact, never beyond a sample spacing.
    EXPECT_LE(x, -5.0 + 1e-9);
    EXPECT_GT(x, -5.0 - 2.0 / 1024);
    EXPECT_GE(still.hits()[0].test.penetration, 0.0);
}

TEST(Ccd, AContainerWallIsMetWhereThePathCrossesIt) {
    // A bullet inside an arena of radius 200, moving obliquely outward at 120 px per step: without ccd
    // the rule sees it far outside and pushes it back toward the arena's centre, away from where it
    // crossed; with ccd it stops on its path at the wall.
    auto run = [](bool ccd) {
        WorldDef def = worldDef(ccd);
        def.effects &= ~kEffectResponse;
        World world(def);
        ObjectDef arena = obstacle("arena", circle(200.0), kContainer);
        world.add(arena);
        Vec2 direction = Vec2(std::cos(0.5), std::sin(0.5));
        world.add(bullet(Vec2(150.0, 0.0), direction * (120.0 / kDt)));
        world.step(kDt);
        EXPECT_EQ(world.hits().size(), 1u);
        return world.objects()[1].transform.position();
    };
    // Crossing: |p + t·d| + 2 = 200 with p = (150, 0), d the direction; the wall is met at |·| = 198.
    Vec2 direction = Vec2(std::cos(0.5), std::sin(0.5));
    double b = 150.0 * direction.x();
    double t = -b + std::sqrt(b * b - (150.0 * 150.0 - 198.0 * 198.0));
    Vec2 crossing = Vec2(150.0, 0.0) + t * direction;

    Vec2 with = run(true);
    EXPECT_LT((with - crossing).norm(), 2.0 / 1024 + 1e-9);
    Vec2 without = run(false);
    EXPECT_GT(without.norm(), 230.0);  // detection saw it well outside the wall
}

TEST(Ccd, ObjectsAlreadyTouchingAreLeftToDetection) {
    // A bullet fired from inside its gun: touching at the start, so the cast does not stop it.
    World world(worldDef(true));
    world.add(obstacle("gun", circle(10.0)));
    world.add(bullet(Vec2(5.0, 0.0), Vec2(120.0 / kDt, 0.0)));
    world.step(kDt);
    EXPECT_NEAR(world.objects()[1].transform.position().x(), 125.0, 1e-9);
}

TEST(Ccd, SameResultsWithEveryBroadPhase) {
    // The mixed scene with fast bullets through it: the cast finds the same first contacts whether
    // its candidates come from the grid or from every object.
#ifdef NDEBUG
    GeneratedScene scene = makeMixedScene(12, 400, BroadPhase::AllPairs);
#else
    GeneratedScene scene =
        makeMixedScene(12, 150, BroadPhase::AllPairs);  // sanitized Debug: all-pairs is slow
#endif
    scene.def.effects |= kEffectCcd;
    SceneRandom random(3);
    for (int k = 0; k < 30; ++k) {
        ObjectDef b = bullet(Vec2(random.uniform(0, scene.side), random.uniform(0, scene.side)),
                             Vec2(random.uniform(-1, 1), random.uniform(-1, 1)) * 9000.0);
        b.name = "bullet-" + std::to_string(k);
        scene.objects.push_back(b);
    }
    std::vector<World> worlds;
    for (BroadPhase method : kAllBroadPhases) {
        scene.def.broadPhase = method;
        worlds.push_back(buildWorld(scene));
    }
    std::uint64_t cast = 0;
    for (int s = 0; s < 10; ++s) {
        for (World& w : worlds) w.step(kDt);
        cast += worlds[0].lastStepStats()[kEffectCcd].objects;
        for (std::size_t m = 1; m < worlds.size(); ++m) {
            ASSERT_EQ(worlds[0].hits().size(), worlds[m].hits().size()) << "step " << s;
            for (std::size_t i = 0; i < worlds[0].objects().size(); ++i) {
                const Vec2& p = worlds[0].objects()[i].transform.position();
                const Vec2& q = worlds[m].objects()[i].transform.position();
                ASSERT_EQ(bits(p.x()), bits(q.x()))
                    << broadPhaseName(worlds[m].def().broadPhase) << " step " << s;
                ASSERT_EQ(bits(p.y()), bits(q.y()))
                    << broadPhaseName(worlds[m].def().broadPhase) << " step " << s;
            }
        }
    }
    EXPECT_EQ(cast, 2u * 300u);  // each step: recording 30 starts, then casting 30 bullets
    EXPECT_GT(worlds[0].totalStats()[kEffectCcd].pairs, 100u);
}

TEST(Ccd, WithoutFastObjectsCcdChangesNothing) {
    GeneratedScene scene = makeMixedScene(5, 300, BroadPhase::Grid);
    World plain = buildWorld(scene);
    scene.def.effects |= kEffectCcd;
    World withCcd = buildWorld(scene);
    for (int s = 0; s < 10; ++s) {
        plain.step(kDt);
        withCcd.step(kDt);
        ASSERT_EQ(plain.hits().size(), withCcd.hits().size());
        EXPECT_EQ(withCcd.lastStepStats()[kEffectCcd].calls, 0u);
    }
    for (std::size_t i = 0; i < plain.objects().size(); ++i)
        EXPECT_EQ(bits(plain.objects()[i].transform.position().x()),
                  bits(withCcd.objects()[i].transform.position().x()));
}

}  // namespace
}  // namespace polar
