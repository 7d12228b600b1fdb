// testPairs (pair_batch.cpp) against testPair (collision.cpp) one pair at a time: the same outcome
// to the bit, at every accuracy level, on random pairs of single and compound radii and containers,
// on nearest-rule ties, at scales that leave the lanes' safe range, and across batch boundaries.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "narrow_phase/pair_test.h"
#include "pair_cases.h"
#include "polar/collision.h"

namespace polar {
namespace {

using testing::expectSameBits;
using testing::randomLinear;
using testing::randomRadii;

TEST(TestPairs, SameBitsAsTestPairOnePairAtATime) {
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0, 1);
    // Objects near each other: single and compound radii, containers, and scales so extreme that the
    // batched lanes must hand the pair back to testPair (products out of range, a singular map).
    std::vector<Bounds> bounds(300);
    std::vector<ObjectPose> poses;
    for (Bounds& b : bounds) {
        bool interpolate;
        b.push_back(randomRadii(rng, interpolate));
        if (rng() % 4 == 0) b.push_back(Bound(Vec2(30 * unit(rng), 0), 5 + 10 * unit(rng)));
        ObjectFlags flags = kCollisions;
        if (rng() % 8 == 0) flags |= kContainer;
        Mat2 linear = randomLinear(rng);
        if (rng() % 40 == 0) linear *= rng() % 2 ? 1e-150 : 1e150;
        if (rng() % 60 == 0) linear.setZero();
        Vec2 position(200 * unit(rng), 200 * unit(rng));
        if (rng() % 30 == 0 && !poses.empty()) position = poses.back().position;  // coincident
        poses.emplace_back(position, linear, &b, flags);
    }
    std::vector<PosePair> pairs;
    // Nearest-rule ties: B exactly on a bisector of A's samples (every 45° from 0 by the samples'
    // symmetry), where the batched lanes must hand the radius to the plain rule as testPair does.
    Bounds square{Bound(Vec2::Zero(), {{0.0, 10.0}, {kPi / 2, 20.0}, {kPi, 30.0}, {1.5 * kPi, 40.0}}, false)};
    Bounds dot{Bound(Vec2::Zero(), 1.0)};
    std::vector<ObjectPose> ties;
    ties.reserve(16);
    for (double scale : {1.0, 2.0}) {
        for (Vec2 along : {Vec2(1, 1), Vec2(-1, 1), Vec2(-1, -1), Vec2(1, -1)}) {
            ties.emplace_back(Vec2(0, 0), Mat2(scale * Mat2::Identity()), &square, kCollisions);
            ties.emplace_back(25.0 * along, Mat2::Identity(), &dot, kCollisions);
        }
    }
    for (std::size_t k = 0; k < ties.size(); k += 2) {
        pairs.push_back({&ties[k], &ties[k + 1]});
        pairs.push_back({&ties[k + 1], &ties[k]});  // the tie on B's side
    }
    for (int k = 0; k < 3001; ++k) {  // not a multiple of any batch size
        std::size_t i = rng() % poses.size(), j = rng() % poses.size();
        if (i == j || (poses[i].flags & poses[j].flags & kContainer)) continue;
        pairs.push_back({&poses[std::min(i, j)], &poses[std::max(i, j)]});
    }
    for (Accuracy level : kAllAccuracies) {
        std::vector<PairTest> batched(pairs.size());
        testPairs(pairs, level, batched.data());
        int hits = 0;
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            expectSameBits(batched[k], testPair(*pairs[k].a, *pairs[k].b, level), k);
            hits += batched[k].hit;
        }
        EXPECT_GT(hits, 100) << accuracyName(level);  // the cases reach both verdicts
        EXPECT_LT(hits, static_cast<int>(pairs.size()) - 100) << accuracyName(level);
    }
    testPairs({}, Accuracy::Chord, nullptr);  // no pairs: nothing read or written
}

}  // namespace
}  // namespace polar
