// The numerical hard cases of the narrow phase, at every accuracy level: tangency to the last ulp,
// resting contact, angle wrap, coincident centres, degenerate and mirrored transforms, far from the
// origin, long spin, thin shapes, extreme sample counts, and no NaN or infinity out of fuzzed scenes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "narrow_phase/pair_test.h"
#include "polar/collision.h"
#include "polar/world.h"
#include "world/numeric_guard.h"

namespace polar {
namespace {

constexpr Accuracy kLevels[] = {Accuracy::Bounds, Accuracy::Circle,   Accuracy::Nearest,
                                Accuracy::Chord,  Accuracy::AllRadii, Accuracy::Exact};

std::shared_ptr<const Bounds> share(Bounds b) {
    return std::make_shared<const Bounds>(std::move(b));
}

// A lumpy chord outline: 24 samples, radius 8 … 12.
Bound lumpy(bool interpolate = true, Vec2 centre = Vec2::Zero()) {
    std::vector<DegreeSample> s;
    for (int k = 0; k < 24; ++k) s.push_back({15.0 * k, 10 + 2 * std::sin(3.0 * k) * ((k % 2) ? 1 : -1)});
    return Bound::fromDegrees(centre, s, interpolate);
}

ObjectPose pose(const Bounds& b, Vec2 position, double rotation = 0, Vec2 scale = Vec2(1, 1),
                ObjectFlags flags = kCollisions) {
    return ObjectPose(position, Transform(position, rotation, scale).linear(), &b, flags);
}

// ---- Tangency

TEST(Tangency, TouchingIsAHitAndOneUlpApartIsNot) {
    // Documented answer: the rule compares D = |u|² with (rA + rB)² in doubles, and touching counts.
    // For circles at exactly representable distances that means: hit at the sum, miss one ulp past it.
    Bounds small{Bound(Vec2::Zero(), 10.0)}, big{Bound(Vec2::Zero(), 20.0)};
    for (Accuracy level : kLevels) {
        for (Vec2 axis : {Vec2(1, 0), Vec2(0, 1), Vec2(-1, 0), Vec2(0, -1)}) {
            double at = 30.0, past = std::nextafter(30.0, 100.0), short_ = std::nextafter(30.0, 0.0);
            EXPECT_TRUE(testPair(pose(small, Vec2::Zero()), pose(big, at * axis), level).hit)
                << accuracyName(level);
            EXPECT_TRUE(testPair(pose(small, Vec2::Zero()), pose(big, short_ * axis), level).hit)
                << accuracyName(level);
            if (level == Accuracy::Exact) continue;  // exact decides within rounding of the tangency (below)
            EXPECT_FALSE(testPair(pose(small, Vec2::Zero()), pose(big, past * axis), level).hit)
                << accuracyName(level);
        }
    }
    // The exact test resolves gaps down to rounding of the outline's own size: 1e-12 relative.
    for (double gap : {1e-9, 1e-11}) {
        EXPECT_FALSE(
            testPair(pose(small, Vec2::Zero()), pose(big, Vec2(30 * (1 + gap), 0)), Accuracy::Exact).hit)
            << gap;
        EXPECT_TRUE(
            testPair(pose(small, Vec2::Zero()), pose(big, Vec2(30 * (1 - gap), 0)), Accuracy::Exact).hit)
            << gap;
    }
    // Far from the origin the same positions stay exact (1e6 + 30 is a double), so does the answer.
    Vec2 far(1e6, -1e6);
    EXPECT_TRUE(testPair(pose(small, far), pose(big, far + Vec2(30, 0))).hit);
    EXPECT_FALSE(
        testPair(pose(small, far), pose(big, far + Vec2(std::nextafter(1e6 + 30, 2e6) - 1e6, 0))).hit);
}

TEST(Tangency, TheVerdictIsAFunctionOfTheDistanceAlone) {
    // No hit/miss flicker from rounding: sweeping the distance across the tangency in ulp steps,
    // once the verdict turns to miss it stays a miss (for every level and a turned, scaled pair).
    Bounds a{lumpy()}, b{lumpy(false)};
    ObjectPose pa = pose(a, Vec2(3, 4), 0.3, Vec2(1.5, 1.5));
    Vec2 dir = Vec2(0.6, 0.8);
    auto hitAt = [&](double d, Accuracy level) {
        return testPair(pa, pose(b, Vec2(3, 4) + d * dir, 1.1), level).hit;
    };
    // The contact distance by bisection: a hit there, a miss one ulp farther.
    auto contactDistance = [&](Accuracy level) {
        double lo = 0, hi = 100;
        for (int i = 0; i < 200; ++i) {
            double mid = 0.5 * (lo + hi);
            if (mid <= lo || mid >= hi) break;
            (hitAt(mid, level) ? lo : hi) = mid;
        }
        return lo;
    };
    for (Accuracy level : kLevels) {
        if (level == Accuracy::Exact) continue;  // exact: to its own resolution, below
        // Walk 200 ulps either side of the contact.
        bool missed = false;
        double d = contactDistance(level);
        for (int i = 0; i < 200; ++i) d = std::nextafter(d, 0.0);
        for (int i = 0; i < 400; ++i, d = std::nextafter(d, 100.0)) {
            bool hit = hitAt(d, level);
            if (missed) {
                ASSERT_FALSE(hit) << accuracyName(level) << " " << i;
            }
            missed = missed || !hit;
        }
        EXPECT_TRUE(missed) << accuracyName(level);
    }

    // Exact resolves the overlap to rounding of the outlines' own size, 1e-12 relative (see
    // TouchingIsAHitAndOneUlpApartIsNot): walking ±2e-11 of its contact in steps of 1e-13, it hits
    // at the start, misses at the end, and hits nowhere more than 1e-12 past its first miss.
    double exact = contactDistance(Accuracy::Exact);
    double firstMiss = INFINITY;
    for (int k = -200; k <= 200; ++k) {
        double d = exact * (1 + k * 1e-13);
        bool hit = hitAt(d, Accuracy::Exact);
        if (k == -200) {
            EXPECT_TRUE(hit) << "2e-11 inside the contact";
        }
        if (k == 200) {
            EXPECT_FALSE(hit) << "2e-11 outside the contact";
        }
        if (!hit) firstMiss = std::min(firstMiss, d);
        if (hit) {
            ASSERT_LE(d, firstMiss + 1e-12 * exact) << k;
        }
    }
    // And it holds the rule's hits (a rule hit is a sure overlap): wherever the bounds rule hits,
    // up to its own contact distance, exact hits too, so its contact is no nearer.
    double rule = contactDistance(Accuracy::Bounds);
    EXPECT_GE(exact, rule);
    for (int k = 0; k <= 100; ++k) {
        double d = rule * (1 - k * 1e-3);  // the rule's contact and 10% inside it
        ASSERT_TRUE(hitAt(d, Accuracy::Bounds)) << k;
        ASSERT_TRUE(hitAt(d, Accuracy::Exact)) << k;
    }
}

// A ball pushed into a fixed (ghost) wall with no bounce comes to rest touching it; from then on it
// is a hit in every step, never flickering to a miss.
void expectRestingContactHolds(Accuracy level, Vec2 origin, Vec2 dir) {
    World world(WorldDef{kEffectPhysics | kEffectCollisions | kEffectResponse, 0.0, level});
    ObjectDef wall;
    wall.name = "wall";
    wall.bounds = share({lumpy()});
    wall.transform = Transform(origin, 0.4, Vec2(3, 3));
    wall.flags = kCollisions | kGhost;
    world.add(wall);
    ObjectDef ball;
    ball.name = "ball";
    ball.bounds = share({lumpy(false)});
    ball.transform = Transform(origin + 60 * dir, 0.0, Vec2(1, 1.3));
    ball.velocity = -40 * dir;
    ball.flags = kCollisions | kPhysics;
    world.add(ball);
    int firstHit = -1;
    for (int step = 0; step < 600; ++step) {
        world.step(1.0 / 60);
        bool hit = !world.hits().empty();
        if (hit && firstHit < 0) firstHit = step;
        if (firstHit >= 0) {
            ASSERT_TRUE(hit) << accuracyName(level) << " flickered at step " << step;
        }
        // Keep pressing toward the wall, as a resting object under a steady push.
        world.objects()[1].velocity = -5 * dir;
    }
    EXPECT_GE(firstHit, 0) << accuracyName(level);
}

TEST(Tangency, RestingContactDoesNotFlicker) {
    for (Accuracy level : kLevels) {
        expectRestingContactHolds(level, Vec2::Zero(), Vec2(1, 0));
        expectRestingContactHolds(level, Vec2(1e6, -1e6), Vec2(0.6, 0.8));  // off the axes, far out
    }
}

// ---- Angles

TEST(Angles, WrapAndExactSampleDirections) {
    // Samples straddling 0/360 and given as −10 and 370 (= 350 and 10): B placed exactly along each
    // sample direction and across the wrap; every level agrees with the plain formulas.
    Bounds a{Bound::fromDegrees(Vec2::Zero(), {{-10, 30}, {370, 20}, {120, 25}, {240, 22}}, true)};
    Bounds b{Bound(Vec2::Zero(), 5.0)};
    for (double deg : {350.0, 10.0, 120.0, 240.0, 0.0, 360.0, 359.9999999, 0.0000001, -0.0}) {
        double phi = degToRad(deg);
        Vec2 dir(trig::cos(phi), trig::sin(phi));
        double r = a[0].radius(phi);
        for (double k : {0.999999, 1.000001}) {
            ObjectPose pa = pose(a, Vec2::Zero()), pb = pose(b, (r + 5) * k * dir);
            for (Accuracy level : {Accuracy::Bounds, Accuracy::Chord, Accuracy::Nearest}) {
                PairTest fast = testPair(pa, pb, level), plain = testPairPlain(pa, pb, level);
                EXPECT_NEAR(fast.ra, plain.ra, 1e-9 * plain.ra) << deg;
                EXPECT_EQ(fast.hit, plain.hit) << deg << " " << accuracyName(level);
            }
            EXPECT_EQ(testPair(pa, pb).hit, k < 1) << deg;
            if (k < 1) {
                EXPECT_TRUE(testPair(pa, pb, Accuracy::Exact).hit) << deg;  // the rule's hits are exact's
            }
        }
    }
}

// ---- Coincident centres

TEST(CoincidentCentres, ContactAndContainerPairs) {
    Bounds shape{lumpy()}, dot{Bound(Vec2::Zero(), 1.0)}, huge{Bound(Vec2::Zero(), 100.0)};
    for (Accuracy level : kLevels) {
        PairTest t = testPair(pose(shape, Vec2(5, 5)), pose(dot, Vec2(5, 5)), level);
        EXPECT_TRUE(t.hit) << accuracyName(level);
        EXPECT_TRUE(isFinite(t)) << accuracyName(level);
        EXPECT_EQ(t.normal, Vec2(1, 0)) << accuracyName(level);
        // A small object at the container's centre is inside; a bigger one is through the wall.
        ObjectPose box = pose(shape, Vec2(5, 5), 0.2, Vec2(2, 2), kCollisions | kContainer);
        PairTest in = testPair(box, pose(dot, Vec2(5, 5)), level);
        PairTest out = testPair(pose(huge, Vec2(5, 5)), box, level);
        EXPECT_FALSE(in.hit) << accuracyName(level);
        EXPECT_TRUE(out.hit) << accuracyName(level);
        EXPECT_TRUE(isFinite(in) && isFinite(out)) << accuracyName(level);
    }
}

// ---- Degenerate transforms

// Random near-contact pairs (both single-radii and a two-radii body), with a relative margin from
// the tangency so that rounding cannot matter; returns each pair's verdict under `transform`.
struct Pair {
    Bounds a, b;
    Vec2 pa, pb;
    double ra, rb;
    Vec2 sa, sb;
    ObjectFlags fa, fb;
};

std::vector<Pair> nearContactPairs(int count, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Pair> pairs;
    while (static_cast<int>(pairs.size()) < count) {
        Pair p;
        p.a = {lumpy(rng() % 2 == 0)};
        p.b = {lumpy(rng() % 2 == 0, Vec2(1, -1))};
        if (rng() % 3 == 0) p.b.push_back(Bound(Vec2(9, 0), 4.0));
        p.ra = unit(rng) * kTwoPi;
        p.rb = unit(rng) * kTwoPi;
        p.sa = Vec2(0.5 + unit(rng), 0.5 + unit(rng));
        p.sb = Vec2(0.5 + unit(rng), 0.5 + unit(rng));
        if (rng() % 3 == 0) p.sb.x() = -p.sb.x();
        p.fa = rng() % 5 == 0 ? kCollisions | kContainer : kCollisions;
        p.fb = kCollisions;
        // Positions on a grid of 1/64 so that moving them by whole numbers stays exact.
        p.pa = Vec2(std::round(64 * (40 * unit(rng) - 20)) / 64, std::round(64 * (40 * unit(rng) - 20)) / 64);
        double angle = unit(rng) * kTwoPi, d = (p.fa & kContainer ? 8 : 20) + 8 * unit(rng);
        p.pb =
            p.pa + Vec2(std::round(64 * d * std::cos(angle)) / 64, std::round(64 * d * std::sin(angle)) / 64);
        pairs.push_back(p);
    }
    return pairs;
}

// Each level's verdicts for the pairs after mapping the whole scene by x → m·x + offset (m a
// similarity, possibly mirrored, applied to positions and linear parts alike).
std::vector<bool> verdicts(const std::vector<Pair>& pairs, Accuracy level, const Mat2& m, Vec2 offset) {
    std::vector<bool> out;
    for (const Pair& p : pairs) {
        Mat2 la = m * Transform(Vec2::Zero(), p.ra, p.sa).linear(),
             lb = m * Transform(Vec2::Zero(), p.rb, p.sb).linear();
        ObjectPose a(m * p.pa + offset, la, &p.a, p.fa), b(m * p.pb + offset, lb, &p.b, p.fb);
        PairTest t = testPair(a, b, level);
        EXPECT_TRUE(isFinite(t));
        out.push_back(t.hit);
    }
    return out;
}

// The pairs whose verdict is robust: the same when B is nudged by ±1e-7 of the scene size.
std::vector<bool> robust(const std::vector<Pair>& pairs, Accuracy level) {
    std::vector<bool> keep;
    for (const Pair& p : pairs) {
        bool same = true, first = true, verdict = false;
        for (Vec2 nudge : {Vec2(0, 0), Vec2(3e-6, 0), Vec2(-3e-6, 0), Vec2(0, 3e-6), Vec2(0, -3e-6)}) {
            Pair q = p;
            q.pb += nudge;
            bool v = verdicts({q}, level, Mat2::Identity(), Vec2::Zero())[0];
            if (!first && v != verdict) same = false;
            verdict = v;
            first = false;
        }
        keep.push_back(same);
    }
    return keep;
}

TEST(DegenerateTransforms, ScaledMirroredAndFarScenesGiveTheSameVerdicts) {
    std::vector<Pair> pairs = nearContactPairs(150, 99);
    Mat2 mirrorX = Vec2(-1, 1).asDiagonal(), mirrorBoth = -Mat2::Identity();
    for (Accuracy level : kLevels) {
        std::vector<bool> base = verdicts(pairs, level, Mat2::Identity(), Vec2::Zero());
        std::vector<bool> keep = robust(pairs, level);
        int hits = 0, compared = 0;
        struct Variant {
            const char* name;
            Mat2 m;
            Vec2 offset;
        };
        const Variant variants[] = {
            {"scale 1e-6", Mat2::Identity() * 1e-6, Vec2::Zero()},
            {"scale 1e6", Mat2::Identity() * 1e6, Vec2::Zero()},
            {"mirrored x", mirrorX, Vec2::Zero()},
            {"mirrored both", mirrorBoth, Vec2::Zero()},
            {"at 1e6", Mat2::Identity(), Vec2(1e6, -1e6)},
            {"at 1e7", Mat2::Identity(), Vec2(-1e7, 1e7)},
        };
        for (const Variant& v : variants) {
            std::vector<bool> moved = verdicts(pairs, level, v.m, v.offset);
            for (std::size_t i = 0; i < pairs.size(); ++i) {
                if (!keep[i]) continue;
                EXPECT_EQ(moved[i], base[i]) << accuracyName(level) << " " << v.name << " pair " << i;
                ++compared;
                hits += base[i];
            }
        }
        EXPECT_GT(compared, 600) << accuracyName(level);
        EXPECT_GT(hits, compared / 10) << accuracyName(level);
        EXPECT_LT(hits, compared * 9 / 10) << accuracyName(level);
    }
}

TEST(DegenerateTransforms, ScaleZeroIsAPointAndNothingIsNaN) {
    Bounds shape{lumpy()};
    for (Accuracy level : kLevels) {
        for (Vec2 scale : {Vec2(0, 0), Vec2(0, 2), Vec2(2, 0), Vec2(1e-300, 1e-300)}) {
            ObjectPose zero = pose(shape, Vec2(100, 0), 0.7, scale);
            PairTest near = testPair(pose(shape, Vec2(95, 0)), zero, level);  // inside the other
            PairTest far = testPair(pose(shape, Vec2(0, 0)), zero, level);
            EXPECT_TRUE(isFinite(near) && isFinite(far)) << accuracyName(level);
            EXPECT_TRUE(near.hit) << accuracyName(level);
            EXPECT_FALSE(far.hit) << accuracyName(level);
            EXPECT_EQ(far.rb, 0.0) << accuracyName(level);
            PairTest both = testPair(zero, pose(shape, Vec2(100, 0), 0, scale), level);
            EXPECT_TRUE(isFinite(both) && both.hit) << accuracyName(level);  // two points at one place
        }
        // Tiny and huge but regular: finite, and the same verdict as at scale 1 scaled.
        for (double s : {1e-6, 1e6}) {
            PairTest t = testPair(pose(shape, Vec2(0, 0), 0, Vec2(s, s)),
                                  pose(shape, Vec2(19 * s, 0), 0.1, Vec2(s, s)), level);
            PairTest u = testPair(pose(shape, Vec2(0, 0), 0, Vec2(1, 1)),
                                  pose(shape, Vec2(19, 0), 0.1, Vec2(1, 1)), level);
            EXPECT_TRUE(isFinite(t));
            EXPECT_EQ(t.hit, u.hit) << accuracyName(level) << " " << s;
            EXPECT_NEAR(t.ra, u.ra * s, 1e-9 * u.ra * s) << accuracyName(level);
        }
    }
}

// ---- Long spin

TEST(LongSpin, TenMillionStepsDoNotDrift) {
    Transform t(Vec2(1e6, 2), 0.0, Vec2(2, -0.5));
    const double spin = 0.0123456789;  // radians per step; no multiple of it is a multiple of 2π
    for (int i = 0; i < 10000000; ++i) t.rotate(spin);
    Mat2 l = t.linear();
    // Still a rotation times the scale: orthogonal columns of lengths 2 and 0.5, det = −1.
    EXPECT_NEAR(l.col(0).dot(l.col(1)), 0.0, 1e-12);
    EXPECT_NEAR(l.col(0).norm(), 2.0, 1e-12);
    EXPECT_NEAR(l.col(1).norm(), 0.5, 1e-12);
    EXPECT_NEAR(l(0, 0) * l(1, 1) - l(0, 1) * l(1, 0), -1.0, 1e-12);
    // And at the angle the steps add up to (10⁷ additions of a rounded spin: error ~1e-6 rad).
    EXPECT_NEAR(std::remainder(t.rotation() - 1e7 * spin, kTwoPi), 0.0, 1e-5);
    EXPECT_EQ(t.position(), Vec2(1e6, 2));
}

// ---- Thin shapes

TEST(ThinShapes, AspectOneToAThousand) {
    // A square outline scaled to 2000 × 2: a rod. Two rods meet in a T: B stands on A's top side.
    Bounds square{Bound::fromDegrees(
        Vec2::Zero(),
        {{45, std::sqrt(2.0)}, {135, std::sqrt(2.0)}, {225, std::sqrt(2.0)}, {315, std::sqrt(2.0)}}, true)};
    Vec2 rod(1000, 1);
    for (double gap : {-1e-6, 1e-6}) {
        ObjectPose a = pose(square, Vec2(0, 0), 0, rod);
        ObjectPose b = pose(square, Vec2(500, 1001 + gap), kHalfPi, rod);  // spans y ∈ [1 + gap, 2001 + gap]
        EXPECT_FALSE(testPair(a, b).hit);  // the line of centres misses both rods' contact
        EXPECT_EQ(testPair(a, b, Accuracy::Exact).hit, gap < 0) << gap;
        EXPECT_EQ(testPair(b, a, Accuracy::Exact).hit, gap < 0) << gap;
    }
    // Along the rod, the rule itself is exact: end to end at 2000 apart.
    for (double gap : {-1e-9, 1e-9}) {
        ObjectPose a = pose(square, Vec2(0, 0), 0, rod), b = pose(square, Vec2(2000 * (1 + gap), 0), 0, rod);
        for (Accuracy level : {Accuracy::Bounds, Accuracy::Chord, Accuracy::AllRadii, Accuracy::Exact})
            EXPECT_EQ(testPair(a, b, level).hit, gap < 0) << accuracyName(level) << " " << gap;
    }
    // A rod as a container: a ball just inside its long side, then just through it.
    ObjectPose box = pose(square, Vec2(0, 0), 0.25, Vec2(1000, 10), kCollisions | kContainer);
    Bounds ball{Bound(Vec2::Zero(), 1.0)};
    Vec2 up = rotationMatrix(0.25) * Vec2(0, 1), along = rotationMatrix(0.25) * Vec2(1, 0);
    for (double gap : {-1e-6, 1e-6}) {
        ObjectPose b = pose(ball, 600 * along + (9 + gap) * up);
        EXPECT_EQ(testPair(box, b, Accuracy::Exact).hit, gap > 0) << gap;
    }
}

// ---- Sample counts

TEST(SampleCounts, OneAndFourThousandSamplesAndGapsJustUnderHalfATurn) {
    std::vector<RadiusSample> many;
    for (int k = 0; k < 4096; ++k)
        many.push_back({kTwoPi * k / 4096, 20 + 3 * std::sin(11.0 * k * kTwoPi / 4096)});
    Bounds dense{Bound(Vec2::Zero(), many, true)}, denseNearest{Bound(Vec2::Zero(), many, false)};
    Bounds one{Bound(Vec2::Zero(), 7.0)};
    Bounds wide{Bound::fromDegrees(Vec2::Zero(), {{0, 10}, {179.999999, 10}, {270, 10}}, true)};
    std::mt19937_64 rng(4);
    std::uniform_real_distribution<double> unit(0, 1);
    for (int i = 0; i < 300; ++i) {
        double angle = unit(rng) * kTwoPi, d = 15 + 20 * unit(rng);
        Vec2 where = d * Vec2(std::cos(angle), std::sin(angle));
        for (const Bounds* a : {&dense, &denseNearest, &one, &wide}) {
            for (const Bounds* b : {&dense, &one, &wide}) {
                ObjectPose pa = pose(*a, Vec2::Zero(), 0.3, Vec2(1.2, 0.9)), pb = pose(*b, where, 1.1);
                PairTest fast = testPair(pa, pb), plain = testPairPlain(pa, pb);
                ASSERT_NEAR(fast.ra, plain.ra, 1e-6 * plain.ra + 1e-12);
                ASSERT_NEAR(fast.rb, plain.rb, 1e-6 * plain.rb + 1e-12);
                bool exact = testPair(pa, pb, Accuracy::Exact).hit;
                if (fast.hit) {
                    ASSERT_TRUE(exact);  // the rule's hits are exact hits
                }
                for (Accuracy level : kLevels) ASSERT_TRUE(isFinite(testPair(pa, pb, level)));
            }
        }
    }
    // Just under half a turn: the chord across the gap passes within a hair of the centre.
    ObjectPose pw = pose(wide, Vec2::Zero());
    EXPECT_LT(testPair(pw, pose(one, Vec2(0, 7.0001))).ra, 1e-5);
    EXPECT_FALSE(testPair(pw, pose(one, Vec2(0, 7.0001))).hit);
    EXPECT_TRUE(testPair(pw, pose(one, Vec2(0, 6.9999))).hit);
    EXPECT_FALSE(testPair(pw, pose(one, Vec2(0, 7.0001)), Accuracy::Exact).hit);
}

// ---- No NaN or infinity

TEST(NoNaN, FuzzedScenesStayFinite) {
    std::mt19937_64 rng(31337);
    std::uniform_real_distribution<double> unit(0, 1);
    auto pick = [&](std::initializer_list<double> values) {
        return *(values.begin() + rng() % values.size());
    };
    int steps = 0, hits = 0;
    for (int scene = 0; scene < 40; ++scene) {
        WorldDef def;
        def.effects = kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers;
        def.restitution = unit(rng);
        def.accuracy = kLevels[rng() % std::size(kLevels)];
        World world(def);
        Vec2 origin = Vec2(pick({0.0, 1e6, -1e7}), pick({0.0, 1e6, 1e7}));
        int count = 3 + static_cast<int>(rng() % 6);
        for (int i = 0; i < count; ++i) {
            ObjectDef o;
            o.name = "o" + std::to_string(i);
            Bounds b;
            int radii = 1 + static_cast<int>(rng() % 3);
            for (int r = 0; r < radii; ++r) {
                int samples = static_cast<int>(pick({1, 3, 5, 16, 4096}));
                std::vector<RadiusSample> s;
                for (int k = 0; k < samples; ++k)
                    s.push_back({kTwoPi * (k + 0.3 * unit(rng)) / samples,
                                 pick({0.001, 1.0, 10.0, 1000.0}) * (0.5 + unit(rng))});
                bool chord = samples >= 3 && rng() % 2;
                b.push_back(Bound(Vec2(pick({0.0, 5.0}) * unit(rng), 0), s, chord));
            }
            o.bounds = share(b);
            double s = pick({0.0, 1e-6, 1.0, 2.0, 1e6});
            Vec2 scale(s * (unit(rng) < 0.3 ? -1 : 1), pick({s, 0.5 * s, 0.0}) * (unit(rng) < 0.3 ? -1 : 1));
            o.transform =
                Transform(origin + Vec2(60 * unit(rng) - 30, 60 * unit(rng) - 30), unit(rng) * kTwoPi, scale);
            o.velocity =
                Vec2(pick({0.0, 10.0, 1e3}) * (unit(rng) - 0.5), pick({0.0, 10.0, 1e3}) * (unit(rng) - 0.5));
            o.spin = pick({0.0, 1.0, 100.0}) * (unit(rng) - 0.5);
            o.damping = pick({0.0, 0.1, 10.0});
            o.flags = kCollisions;
            if (rng() % 2) o.flags |= kPhysics;
            if (rng() % 4 == 0) o.flags |= kGhost;
            if (i == 0 && rng() % 2) o.flags |= kContainer;
            if (rng() % 6 == 0) o.flags |= kIgnoreContainers;
            world.add(o);
        }
        for (int step = 0; step < 60; ++step) {
            world.step(1.0 / 60);  // in Debug, the world itself asserts the same at the step boundary
            ++steps;
            for (const GameObject& o : world.objects())
                ASSERT_TRUE(isFinite(o)) << "scene " << scene << " step " << step;
            for (const PairReport& h : world.hits()) ASSERT_TRUE(isFinite(h.test)) << "scene " << scene;
            hits += static_cast<int>(world.hits().size());
        }
    }
    EXPECT_EQ(steps, 40 * 60);
    EXPECT_GT(hits, 100);  // the scenes did collide
}

}  // namespace
}  // namespace polar
