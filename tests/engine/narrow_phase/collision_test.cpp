#include "polar/collision.h"
#include "broad_phase/step_data.h"
#include "narrow_phase/pair_test.h"

#include <gtest/gtest.h>

#include <cmath>

namespace polar {
namespace {

// An object reduced to what the pair rule reads.
struct Body {
    Bounds bounds;
    Transform transform;
    ObjectFlags flags = kCollisions;

    ObjectPose pose() const { return ObjectPose{transform.position(), transform.linear(), &bounds, flags}; }
};

Body circle(Vec2 position, double radius, ObjectFlags flags = kCollisions) {
    return Body{{Bound(Vec2::Zero(), radius)}, Transform(position, 0.0, Vec2(1, 1)), flags};
}

// Radii with a long side toward bound-space +x (10) and a short one toward −x (1): which side a
// rule reads shows in the radius it reports.
Bound lopsided(Vec2 centre = Vec2::Zero()) {
    return Bound::fromDegrees(centre, {{0, 10}, {180, 1}}, false);
}

PairTest test(const Body& a, const Body& b) {
    return testPair(a.pose(), b.pose());
}

TEST(PairIsTested, BothNeedCollisionsAndRadii) {
    Body a = circle(Vec2(0, 0), 1), b = circle(Vec2(1, 0), 1);
    EXPECT_TRUE(pairIsTested(a.pose(), b.pose(), false));
    Body quiet = b;
    quiet.flags = kPhysics | kGhost;  // no collisions flag
    EXPECT_FALSE(pairIsTested(a.pose(), quiet.pose(), true));
    EXPECT_FALSE(pairIsTested(quiet.pose(), a.pose(), true));
    Body empty = b;
    empty.bounds.clear();  // no Bound
    EXPECT_FALSE(pairIsTested(a.pose(), empty.pose(), true));
    EXPECT_FALSE(pairIsTested(empty.pose(), a.pose(), true));
    ObjectPose none = b.pose();
    none.bounds = nullptr;
    EXPECT_FALSE(pairIsTested(a.pose(), none, true));
    // Ghost, physics and ignore_containers do not matter between ordinary objects.
    Body ghost = circle(Vec2(1, 0), 1, kCollisions | kGhost | kPhysics | kIgnoreContainers);
    EXPECT_TRUE(pairIsTested(a.pose(), ghost.pose(), false));
}

TEST(PairIsTested, ContainerRules) {
    Body box = circle(Vec2(0, 0), 100, kCollisions | kContainer);
    Body box2 = circle(Vec2(0, 0), 50, kCollisions | kContainer | kGhost);
    Body ball = circle(Vec2(10, 0), 1);
    Body passer = circle(Vec2(10, 0), 1, kCollisions | kIgnoreContainers);
    // A container with an ordinary object: only with the containers effect, in either order.
    EXPECT_TRUE(pairIsTested(box.pose(), ball.pose(), true));
    EXPECT_TRUE(pairIsTested(ball.pose(), box.pose(), true));
    EXPECT_FALSE(pairIsTested(box.pose(), ball.pose(), false));
    EXPECT_FALSE(pairIsTested(ball.pose(), box.pose(), false));
    // Two containers: never.
    EXPECT_FALSE(pairIsTested(box.pose(), box2.pose(), true));
    EXPECT_FALSE(pairIsTested(box2.pose(), box.pose(), true));
    // A container with an object flagged ignore_containers: never.
    EXPECT_FALSE(pairIsTested(box.pose(), passer.pose(), true));
    EXPECT_FALSE(pairIsTested(passer.pose(), box.pose(), true));
    // ignore_containers on the container itself does not stop it holding things.
    Body odd = circle(Vec2(0, 0), 100, kCollisions | kContainer | kIgnoreContainers);
    EXPECT_TRUE(pairIsTested(odd.pose(), ball.pose(), true));
}

TEST(PairTest, ContactRuleComparesSquaredDistanceWithSquaredSum) {
    // Radii 1 and 1: D = |u|² against (1 + 1)² = 4.
    for (double d : {0.5, 1.0, 1.9, 1.999999}) {
        PairTest t = test(circle(Vec2(0, 0), 1), circle(Vec2(d, 0), 1));
        EXPECT_TRUE(t.hit) << d;  // the seed's D ≤ 2 would miss at 1.9 (3.61 > 2)
        EXPECT_EQ(t.kind, ContactKind::Contact);
    }
    for (double d : {2.000001, 3.0, 3.9}) {
        EXPECT_FALSE(test(circle(Vec2(0, 0), 1), circle(Vec2(d, 0), 1)).hit) << d;  // |u| ≤ 4 would hit at 3
    }
    PairTest t = test(circle(Vec2(1, 1), 1.5), circle(Vec2(1, 4), 2.5));
    EXPECT_EQ(t.distance, 3.0);
    EXPECT_EQ(t.ra, 1.5);
    EXPECT_EQ(t.rb, 2.5);
    EXPECT_EQ(t.normal, Vec2(0, 1));  // from A toward B
    EXPECT_DOUBLE_EQ(t.penetration, 1.0);
}

TEST(PairTest, ExactTangencyIsAHit) {
    // Radii 1 and 2 at distance exactly 3, along the axes.
    for (Vec2 offset : {Vec2(3, 0), Vec2(-3, 0), Vec2(0, 3), Vec2(0, -3)}) {
        EXPECT_TRUE(test(circle(Vec2(0, 0), 1), circle(offset, 2)).hit) << offset.transpose();
        EXPECT_FALSE(test(circle(Vec2(0, 0), 1), circle(offset * (1 + 1e-15), 2)).hit) << offset.transpose();
    }
    // Diagonally, 3-4-5: radii 2 and 3 at distance 5.
    EXPECT_TRUE(test(circle(Vec2(0, 0), 2), circle(Vec2(3, 4), 3)).hit);
    EXPECT_TRUE(test(circle(Vec2(-7, 2), 2.5), circle(Vec2(-4, 6), 2.5)).hit);
    EXPECT_FALSE(test(circle(Vec2(0, 0), 2), circle(Vec2(3, 4.00000001), 3)).hit);
}

TEST(PairTest, EachSideUsesItsRadiusTowardTheOther) {
    // A's long side (10) faces +x; B sits on the +x side at 10.5 with radius 1: 10 + 1 ≥ 10.5.
    Body a{{lopsided()}, Transform(), kCollisions};
    Body right = circle(Vec2(10.5, 0), 1), left = circle(Vec2(-10.5, 0), 1);
    PairTest t = test(a, right);
    EXPECT_TRUE(t.hit);
    EXPECT_EQ(t.ra, 10);
    EXPECT_EQ(t.rb, 1);
    PairTest u = test(a, left);  // on the short side: 1 + 1 < 10.5
    EXPECT_FALSE(u.hit);
    EXPECT_EQ(u.ra, 1);
    // B's radius is read toward −u: B's long side must face A.
    Body b{{lopsided()}, Transform(Vec2(10.5, 0), 0.0, Vec2(1, 1)), kCollisions};
    EXPECT_EQ(test(circle(Vec2(0, 0), 1), b).rb, 1);  // long side faces away
    EXPECT_FALSE(test(circle(Vec2(0, 0), 1), b).hit);
    b.transform.rotate(kPi);  // now it faces A
    PairTest turned = test(circle(Vec2(0, 0), 1), b);
    EXPECT_NEAR(turned.rb, 10, 1e-12);
    EXPECT_TRUE(turned.hit);
}

TEST(PairTest, CoincidentCentresUsePlusX) {
    Body a{{lopsided()}, Transform(Vec2(5, 5), 0.0, Vec2(1, 1)), kCollisions};
    Body b{{Bound::fromDegrees(Vec2::Zero(), {{0, 7}, {180, 2}}, false)},
           Transform(Vec2(5, 5), 0.0, Vec2(1, 1)),
           kCollisions};
    PairTest t = test(a, b);
    EXPECT_TRUE(t.hit);
    EXPECT_EQ(t.distance, 0.0);
    EXPECT_EQ(t.normal, Vec2(1, 0));
    EXPECT_EQ(t.ra, 10);  // A toward +x
    EXPECT_EQ(t.rb, 2);   // B toward −x
    EXPECT_FALSE(std::isnan(t.penetration));
    EXPECT_EQ(t.penetration, 12);
    // Coincident world centres of offset radii count too, not only coincident positions.
    Body c{{lopsided(Vec2(2, 0))}, Transform(Vec2(3, 5), 0.0, Vec2(1, 1)), kCollisions};
    PairTest ct = test(c, b);
    EXPECT_EQ(ct.distance, 0.0);
    EXPECT_EQ(ct.normal, Vec2(1, 0));
    EXPECT_EQ(ct.ra, 10);
}

TEST(PairTest, AcrIsClosestToBsPositionAndBcrClosestToAcr) {
    // A: centres (0, 0) and (100, 0). B at (100, 60) with centres at world (0, 0) and (100, 10).
    Body a{{Bound(Vec2(0, 0), 5), Bound(Vec2(100, 0), 6)}, Transform(), kCollisions};
    Body b{{Bound(Vec2(-100, -60), 7), Bound(Vec2(0, -50), 8)},
           Transform(Vec2(100, 60), 0.0, Vec2(1, 1)),
           kCollisions};
    PairTest t = test(a, b);
    EXPECT_EQ(t.radiiA, 1u);  // (100, 0) is 60 from B's position; (0, 0) is 117
    EXPECT_EQ(t.radiiB, 1u);  // (100, 10) is 10 from Acr's centre; closest to A's position would be 0
    EXPECT_EQ(t.distance, 10);
    EXPECT_EQ(t.ra, 6);
    EXPECT_EQ(t.rb, 8);
    EXPECT_TRUE(t.hit);
}

TEST(PairTest, RadiiChoiceFollowsRotationAndScale) {
    Body a{{Bound(Vec2(-10, 0), 1), Bound(Vec2(10, 0), 2)}, Transform(), kCollisions};
    Body b = circle(Vec2(12, 0), 1);
    EXPECT_EQ(test(a, b).radiiA, 1u);
    a.transform.rotate(kPi);  // the centres swap sides
    PairTest t = test(a, b);
    EXPECT_EQ(t.radiiA, 0u);
    EXPECT_NEAR(t.distance, 2, 1e-12);
    EXPECT_TRUE(t.hit);                                       // 1 + 1 ≥ 2
    a.transform = Transform(Vec2::Zero(), 0.0, Vec2(-1, 1));  // mirrored: the same swap
    EXPECT_EQ(test(a, b).radiiA, 0u);
    a.transform = Transform(Vec2::Zero(), 0.0, Vec2(0.5, 1));  // centres at ±5, (10, 0) → (5, 0)
    PairTest s = test(a, b);
    EXPECT_EQ(s.radiiA, 1u);
    EXPECT_EQ(s.distance, 7);
    EXPECT_EQ(s.ra, 1);  // radius 2 scaled by 0.5 along x
}

TEST(PairTest, SeveralRadiiOnlyTheChosenPairIsTested) {
    // The seed tests Acr against Bcr only: a big radius that is not the closest one does not count.
    Body a{{Bound(Vec2(0, 0), 20), Bound(Vec2(15, 0), 1)}, Transform(), kCollisions};
    Body b = circle(Vec2(18, 5), 2);
    PairTest t = test(a, b);
    EXPECT_EQ(t.radiiA, 1u);
    EXPECT_FALSE(t.hit);  // |(3, 5)| = 5.83 > 1 + 2, although the big circle reaches B
    // Both sides with several radii: a dumbbell meeting a dumbbell end to end.
    Body d1{{Bound(Vec2(-10, 0), 3), Bound(Vec2(10, 0), 3)}, Transform(), kCollisions};
    Body d2{{Bound(Vec2(-10, 0), 2), Bound(Vec2(10, 0), 2)},
            Transform(Vec2(24, 0), 0.0, Vec2(1, 1)),
            kCollisions};
    PairTest e = test(d1, d2);
    EXPECT_EQ(e.radiiA, 1u);
    EXPECT_EQ(e.radiiB, 0u);
    EXPECT_EQ(e.distance, 4);
    EXPECT_TRUE(e.hit);  // 3 + 2 ≥ 4
}

TEST(PairTest, TiesGoToTheFirstRadiiInFileOrder) {
    // Both of A's centres, (0, ±10), are √(30² + 10²) from B's position (30, 0): Acr is the first.
    Body a{{Bound(Vec2(0, 10), 1), Bound(Vec2(0, -10), 2)}, Transform(), kCollisions};
    Body b{{Bound(Vec2(0, 10), 3), Bound(Vec2(0, -10), 4), Bound(Vec2(-20, 0), 5)},
           Transform(Vec2(30, 0), 0.0, Vec2(1, 1)),
           kCollisions};
    // B's world centres (30, 10), (30, −10), (10, 0) lie √900, √1300 and √500 from Acr's (0, 10).
    PairTest t = test(a, b);
    EXPECT_EQ(t.radiiA, 0u);
    EXPECT_EQ(t.radiiB, 2u);
    // A tie on B's side: centres (±10, 0) about B at (0, 30) are equally far from Acr at (0, 0).
    Body c = circle(Vec2(0, 0), 1);
    Body d{{Bound(Vec2(10, 0), 1), Bound(Vec2(-10, 0), 2)},
           Transform(Vec2(0, 30), 0.0, Vec2(1, 1)),
           kCollisions};
    EXPECT_EQ(test(c, d).radiiB, 0u);
    std::swap(d.bounds[0], d.bounds[1]);
    EXPECT_EQ(test(c, d).radiiB, 0u);  // still the first, now the other circle
    EXPECT_EQ(test(c, d).rb, 2);
}

TEST(PairTest, ContainerRuleWithTheContainerAsA) {
    Body box = circle(Vec2(0, 0), 100, kCollisions | kContainer | kGhost);
    struct Case {
        double x;
        bool hit;
    };
    // Ball radius 10: the wall is met when |u| + 10 ≥ 100.
    for (Case c : {Case{0, false}, Case{50, false}, Case{89.9, false}, Case{90, true}, Case{95, true},
                   Case{100, true}, Case{111, true}, Case{500, true}}) {
        PairTest t = test(box, circle(Vec2(c.x, 0), 10));
        EXPECT_EQ(t.hit, c.hit) << "ball at " << c.x;
        EXPECT_EQ(t.kind, ContactKind::Container);
        EXPECT_EQ(t.ra, 100);  // A is the container: ra is the wall
        EXPECT_EQ(t.rb, 10);
        EXPECT_EQ(t.distance, c.x);
        EXPECT_DOUBLE_EQ(t.penetration, c.x + 10 - 100);
        if (c.x > 0) {
            EXPECT_EQ(t.normal, Vec2(-1, 0));  // the ball goes back toward the centre
        }
    }
}

TEST(PairTest, ContainerRuleWithTheContainerAsB) {
    Body box = circle(Vec2(0, 0), 100, kCollisions | kContainer | kGhost);
    for (double y : {-89.9, -90.0, 89.9, 90.0}) {
        bool expected = std::fabs(y) >= 90;
        PairTest t = test(circle(Vec2(0, y), 10), box);
        EXPECT_EQ(t.hit, expected) << y;
        EXPECT_EQ(t.kind, ContactKind::Container);
        EXPECT_EQ(t.ra, 10);  // A is the ball
        EXPECT_EQ(t.rb, 100);
        EXPECT_EQ(t.distance, std::fabs(y));
        // The ball is A, which moves along −normal: −normal points from the ball to the centre.
        EXPECT_EQ(-t.normal, Vec2(0, y > 0 ? -1 : 1));
    }
}

TEST(PairTest, ContainerUsesTheHeldObjectsSideFacingTheWall) {
    Body box = circle(Vec2(0, 0), 100, kCollisions | kContainer);
    // The held object's long side (10) toward +x, short side (1) toward −x, at (89.5, 0).
    Body o{{lopsided()}, Transform(Vec2(89.5, 0), 0.0, Vec2(1, 1)), kCollisions};
    PairTest t = test(box, o);
    EXPECT_FALSE(t.hit);  // 89.5 + 10 < 100
    EXPECT_EQ(t.rb, 10);
    o.transform.setPosition(Vec2(90, 0));
    EXPECT_TRUE(test(box, o).hit);  // 90 + 10 = 100: touching from inside
    o.transform.rotate(kPi);        // short side to the wall
    PairTest turned = test(box, o);
    EXPECT_FALSE(turned.hit);
    EXPECT_NEAR(turned.rb, 1, 1e-12);
    // As A the same: r is O's side toward the wall, R the wall toward O.
    PairTest asA = test(o, box);
    EXPECT_NEAR(asA.ra, 1, 1e-12);
    EXPECT_EQ(asA.rb, 100);
    EXPECT_FALSE(asA.hit);
}

TEST(PairTest, ContainerWallIsReadTowardTheHeldObject) {
    // A container whose outline is 100 toward +x and 50 elsewhere (nearest rule).
    Body box{{Bound::fromDegrees(Vec2::Zero(), {{0, 100}, {90, 50}, {180, 50}, {270, 50}}, false)},
             Transform(),
             kCollisions | kContainer};
    EXPECT_FALSE(test(box, circle(Vec2(80, 0), 5)).hit);
    EXPECT_TRUE(test(box, circle(Vec2(0, 80), 5)).hit);
    EXPECT_EQ(test(box, circle(Vec2(0, 80), 5)).ra, 50);
    EXPECT_TRUE(test(circle(Vec2(-46, 0), 5), box).hit);
    EXPECT_EQ(test(circle(Vec2(-46, 0), 5), box).rb, 50);
}

TEST(PairTest, ContainerWithCoincidentCentres) {
    Body box{{Bound::fromDegrees(Vec2::Zero(), {{0, 100}, {180, 40}}, false)},
             Transform(),
             kCollisions | kContainer};
    Body o{{lopsided()}, Transform(), kCollisions};
    PairTest asA = test(box, o);  // u = +x: the wall toward +x is 100, O's side toward +x is 10
    EXPECT_EQ(asA.distance, 0);
    EXPECT_EQ(asA.ra, 100);
    EXPECT_EQ(asA.rb, 10);
    EXPECT_FALSE(asA.hit);
    PairTest asB = test(o, box);  // u = +x from O to C, so C toward O is −x: wall 40, O's side 1
    EXPECT_EQ(asB.ra, 1);
    EXPECT_EQ(asB.rb, 40);
    EXPECT_FALSE(asB.hit);
    EXPECT_FALSE(std::isnan(asB.penetration));
}

TEST(PairTest, FarFromTheOriginGivesTheSameAnswers) {
    // A small scene with rotations, non-uniform scales, several radii, tangencies and a container,
    // tested at the origin and 10⁶ units away.
    auto scene = [](Vec2 shift) {
        std::vector<Body> bodies;
        bodies.push_back(
            Body{{Bound::fromDegrees(Vec2::Zero(), {{0, 30}, {90, 24.5}, {180, 31}, {270, 22}}, true)},
                 Transform(shift + Vec2(0, 0), 0.5, Vec2(1.5, 0.8)),
                 kCollisions});
        bodies.push_back(circle(shift + Vec2(40, 10), 12));
        bodies.push_back(circle(shift + Vec2(43, 10), 2));
        bodies.push_back(circle(shift + Vec2(-3, -60), 1));
        bodies.push_back(circle(shift + Vec2(0, -60), 2));  // tangent to the one before: 1 + 2 = 3
        bodies.push_back(Body{{Bound(Vec2(-10, 0), 3), Bound(Vec2(10, 0), 4)},
                              Transform(shift + Vec2(-45, 5), 2.0, Vec2(1, 1)),
                              kCollisions});
        bodies.push_back(
            Body{{Bound(Vec2::Zero(), 200)}, Transform(shift, 0.0, Vec2(1, 1)), kCollisions | kContainer});
        bodies.push_back(circle(shift + Vec2(190, 0), 10));   // touches the container wall from inside
        bodies.push_back(circle(shift + Vec2(150, 125), 5));  // past the wall: |u| + 5 = 200.26
        return bodies;
    };
    std::vector<Body> home = scene(Vec2(0, 0));
    int hits = 0;
    // The last shift is exact in double but not in float (whose spacing there is 0.125).
    for (Vec2 shift : {Vec2(1e6, 0), Vec2(-1e6, 1e6), Vec2(1e6 + 0.25, -1e6 - 0.5),
                       Vec2(1234567.890625, -987654.328125)}) {
        std::vector<Body> far = scene(shift);
        for (std::size_t i = 0; i < home.size(); ++i) {
            for (std::size_t j = i + 1; j < home.size(); ++j) {
                if (!pairIsTested(home[i].pose(), home[j].pose(), true)) continue;
                PairTest h = test(home[i], home[j]), f = test(far[i], far[j]);
                EXPECT_EQ(h.hit, f.hit) << i << "-" << j << " shifted by " << shift.transpose();
                EXPECT_EQ(h.radiiA, f.radiiA);
                EXPECT_EQ(h.radiiB, f.radiiB);
                EXPECT_NEAR(h.distance, f.distance, 1e-9);
                EXPECT_NEAR(h.ra, f.ra, 1e-9);
                EXPECT_NEAR(h.rb, f.rb, 1e-9);
                hits += h.hit;
            }
        }
    }
    EXPECT_EQ(hits, 4 * 4);  // the scene has hits to compare, tangencies among them
    EXPECT_TRUE(test(home[3], home[4]).hit);
    EXPECT_TRUE(test(home[6], home[7]).hit);
}

TEST(PairTest, ZeroTinyAndHugeScales) {
    // A radius-1000 circle at scale 1e-3 is a radius-1 circle; a radius-1 circle at 1e3 is radius 1000.
    Body tiny{{Bound(Vec2(0, 0), 1000)}, Transform(Vec2(0, 0), 0.3, Vec2(1e-3, 1e-3)), kCollisions};
    Body huge{{Bound(Vec2(0, 0), 1)}, Transform(Vec2(1500, 0), 0.0, Vec2(1e3, 1e3)), kCollisions};
    PairTest near = test(tiny, circle(Vec2(3, 0), 2));
    EXPECT_NEAR(near.ra, 1, 1e-12);
    EXPECT_TRUE(near.hit);  // 1 + 2 ≥ 3
    EXPECT_FALSE(test(tiny, circle(Vec2(3.001, 0), 2)).hit);
    PairTest big = test(circle(Vec2(0, 0), 500), huge);
    EXPECT_NEAR(big.rb, 1000, 1e-9);
    EXPECT_TRUE(big.hit);
    // Scale 0, on one axis or both: the world radius is 0, and nothing is NaN.
    for (Vec2 s : {Vec2(0, 0), Vec2(0, 1), Vec2(2, 0)}) {
        Body flat{{lopsided()}, Transform(Vec2(0, 0), 0.7, s), kCollisions};
        for (Vec2 where : {Vec2(1.5, 0), Vec2(0, 0), Vec2(-3, 4)}) {
            PairTest t = test(flat, circle(where, 2));
            EXPECT_EQ(t.ra, 0.0);
            EXPECT_FALSE(std::isnan(t.distance) || std::isnan(t.penetration) || std::isnan(t.normal.x()));
            EXPECT_EQ(t.hit, where.norm() <= 2);
        }
        Body box{{Bound(Vec2::Zero(), 100)}, Transform(Vec2(0, 0), 0.0, s), kCollisions | kContainer};
        PairTest c = test(box, circle(Vec2(1, 1), 2));
        EXPECT_EQ(c.ra, 0.0);
        EXPECT_TRUE(c.hit);  // a container squashed to nothing holds nothing
    }
}

TEST(ObjectPose, ReadsAGameObject) {
    GameObject o;
    o.transform = Transform(Vec2(3, 4), kHalfPi, Vec2(2, 1));
    o.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2(1, 0), 1)});
    o.flags = kCollisions | kGhost;
    ObjectPose p = poseOf(o);
    EXPECT_EQ(p.position, Vec2(3, 4));
    EXPECT_EQ(p.flags, kCollisions | kGhost);
    EXPECT_EQ(p.bounds, o.bounds.get());
    Vec2 c = p.worldCentre(0);  // (1, 0) → scale (2, 0) → turn (0, 2) → + (3, 4)
    EXPECT_NEAR(c.x(), 3, 1e-15);
    EXPECT_NEAR(c.y(), 6, 1e-15);
    GameObject bare;
    EXPECT_TRUE(bare.boundsOrEmpty().empty());
    EXPECT_STREQ(contactKindName(ContactKind::Contact), "contact");
    EXPECT_STREQ(contactKindName(ContactKind::Container), "container");
}

}  // namespace
}  // namespace polar
