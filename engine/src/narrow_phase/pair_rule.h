#pragma once
// The parts of the narrow phase's closest-pair rule that testPair (collision.cpp) and its batched
// form testPairs (pair_batch.cpp) share, so that the two cannot pick different radii or paths.
#include <cmath>
#include <cstdint>

#include "narrow_phase/pair_test.h"
#include "polar/collision.h"

namespace polar {

// The index of the radii whose world centre (position + L·centre) is closest to `target`, given as
// target − position so that far-from-origin positions cancel before any rounding. Ties: the first.
inline std::uint32_t closestRadiiTo(const ObjectPose& pose, const Vec2& targetFromPosition) {
    if (pose.radii->size() == 1) return 0;
    std::uint32_t best = 0;
    double bestDistance = INFINITY;
    for (std::size_t k = 0; k < pose.radii->size(); ++k) {
        double d = (pose.linear * (*pose.radii)[k].centre() - targetFromPosition).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<std::uint32_t>(k);
        }
    }
    return best;
}

// The closest-pair rule's choice: Acr = A's radii whose world centre is closest to B's position,
// Bcr = B's radii closest to Acr's world centre, and u = Bcr's world centre − Acr's, computed as
// (bFromA + L_B·c_B) − L_A·c_A so that far-from-origin positions cancel first.
struct ClosestRadii {
    std::uint32_t a = 0;  // Acr's index
    std::uint32_t b = 0;  // Bcr's index
    Vec2 u;
};
inline ClosestRadii closestRadii(const ObjectPose& a, const ObjectPose& b) {
    Vec2 bFromA = b.position - a.position;
    ClosestRadii c;
    c.a = closestRadiiTo(a, bFromA);
    Vec2 acrOffset = a.linear * (*a.radii)[c.a].centre();
    c.b = closestRadiiTo(b, acrOffset - bFromA);
    c.u = bFromA + b.linear * (*b.radii)[c.b].centre() - acrOffset;
    return c;
}

inline OutlineShape shapeAt(const CollisionRadii& r, Accuracy level) {
    if (level == Accuracy::Nearest) return OutlineShape::Nearest;
    if (level == Accuracy::Chord) return OutlineShape::Chord;
    return r.shape();
}

// Whether a product of the chord path (collision.cpp's chordContact) stays where its shared
// reciprocals are safe: positive, and far from overflow and underflow (extreme scales). Out of it,
// the pair takes the plain-division path. `&`, not `&&`: both comparisons, no branch, so that the
// batched lanes' loops vectorise; NaN is outside.
inline bool inChordRange(double product) {
    return (product > 1e-280) & (product < 1e280);
}

// Whether a pair takes the common path: one radii each, both read by chord, a contact pair.
inline bool singleChordContact(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy) {
    bool chordA = a.onlyChord && (accuracy == Accuracy::Chord || a.onlyChordByFlag);
    bool chordB = b.onlyChord && (accuracy == Accuracy::Chord || b.onlyChordByFlag);
    return chordA && chordB && (accuracy == Accuracy::Bounds || accuracy == Accuracy::Chord) &&
           !((a.flags | b.flags) & kContainer);
}

// u on the common path, computed as the closest-pair rule does, (bFromA + L_B·c_B) − L_A·c_A, so
// both paths agree to the bit.
inline Vec2 singleRadiiOffset(const ObjectPose& a, const ObjectPose& b) {
    return ((b.position - a.position) + b.onlyCentreOffset) - a.onlyCentreOffset;
}

}  // namespace polar
