#pragma once
// The narrow phase's pair test on per-step poses: what the world's collision loop calls.
//
// A pair's path from World::step to its verdict, call by call, is listed in narrow_phase/README.md.
// The lanes call the same functions (pair_rule.h, shapes/outline.h) in the same order, so testPairs
// gives testPair's bits (tests/engine/narrow_phase/pair_batch_test.cpp).
#include <cstdint>
#include <span>

#include "polar/accuracy.h"
#include "polar/collision.h"
#include "polar/object_flags.h"
#include "shapes/outline.h"

namespace polar {

// What a pair test needs from one object, computed once per object per step.
//
// Why a LinearMap? Every pair the object takes part in reads its bounds in world directions, which
// needs L⁻¹; computing it (and |det L|, the stretch bounds, the bounding circle) once per object per
// step instead of once per pair is what makes the pair test cheap. The constructor derives all of
// it from `linear`: build a new pose rather than editing `linear` in place.
struct ObjectPose : LinearMap {
    // The small fields first, so that they fill LinearMap's tail padding: 112 bytes in all.
    bool onlyChordByFlag = false;  // whether its bounds file asks for chord (interpolate)
    ObjectFlags flags = 0;
    Vec2 position = Vec2::Zero();
    // For the common one-bound object: L·centre and the chord outline of its bound (null when it
    // has none: several bounds, or samples that the chord rule does not define), so that a pair test
    // reads them without a chain of loads.
    Vec2 onlyCentreOffset = Vec2::Zero();
    const Bounds* bounds = nullptr;
    const Outline* onlyChord = nullptr;

    ObjectPose() = default;
    ObjectPose(const Vec2& position, const Mat2& linear, const Bounds* bounds, ObjectFlags flags);
    // The world centre of bound k: position + L·centre.
    Vec2 worldCentre(std::size_t k) const { return position + linear * (*bounds)[k].centre(); }
};

// Whether the rules test this pair at all: both flagged collisions with at least one bound, not
// two containers, not a container with an object flagged ignore_containers, and container pairs
// only when `containers` is on.
bool pairIsTested(const ObjectPose& a, const ObjectPose& b, bool containers);

// The narrow phase at an accuracy level (see accuracy.h). At `bounds`, `nearest`, `chord` and
// `circle`, the seed's rule with its two arithmetic slips fixed:
//   Acr = A's bound whose world centre is closest to B's position; Bcr = B's bound closest to
//   Acr's world centre (ties: first in file order); u = Bcr centre − Acr centre (u = +x when 0).
//   Contact:   rA = radius of Acr toward u, rB = radius of Bcr toward −u; hit iff |u|² ≤ (rA + rB)².
//   Container C holding O: R = radius of C toward O, r = radius of O the same way; hit iff |u| + r ≥ R.
// Radii come from Outline's tables (no trigonometry); `all-radii` and `exact` report the pair of
// bounds that decided, with that pair's rule values (an exact hit the rule misses has penetration 0:
// the push-out still follows the line of centres).
PairTest testPair(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy = Accuracy::Bounds);

// A pair for testPairs: A earlier in the scene than B.
struct PosePair {
    const ObjectPose* a = nullptr;
    const ObjectPose* b = nullptr;
};

// testPair on each pair: out[k] = testPair(*pairs[k].a, *pairs[k].b, accuracy), the same to the
// bit, for any number of pairs (out holds at least as many). Faster at the closest-pair rule's levels
// (bounds, nearest, chord), since its pairs run side by side: their divisions and square roots, which
// one pair would wait on in turn, go through the vector unit several lanes at a time (see
// pair_batch.cpp). The other levels cost what testPair costs.
void testPairs(std::span<const PosePair> pairs, Accuracy accuracy, PairTest* out);

// The same closest-pair rule through the plain formulas (Bound::worldRadius: atan2, a
// binary search, sin): the reference the fast path is checked against, and the benchmark's
// baseline. Levels `bounds`, `circle`, `nearest` and `chord` only (asserted).
PairTest testPairPlain(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy = Accuracy::Bounds);

}  // namespace polar
