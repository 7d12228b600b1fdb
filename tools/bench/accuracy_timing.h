#pragma once
// The accuracy benchmark's timings, each the median ns per item over 301 repetitions: the levels,
// chord by kind of pair, the floor of a chord contact and the pose.
#include <array>
#include <cstddef>
#include <vector>

#include "accuracy_pairs.h"
#include "narrow_phase/pair_test.h"
#include "polar/collision.h"

namespace polar::bench {

// Up to 1024 tests near contact, poses laid out contiguously as the world would have them.
struct TimedSet {
    TimedSet() = default;
    TimedSet(TimedSet&&) = default;  // keeps `pairs` pointing into `a` and `b`; a copy would not
    TimedSet& operator=(TimedSet&&) = default;

    std::vector<ObjectPose> a, b;
    std::vector<PosePair> pairs;  // {&a[i], &b[i]}
    std::vector<PairTest> tests;  // the outcome array every timing writes into
};
// The timing set: the first 1024 samples, posed.
TimedSet timedSetOf(const std::vector<Sprite>& sprites, const std::vector<Placement>& placements,
                    const std::vector<Sample>& samples);

// One level over the timed set: through testPairs, as the world's detector runs it; with
// `oneAtATime`, testPair called pair by pair instead, for comparison; with `plain`, the plain
// formulas pair by pair.
double timeLevel(TimedSet& timed, Accuracy accuracy, bool plain, bool oneAtATime = false);

// chord on one kind of pair alone, that kind's poses in arrays of their own.
struct KindTiming {
    const char* name;
    std::vector<ObjectPose> a, b;
    double ns = 0;
};
// chord by kind of pair (one bound each, several radii, container): where the average goes.
std::array<KindTiming, 3> timeChordByKind(TimedSet& timed);

// What a chord contact cannot do without, one pair at a time.
struct FloorTiming {
    double readWriteNs = 0;  // reading the two poses, u and both bound-space directions, writing the outcome
    double lookUpNs = 0;     // the same with the two sector look-ups
};
// The floor on the single-radii contacts (`single`, the first kind of timeChordByKind).
FloorTiming timeFloor(TimedSet& timed, const KindTiming& single);

// Building a pose (once per object per step in the world).
double timePose(const TimedSet& timed);

}  // namespace polar::bench
