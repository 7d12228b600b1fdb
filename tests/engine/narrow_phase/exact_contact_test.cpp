// Exact contact on every path of the pair rule. Each pair is built from powers of two and small
// integers on the x axis, so that every double on the way is exact and the rule's comparison is met
// with equality: |u|² = (rA + rB)² for a contact, |u| + r = R for a container. Touching counts, so
// each is a hit, and one ulp apart it is a miss. Each case runs through testPair, through testPairs
// (its lanes), and through a World with each broad phase, at bounds, nearest, chord and all-radii
// (and is a hit at exact too); together they take the chord contact path (single and several
// radii: chordContact, the chord lanes) and the rule's general path (nearest, circles, one side of
// each, containers: applyRule, the rule lanes). Each of those paths' verdicts, made strict (`<` for
// `<=`, `>` for `>=`), fails a test here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include "narrow_phase/pair_test.h"
#include "pair_cases.h"
#include "polar/collision.h"
#include "polar/world.h"

namespace polar {
namespace {

using testing::expectSameBits;

// A diamond: samples at 0°, 90°, 180° and 270°, of radius r0 at 0° and `rest` at the others, read
// by chord when `chord` (the file's interpolate flag). Toward bound-space +x both rules read r0
// exactly. Nearest: the 0° sample. Chord: the 0° vertex (r0, 0) is exact, and the edge to the 90°
// vertex (rest·cos 90°, rest·sin 90°) has n_x = rest·sin 90° = rest (sin 90° rounds to 1) and
// h = r0·rest, which is all a direction along +x reads. With powers of two, so are the quotients.
Bound diamond(bool chord, double r0, double rest, Vec2 centre = Vec2::Zero()) {
    return Bound(centre, {{0.0, r0}, {kHalfPi, rest}, {kPi, rest}, {1.5 * kPi, rest}}, chord);
}
Bound diamond(bool chord, double r) {
    return diamond(chord, r, r);
}
Bound circle(double r, Vec2 centre = Vec2::Zero()) {
    return Bound(centre, r);
}

// One object of a case: its radii and where it stands. The transform has no rotation, so its linear
// part is diag(scale) exactly; a scale of (−1, −1) turns the object's 0° sample toward −x.
struct Body {
    Bounds bounds;
    Vec2 position = Vec2::Zero();
    Vec2 scale = Vec2(1, 1);
    ObjectFlags flags = kCollisions;

    ObjectPose pose() const { return poseAt(position); }
    // The same object moved to `at`.
    ObjectPose poseAt(Vec2 at) const {
        return ObjectPose(at, Transform(at, 0.0, scale).linear(), &bounds, flags);
    }
};

// A pair at exact contact (A earlier in the scene than B), the radii the rule must read, and where
// B stands one ulp from the contact, on the side where the pair misses.
struct ExactCase {
    std::string name;
    Body a, b;
    double ra = 0.0, rb = 0.0;  // A's radius and B's, as PairTest reports them
    double missX = 0.0;         // B's x one ulp off the contact
    ContactKind kind = ContactKind::Contact;
};

// The levels at which the rule decides every case below: the closest-pair rule's three, and
// all-radii (the same rule on every pair of radii).
constexpr Accuracy kRuleLevels[] = {Accuracy::Bounds, Accuracy::Nearest, Accuracy::Chord, Accuracy::AllRadii};

std::vector<ExactCase> exactCases() {
    const double farther16 = std::nextafter(16.0, INFINITY), farther32 = std::nextafter(32.0, INFINITY);
    const double nearer24 = std::nextafter(24.0, 0.0);
    const Vec2 here(0, 0), at16(16, 0), at24(24, 0), at32(32, 0), upright(1, 1), turned(-1, -1);
    const ObjectFlags container = kCollisions | kContainer;
    std::vector<ExactCase> cases;
    auto contact = [&](std::string name, Body a, Body b, double ra, double rb, double missX) {
        cases.push_back({std::move(name), std::move(a), std::move(b), ra, rb, missX, ContactKind::Contact});
    };
    auto held = [&](std::string name, Body a, Body b, double ra, double rb) {
        cases.push_back(
            {std::move(name), std::move(a), std::move(b), ra, rb, nearer24, ContactKind::Container});
    };

    // Contacts, 8 + 8 at 16 unless said otherwise; B is turned so that it too reads its 0° sample
    // toward −u. Both by chord (the files' flag, or the level's): testPair's first path and the
    // chord lanes. Nearest, or one side each: the rule's general path and the rule lanes.
    contact("chord diamonds", {{diamond(true, 8)}}, {{diamond(true, 8)}, at16, turned}, 8, 8, farther16);
    contact("nearest diamonds", {{diamond(false, 8)}}, {{diamond(false, 8)}, at16, turned}, 8, 8, farther16);
    contact("chord and nearest", {{diamond(true, 8)}}, {{diamond(false, 8, 1)}, at16, turned}, 8, 8,
            farther16);
    // Other radii: 4 + 12 at 16, lumpy (the other samples 1 or 4).
    contact("4 + 12 by chord", {{diamond(true, 4)}}, {{diamond(true, 12, 4)}, at16, turned}, 4, 12,
            farther16);
    contact("4 + 12 by nearest", {{diamond(false, 4, 1)}}, {{diamond(false, 12, 4)}, at16, turned}, 4, 12,
            farther16);
    // A scaled by 2 (|det L| = 4): 16 + 16 at 32.
    contact("scaled", {{diamond(true, 8)}, here, Vec2(2, 2)}, {{diamond(true, 16)}, at32, turned}, 16, 16,
            farther32);
    // Circles (one sample: the nearest rule at every level), 8 + 24 at 32.
    contact("circles", {{circle(8)}}, {{circle(24)}, at32}, 8, 24, farther32);
    // Several radii: the closest pair first (followPath's paths; the lanes through closestBounds).
    // A's second radii, at its position, is the closer to B; B's first.
    contact("several radii by chord", {{diamond(true, 8, 8, Vec2(128, 0)), diamond(true, 8)}},
            {{diamond(true, 8), diamond(true, 8, 8, Vec2(0, 100))}, at16, turned}, 8, 8, farther16);
    contact("several radii by nearest", {{circle(5, Vec2(0, 100)), circle(8)}},
            {{circle(8), circle(8, Vec2(0, 100))}, at16}, 8, 8, farther16);

    // Containers: the held object's side facing the wall reaches it, 24 + 8 = 32; one ulp nearer
    // the container's centre it is inside.
    held("chord container as A", {{diamond(true, 32)}, here, upright, container}, {{diamond(true, 8)}, at24},
         32, 8);
    held("nearest container as A", {{diamond(false, 32, 16)}, here, upright, container},
         {{diamond(false, 8, 1)}, at24}, 32, 8);
    held("circle in a diamond", {{diamond(true, 32)}, here, upright, container}, {{circle(8)}, at24}, 32, 8);
    // The container as B: the wall is met toward −x from B's centre, where both are turned.
    held("chord container as B", {{diamond(true, 8)}, here, turned},
         {{diamond(true, 32)}, at24, turned, container}, 8, 32);
    // A's other radii is farther from the container's centre than the one at A's position, and
    // inside the wall (26 + 2 < 32), so all-radii (which sees every held radii) agrees.
    held("container as B, several radii held", {{circle(2, Vec2(24, -26)), circle(8)}},
         {{circle(32)}, at24, upright, container}, 8, 32);
    return cases;
}

ExactCase missing(const ExactCase& c) {
    ExactCase m = c;
    m.b.position.x() = c.missX;
    return m;
}

// The pair's hits as a World with this broad phase reports them after a step (nothing moves: no
// physics, no response), checked against World::detect on the same state.
std::vector<PairReport> worldHits(const ExactCase& c, Accuracy level, BroadPhase method) {
    World world(WorldDef{kEffectCollisions | kEffectContainers, 0.8, level, method});
    for (const Body* body : {&c.a, &c.b}) {
        ObjectDef def;
        def.name = body == &c.a ? "a" : "b";
        def.bounds = std::make_shared<const Bounds>(body->bounds);
        def.transform = Transform(body->position, 0.0, body->scale);
        def.flags = body->flags;
        world.add(def);
    }
    world.step(1.0 / 60);
    std::vector<PairReport> detected = world.detect(false);
    EXPECT_EQ(detected.size(), world.hits().size());
    for (std::size_t k = 0; k < detected.size() && k < world.hits().size(); ++k)
        expectSameBits(detected[k].test, world.hits()[k].test, k);
    return {world.hits().begin(), world.hits().end()};
}

// What the rule must report for a case at exact contact: its radii and distance exactly (so the
// comparison was made at equality), no penetration, and a hit.
void expectExactContact(const PairTest& t, const ExactCase& c) {
    EXPECT_EQ(t.ra, c.ra);
    EXPECT_EQ(t.rb, c.rb);
    EXPECT_EQ(t.distance, c.kind == ContactKind::Contact ? c.ra + c.rb : std::fabs(c.ra - c.rb));
    EXPECT_EQ(t.penetration, 0.0);
    EXPECT_EQ(t.kind, c.kind);
    EXPECT_TRUE(t.hit);
}

TEST(ExactContact, TestPairHitsAtContactAndMissesOneUlpApart) {
    for (const ExactCase& c : exactCases()) {
        for (Accuracy level : kRuleLevels) {
            SCOPED_TRACE(c.name + " at " + accuracyName(level));
            expectExactContact(testPair(c.a.pose(), c.b.pose(), level), c);
            ExactCase apart = missing(c);
            PairTest t = testPair(apart.a.pose(), apart.b.pose(), level);
            EXPECT_FALSE(t.hit) << "penetration " << t.penetration;
        }
        // The exact level: touching counts there too.
        EXPECT_TRUE(testPair(c.a.pose(), c.b.pose(), Accuracy::Exact).hit) << c.name;
    }
}

TEST(ExactContact, TestPairsGivesTestPairsBitsAtContact) {
    std::vector<ExactCase> cases = exactCases();
    std::vector<ObjectPose> poses;  // per case: the contact's A and B, then the miss's
    for (const ExactCase& c : cases) {
        for (const ObjectPose& pose :
             {c.a.pose(), c.b.pose(), c.a.pose(), c.b.poseAt(Vec2(c.missX, c.b.position.y()))})
            poses.push_back(pose);
    }
    for (Accuracy level : kAllAccuracies) {
        // Every case at once, so that each kind of lane holds several pairs.
        std::vector<PosePair> pairs;
        for (std::size_t k = 0; k < poses.size(); k += 2) pairs.push_back({&poses[k], &poses[k + 1]});
        std::vector<PairTest> batched(pairs.size());
        testPairs(pairs, level, batched.data());
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const ExactCase& c = cases[k / 2];
            bool contact = k % 2 == 0;
            SCOPED_TRACE(c.name + (contact ? "" : " one ulp apart") + " at " + accuracyName(level));
            expectSameBits(batched[k], testPair(*pairs[k].a, *pairs[k].b, level), k);
            if (std::find(std::begin(kRuleLevels), std::end(kRuleLevels), level) == std::end(kRuleLevels))
                continue;
            if (contact)
                expectExactContact(batched[k], c);
            else
                EXPECT_FALSE(batched[k].hit);
        }
    }
}

TEST(ExactContact, EveryBroadPhaseReportsTheContactAndNotTheMiss) {
    for (const ExactCase& c : exactCases()) {
        for (Accuracy level : kRuleLevels) {
            PairTest single = testPair(c.a.pose(), c.b.pose(), level);
            for (BroadPhase method : kAllBroadPhases) {
                SCOPED_TRACE(c.name + " at " + accuracyName(level) + " with " + broadPhaseName(method));
                std::vector<PairReport> hits = worldHits(c, level, method);
                ASSERT_EQ(hits.size(), 1u);
                EXPECT_EQ(hits[0].a, 0u);
                EXPECT_EQ(hits[0].b, 1u);
                expectSameBits(hits[0].test, single, 0);
                expectExactContact(hits[0].test, c);
                EXPECT_TRUE(worldHits(missing(c), level, method).empty());
            }
        }
    }
}

}  // namespace
}  // namespace polar
