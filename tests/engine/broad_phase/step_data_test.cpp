#include "broad_phase/step_data.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

#include "bits.h"
#include "polar/authoring/random_scene.h"
#include "polar/world.h"
#include "shapes/outline.h"

namespace polar {
namespace {

// The objects of a mixed scene (rocks of one to three radii, rotated, scaled, mirrored, some of
// scale 0; containers; objects without collisions), and the indices of those flagged collisions.
struct Objects {
    std::vector<GameObject> objects;
    std::vector<std::uint32_t> collisions;
};

Objects mixedObjects(std::uint64_t seed, std::size_t n) {
    World world = buildWorld(makeMixedScene(seed, n, BroadPhase::AllPairs));
    Objects o{{world.objects().begin(), world.objects().end()}, {}};
    for (std::uint32_t i = 0; i < o.objects.size(); ++i)
        if (o.objects[i].has(kCollisions)) o.collisions.push_back(i);
    return o;
}

double sigmaMax(const GameObject& object) {
    Vec2 s = object.transform.scaleFactors();
    return std::max(std::fabs(s.x()), std::fabs(s.y()));
}

TEST(StepData, GivesASlotToEachCandidateInTheGivenOrder) {
    Objects o = mixedObjects(3, 400);
    // Also one without radii and one whose position is not finite: neither can hit anything.
    for (std::uint32_t k = 0; k < 2; ++k) {
        o.objects.push_back(o.objects[o.collisions[k]]);
        o.collisions.push_back(static_cast<std::uint32_t>(o.objects.size() - 1));
    }
    o.objects[o.collisions.end()[-2]].bounds = nullptr;
    o.objects[o.collisions.end()[-1]].transform.setPosition(Vec2(NAN, 0.0));
    // Any order: the grid passes its last cell order.
    std::vector<std::uint32_t> indices(o.collisions.rbegin(), o.collisions.rend());
    for (bool containers : {false, true}) {
        StepData data;
        std::vector<std::uint32_t> others;
        data.build({.objects = o.objects,
                    .candidates = indices,
                    .containers = containers,
                    .accuracy = Accuracy::Bounds,
                    .fastStarts = {}},
                   others);
        std::vector<std::uint32_t> slotted, regular, container, rest;
        for (std::uint32_t i : indices) {
            const GameObject& object = o.objects[i];
            bool isContainer = object.has(kContainer);
            if (!object.boundsOrEmpty().empty() && (containers || !isContainer)) slotted.push_back(i);
            bool finite = std::isfinite(object.transform.position().x());
            if (object.boundsOrEmpty().empty() || isContainer || !finite) rest.push_back(i);
        }
        EXPECT_EQ(data.objectIndex, slotted) << "containers " << containers;
        EXPECT_EQ(others, rest) << "containers " << containers;
        for (std::uint32_t s = 0; s < data.size(); ++s) {
            const GameObject& object = o.objects[data.objectIndex[s]];
            if (!std::isfinite(object.transform.position().x())) continue;
            (object.has(kContainer) ? container : regular).push_back(s);
        }
        EXPECT_EQ(data.regularSlots, regular);
        EXPECT_EQ(data.containerSlots, container);
        EXPECT_EQ(containers, !container.empty()) << "the scene has containers";
        EXPECT_TRUE(data.fastSlots.empty());
    }
}

TEST(StepData, PosesAndReachCirclesAreTheObjectsAsDocumented) {
    Objects o = mixedObjects(5, 300);
    StepData data;
    std::vector<std::uint32_t> others;
    data.build({.objects = o.objects,
                .candidates = o.collisions,
                .containers = true,
                .accuracy = Accuracy::Bounds,
                .fastStarts = {}},
               others);
    std::size_t compound = 0;
    for (std::uint32_t s = 0; s < data.size(); ++s) {
        const GameObject& object = o.objects[data.objectIndex[s]];
        ObjectPose pose = poseOf(object);
        ASSERT_EQ(bits(data.poses[s].position.x()), bits(pose.position.x()));
        ASSERT_EQ(bits(data.poses[s].position.y()), bits(pose.position.y()));
        for (int e = 0; e < 4; ++e) ASSERT_EQ(bits(data.poses[s].linear(e)), bits(pose.linear(e)));
        ASSERT_EQ(data.poses[s].flags, object.flags);

        const Bounds& radii = object.boundsOrEmpty();
        const ReachCircle& c = data.reach[s];
        // The margin: at least 1e-9 of the radius plus 1e-14 of the coordinates.
        EXPECT_GE(static_cast<double>(c.margin), 1e-9 * c.radius + 1e-14 * (std::fabs(c.x) + std::fabs(c.y)));
        EXPECT_EQ(c.fast, ReachCircle::kNotFast);
        Box box = data.box(s), around = Box::around(c);
        EXPECT_TRUE(box.minX == around.minX && box.minY == around.minY && box.maxX == around.maxX &&
                    box.maxY == around.maxY);
        if (radii.size() == 1) {
            // One bound: its circle, σmax·maxRadius about its world centre.
            ASSERT_TRUE(data.single(s));
            Vec2 centre = pose.worldCentre(0);
            EXPECT_EQ(bits(c.x), bits(centre.x()));
            EXPECT_EQ(bits(c.y), bits(centre.y()));
            EXPECT_EQ(bits(c.radius), bits(sigmaMax(object) * radii[0].maxRadius()));
            continue;
        }
        // Compound: a circle per radii about its world centre, and one about the position that
        // holds them all: R = max_k |L·c_k| + σmax·maxRadius_k.
        ++compound;
        ASSERT_EQ(data.radiiBegin[s + 1] - data.radiiBegin[s], radii.size());
        EXPECT_EQ(bits(c.x), bits(pose.position.x()));
        EXPECT_EQ(bits(c.y), bits(pose.position.y()));
        for (std::size_t k = 0; k < radii.size(); ++k) {
            const Disc& d = data.radiiReach[data.radiiBegin[s] + k];
            Vec2 centre = pose.worldCentre(k);
            EXPECT_EQ(bits(d.x), bits(centre.x()));
            EXPECT_EQ(bits(d.y), bits(centre.y()));
            double r = sigmaMax(object) * radii[k].maxRadius();
            EXPECT_GE(d.reach, r);
            // Within rounding of the coordinates, which the margin covers.
            EXPECT_LE(std::hypot(d.x - c.x, d.y - c.y) + r, c.radius + static_cast<double>(c.margin));
        }
    }
    EXPECT_GT(compound, 20u);
}

TEST(StepData, ReachCirclesHoldEveryRadiusTheNarrowPhaseReads) {
    // For every bound and direction, the narrow phase's world radius about the radii's world
    // centre lies within the object's reach circle (with its margin).
    Objects o = mixedObjects(7, 300);
    StepData data;
    std::vector<std::uint32_t> others;
    data.build({.objects = o.objects,
                .candidates = o.collisions,
                .containers = true,
                .accuracy = Accuracy::Bounds,
                .fastStarts = {}},
               others);
    for (std::uint32_t s = 0; s < data.size(); ++s) {
        const GameObject& object = o.objects[data.objectIndex[s]];
        const ObjectPose& pose = data.poses[s];
        const ReachCircle& c = data.reach[s];
        double reach = c.radius + static_cast<double>(c.margin);
        for (std::size_t k = 0; k < object.boundsOrEmpty().size(); ++k) {
            Vec2 centre = pose.worldCentre(k);
            double offset = std::hypot(centre.x() - c.x, centre.y() - c.y);
            for (int d = 0; d < 64; ++d) {
                double sine, cosine;
                trig::sincos(kTwoPi * d / 64.0 + 0.01, sine, cosine);
                Vec2 w(cosine, sine);
                for (OutlineShape shape : {OutlineShape::Nearest, OutlineShape::Chord}) {
                    double r = outlineOf(object.boundsOrEmpty()[k], shape).worldRadius(pose, w, 1.0);
                    ASSERT_LE(offset + r, reach) << object.name << " radii " << k << " direction " << d;
                }
            }
        }
    }
}

TEST(StepData, AFastObjectsBoxCoversItsCast) {
    Objects o = mixedObjects(9, 200);
    // Fast starts, sorted by object: every third candidate came from 40 units left and 30 below;
    // one did not move at all.
    std::vector<FastStart> starts;
    for (std::size_t k = 0; k < o.collisions.size(); k += 3) {
        std::uint32_t i = o.collisions[k];
        o.objects[i].flags |= kFast;
        const Vec2& p = o.objects[i].transform.position();
        starts.push_back({i, p.x() - 40.0, p.y() - 30.0});
    }
    starts[1].x = o.objects[starts[1].object].transform.position().x();
    starts[1].y = o.objects[starts[1].object].transform.position().y();
    // Lay the slots out in reverse: fast slots still come in creation order.
    std::vector<std::uint32_t> indices(o.collisions.rbegin(), o.collisions.rend());
    StepData data;
    std::vector<std::uint32_t> others;
    data.build({.objects = o.objects,
                .candidates = indices,
                .containers = true,
                .accuracy = Accuracy::Bounds,
                .fastStarts = starts},
               others);
    std::size_t moved = 0;
    for (std::uint32_t s = 0; s < data.size(); ++s) {
        const GameObject& object = o.objects[data.objectIndex[s]];
        const ReachCircle& c = data.reach[s];
        auto start = std::find_if(starts.begin(), starts.end(),
                                  [&](const FastStart& f) { return f.object == data.objectIndex[s]; });
        bool expectFast = start != starts.end() && start != starts.begin() + 1 && object.has(kFast);
        ASSERT_EQ(c.fast != ReachCircle::kNotFast, expectFast) << object.name;
        if (!expectFast) continue;
        ++moved;
        const FastSlot& fast = data.fastSlots[c.fast];
        EXPECT_EQ(fast.slot, s);
        EXPECT_EQ(fast.startX, start->x);
        EXPECT_EQ(fast.startY, start->y);
        // Around the reach circle where the object is, and where it would be at the start.
        Box end = Box::around(c);
        ReachCircle before = c;
        before.x -= object.transform.position().x() - start->x;
        before.y -= object.transform.position().y() - start->y;
        Box begin = Box::around(before), box = data.box(s);
        for (const Box& b : {end, begin})
            EXPECT_TRUE(box.minX <= b.minX && box.minY <= b.minY && box.maxX >= b.maxX && box.maxY >= b.maxY);
    }
    EXPECT_EQ(moved, data.fastSlots.size());
    EXPECT_GT(moved, 30u);
    for (std::size_t k = 1; k < data.fastSlots.size(); ++k)
        EXPECT_LT(data.objectIndex[data.fastSlots[k - 1].slot], data.objectIndex[data.fastSlots[k].slot]);
}

TEST(StepData, CullingNeverLosesAHit) {
    // mayHit false, a contact gap > 0 or a container gap > 0 each say the narrow phase cannot hit,
    // at every accuracy level.
    Objects o = mixedObjects(13, 250);
    for (Accuracy accuracy : kAllAccuracies) {
        StepData data;
        std::vector<std::uint32_t> others;
        data.build({.objects = o.objects,
                    .candidates = o.collisions,
                    .containers = true,
                    .accuracy = accuracy,
                    .fastStarts = {}},
                   others);
        std::size_t hits = 0, containerHits = 0;
        for (std::uint32_t a = 0; a < data.size(); ++a) {
            for (std::uint32_t b = a + 1; b < data.size(); ++b) {
                if (!pairIsTested(data.poses[a], data.poses[b], true)) continue;
                if (!testPair(data.poses[a], data.poses[b], accuracy).hit) continue;
                bool ca = data.isContainer(a), cb = data.isContainer(b);
                if (!ca && !cb) {
                    ++hits;
                    EXPECT_TRUE(data.mayHit(a, b)) << accuracyName(accuracy);
                    EXPECT_LE(data.contactGap(a, b), 0.0) << accuracyName(accuracy);
                    continue;
                }
                std::uint32_t container = ca ? a : b, held = ca ? b : a;
                if (!std::binary_search(data.containerSlots.begin(), data.containerSlots.end(), container))
                    continue;
                ++containerHits;
                EXPECT_LE(data.containerGap(data.containerOrdinal(container), held), 0.0)
                    << accuracyName(accuracy) << " " << o.objects[data.objectIndex[container]].name << " "
                    << o.objects[data.objectIndex[held]].name;
            }
        }
        EXPECT_GT(hits, 50u) << accuracyName(accuracy);
        EXPECT_GT(containerHits, 3u) << accuracyName(accuracy);
    }
}

TEST(StepData, RefreshGivesWhatABuildGives) {
    Objects o = mixedObjects(17, 200);
    StepData data, fresh;
    std::vector<std::uint32_t> others;
    data.build({.objects = o.objects,
                .candidates = o.collisions,
                .containers = true,
                .accuracy = Accuracy::Bounds,
                .fastStarts = {}},
               others);
    for (std::uint32_t s = 0; s < data.size(); s += 7) {
        GameObject& object = o.objects[data.objectIndex[s]];
        object.transform.setPosition(object.transform.position() + Vec2(12.5, -3.25));
        data.refresh(s, object);
    }
    fresh.build({.objects = o.objects,
                 .candidates = o.collisions,
                 .containers = true,
                 .accuracy = Accuracy::Bounds,
                 .fastStarts = {}},
                others);
    ASSERT_EQ(data.size(), fresh.size());
    for (std::uint32_t s = 0; s < data.size(); ++s) {
        EXPECT_EQ(bits(data.poses[s].position.x()), bits(fresh.poses[s].position.x()));
        EXPECT_EQ(bits(data.reach[s].x), bits(fresh.reach[s].x));
        EXPECT_EQ(bits(data.reach[s].y), bits(fresh.reach[s].y));
        EXPECT_EQ(bits(data.reach[s].radius), bits(fresh.reach[s].radius));
        EXPECT_EQ(data.reach[s].margin, fresh.reach[s].margin);
    }
    ASSERT_EQ(data.radiiReach.size(), fresh.radiiReach.size());
    for (std::size_t k = 0; k < data.radiiReach.size(); ++k) {
        EXPECT_EQ(bits(data.radiiReach[k].x), bits(fresh.radiiReach[k].x));
        EXPECT_EQ(bits(data.radiiReach[k].reach), bits(fresh.radiiReach[k].reach));
    }
    ASSERT_EQ(data.inner.size(), fresh.inner.size());
    for (std::size_t k = 0; k < data.inner.size(); ++k) {
        EXPECT_EQ(bits(data.inner[k].x), bits(fresh.inner[k].x));
        EXPECT_EQ(bits(data.inner[k].margin), bits(fresh.inner[k].margin));
    }
}

TEST(StepData, InnerBoundRadiusIsTheNearestPointOfTheOutlineTheLevelReads) {
    EXPECT_EQ(innerBoundRadius(Bound(Vec2(3, 4), 2.5), Accuracy::Bounds), 2.5);
    // Nearest rule: the smallest sample.
    std::vector<RadiusSample> star{{0.0, 3.0}, {1.0, 1.5}, {2.5, 4.0}, {4.0, 2.0}};
    EXPECT_EQ(innerBoundRadius(Bound(Vec2::Zero(), star, false), Accuracy::Bounds), 1.5);
    // Chord rule: the nearest edge. A square with corners at radius √2 on the axes' diagonals has
    // its edges at distance 1; one with vertices at radius 1 on the axes has them at √½.
    std::vector<RadiusSample> corners, axes;
    for (int k = 0; k < 4; ++k) {
        corners.push_back({kHalfPi * k + kHalfPi / 2, std::sqrt(2.0)});
        axes.push_back({kHalfPi * k, 1.0});
    }
    EXPECT_NEAR(innerBoundRadius(Bound(Vec2::Zero(), corners, true), Accuracy::Bounds), 1.0, 1e-15);
    Bound chord(Vec2::Zero(), axes, true), nearest(Vec2::Zero(), axes, false);
    // By the file's flag, unless the level picks the rule.
    for (Accuracy level : {Accuracy::Bounds, Accuracy::Circle, Accuracy::AllRadii, Accuracy::Exact}) {
        EXPECT_NEAR(innerBoundRadius(chord, level), std::sqrt(0.5), 1e-15) << accuracyName(level);
        EXPECT_EQ(innerBoundRadius(nearest, level), 1.0) << accuracyName(level);
    }
    EXPECT_NEAR(innerBoundRadius(nearest, Accuracy::Chord), std::sqrt(0.5), 1e-15);
    EXPECT_EQ(innerBoundRadius(chord, Accuracy::Nearest), 1.0);
}

TEST(StepData, AContainersInnerCirclesFollowTheLevelsRule) {
    // A container whose file asks for the nearest rule, read by chord at the chord level: its wall
    // comes in to √½ of the samples' radius between them, so a held circle there hits. The gap must
    // not say otherwise at any level, and likewise for a chord container read by nearest.
    for (bool interpolate : {false, true}) {
        std::vector<RadiusSample> square;
        for (int k = 0; k < 4; ++k) square.push_back({kHalfPi * k, 10.0});
        World world(WorldDef{kEffectCollisions | kEffectContainers, 0.8});
        ObjectDef container;
        container.name = "container";
        container.flags = kCollisions | kContainer;
        container.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), square, interpolate)});
        world.add(container);
        std::size_t hits = 0;
        for (int k = 0; k < 40; ++k) {
            ObjectDef held;
            held.name = "held-" + std::to_string(k);
            held.flags = kCollisions;
            held.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), 1.0)});
            double d = 4.0 + 0.15 * k;  // from well inside to past every wall, along the diagonal
            held.transform.setPosition(Vec2(d, d));
            world.add(held);
        }
        std::vector<GameObject> objects(world.objects().begin(), world.objects().end());
        std::vector<std::uint32_t> indices(objects.size()), others;
        for (std::uint32_t i = 0; i < indices.size(); ++i) indices[i] = i;
        for (Accuracy accuracy : kAllAccuracies) {
            StepData data;
            data.build({.objects = objects,
                        .candidates = indices,
                        .containers = true,
                        .accuracy = accuracy,
                        .fastStarts = {}},
                       others);
            ASSERT_EQ(data.containerSlots.size(), 1u);
            for (std::uint32_t held = 1; held < data.size(); ++held) {
                if (!testPair(data.poses[0], data.poses[held], accuracy).hit) continue;
                ++hits;
                EXPECT_LE(data.containerGap(0, held), 0.0)
                    << accuracyName(accuracy) << " interpolate " << interpolate << " " << objects[held].name;
            }
        }
        EXPECT_GT(hits, 40u);
    }
}

}  // namespace
}  // namespace polar
