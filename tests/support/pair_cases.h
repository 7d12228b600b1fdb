#pragma once
// What the narrow phase's tests share: random radii and linear maps that reach the hard corners of
// the outline tables (one sample, ties, a gap just under half a turn, mirrors, extreme scales), and a
// comparison of two pair outcomes to the bit.
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <iterator>
#include <random>
#include <vector>

#include "bits.h"
#include "polar/bound.h"
#include "polar/collision.h"
#include "polar/math.h"

namespace polar::testing {

// Random radii: 1 to 200 samples at random or evenly spaced angles (0 exactly included), or with one
// gap just under half a turn. `interpolate` says whether the file flag asks for chord.
inline Bound randomRadii(std::mt19937_64& rng, bool& interpolate) {
    std::uniform_real_distribution<double> unit(0, 1);
    static const int kCounts[] = {1, 2, 3, 4, 5, 8, 17, 64, 200};
    int count = kCounts[rng() % std::size(kCounts)];
    std::vector<RadiusSample> samples;
    int kind = static_cast<int>(rng() % 3);
    for (int k = 0; k < count; ++k) {
        double angle = kind == 0 ? unit(rng) * kTwoPi : kTwoPi * k / count;
        if (kind == 2)
            angle = k == 0 ? 0.0
                           : (kPi - 1e-9) +
                                 (kPi + 1e-9) * (k - 1) / std::max(1, count - 1);  // a gap just under π
        samples.push_back({angle, 0.5 + 50 * unit(rng)});
    }
    std::sort(samples.begin(), samples.end(), [](auto& a, auto& b) { return a.angle < b.angle; });
    samples.erase(
        std::unique(samples.begin(), samples.end(), [](auto& a, auto& b) { return a.angle == b.angle; }),
        samples.end());
    Bound probe(Vec2::Zero(), samples, false);
    interpolate = probe.chordDefined() && samples.size() >= 3 && rng() % 2 == 0;
    return Bound(Vec2::Zero(), samples, interpolate);
}

// A random linear part R·S: any rotation, scales from 1e-3 to 1e3, uniform or not, mirrored or not.
inline Mat2 randomLinear(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> unit(0, 1);
    static const double kScales[] = {1.0, 0.2, 0.7, 2.5, 5.0, 1e-3, 1e3};
    double sx = kScales[rng() % std::size(kScales)] * (unit(rng) < 0.3 ? -1 : 1);
    double sy = rng() % 3 == 0 ? sx : kScales[rng() % std::size(kScales)] * (unit(rng) < 0.3 ? -1 : 1);
    return rotationMatrix(unit(rng) * kTwoPi) * Vec2(sx, sy).asDiagonal();
}

// Every field of two outcomes, doubles compared as bits (signed zeros and NaN payloads included);
// `k` names the case in a failure.
inline void expectSameBits(const PairTest& batched, const PairTest& single, std::size_t k) {
    EXPECT_EQ(bits(batched.normal.x()), bits(single.normal.x())) << k;
    EXPECT_EQ(bits(batched.normal.y()), bits(single.normal.y())) << k;
    EXPECT_EQ(bits(batched.distance), bits(single.distance)) << k;
    EXPECT_EQ(bits(batched.ra), bits(single.ra)) << k;
    EXPECT_EQ(bits(batched.rb), bits(single.rb)) << k;
    EXPECT_EQ(bits(batched.penetration), bits(single.penetration)) << k;
    EXPECT_EQ(batched.kind, single.kind) << k;
    EXPECT_EQ(batched.hit, single.hit) << k;
    EXPECT_EQ(batched.radiiA, single.radiiA) << k;
    EXPECT_EQ(batched.radiiB, single.radiiB) << k;
}

}  // namespace polar::testing
