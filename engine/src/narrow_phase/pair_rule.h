#pragma once
// The narrow phase's closest-pair rule, each part written once: which path a pair takes, which
// radii it reads, the chord path's formulas and the verdicts. testPair (collision.cpp) calls these
// one pair at a time and the lanes of testPairs (pair_batch.cpp) on arrays of pairs, so the two
// cannot differ, and the lanes' loops still vectorise (the functions are small and inline). The
// sector key and a sector's radius are in shapes/outline.h, which Outline::worldRadius calls too.
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

// The shape radii r is read by at an accuracy level: nearest and chord force theirs, the other
// levels follow the file's interpolate flag.
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

// ---- The choice of path

// Whether the level is decided by the closest-pair rule through the tables (bounds, nearest, chord):
// the levels that testPair decides by the paths below and that testPairs runs in lanes. The others
// (circle, all-radii, exact) take testPair's own loops.
inline bool closestPairByTables(Accuracy accuracy) {
    return accuracy == Accuracy::Bounds || accuracy == Accuracy::Nearest || accuracy == Accuracy::Chord;
}

// Whether one of the two objects is a container (then the pair is a container pair).
inline bool containerPair(const ObjectPose& a, const ObjectPose& b) {
    return ((a.flags | b.flags) & kContainer) != 0;
}

// Whether a pair takes the common path: one radii each, both read by chord, a contact pair.
inline bool singleChordContact(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy) {
    bool chordA = a.onlyChord && (accuracy == Accuracy::Chord || a.onlyChordByFlag);
    bool chordB = b.onlyChord && (accuracy == Accuracy::Chord || b.onlyChordByFlag);
    return chordA && chordB && (accuracy == Accuracy::Bounds || accuracy == Accuracy::Chord) &&
           !containerPair(a, b);
}

// Whether the chosen radii of a pair, read through outlines oa and ob, take the chord contact path
// (chordContact in collision.cpp, ChordLanes in pair_batch.cpp): both read by chord, a contact
// pair. Everything else the tables decide takes the rule's general path (applyRule, RuleLanes).
inline bool chordContactPair(const ObjectPose& a, const Outline& oa, const ObjectPose& b, const Outline& ob) {
    return oa.chord() && ob.chord() && !containerPair(a, b);
}

// u on the common path, computed as the closest-pair rule does, (bFromA + L_B·c_B) − L_A·c_A, so
// both paths agree to the bit.
inline Vec2 singleRadiiOffset(const ObjectPose& a, const ObjectPose& b) {
    return ((b.position - a.position) + b.onlyCentreOffset) - a.onlyCentreOffset;
}

// ---- The chord contact path: both radii by chord, the divisions shared by both sides
//
// The same formulas as Outline::worldRadius, with the divisions shared:
//   sector keys: sA = |eA.x| + |eA.y|, sB likewise; one reciprocal q = 1/(sA·sB) gives both,
//     tA = |eA.y|·sB·q and tB = |eB.y|·sA·q (sectorKeyShared);
//   radii: rA = hA·|det LA|·|u| / (nA·eA); with k = 1/((nA·eA)·(nB·eB)·|u|),
//     rA = hA·|det LA|·((nB·eB)·|u|²·k), rB = hB·|det LB|·((nA·eA)·|u|²·k), 1/|u| = (nA·eA)·(nB·eB)·k.
// Three long operations (a square root, two divisions) instead of six. Each step also says whether
// its product stayed in inChordRange; out of it, the pair takes the plain-division path.

// Both sides' sector keys, from bound directions eA = L_A⁻¹|det|·u and eB = −L_B⁻¹|det|·u.
struct ChordKeys {
    double ta = 0.0;
    double tb = 0.0;
    bool inRange = false;  // sA·sB in inChordRange: the keys stand
};
inline ChordKeys chordKeys(double eax, double eay, double ebx, double eby) {
    double sa = keyDivisor(eax, eay), sb = keyDivisor(ebx, eby);
    double sProduct = sa * sb;
    bool inRange = inChordRange(sProduct);
    double q = 1.0 / sProduct;
    return {sectorKeyShared(eay, sb, q), sectorKeyShared(eby, sa, q), inRange};
}

// Both radii from the sectors' offsets h and divisors d = n·e, and |u|² and |u|.
struct ChordRadii {
    double ra = 0.0;
    double rb = 0.0;
    double toNormal = 0.0;  // 1/|u|: the normal is u·toNormal
    bool inRange = false;   // dA·dB·|u| in inChordRange: the radii stand
};
inline ChordRadii chordRadii(double offsetA, double detA, double da, double offsetB, double detB, double db,
                             double squared, double distance) {
    double dProduct = da * db * distance;
    bool inRange = inChordRange(dProduct);
    double k = 1.0 / dProduct;
    double scaledK = squared * k;
    return {offsetA * detA * (db * scaledK), offsetB * detB * (da * scaledK), da * db * k, inRange};
}

// ---- The verdicts

// Contact: hit iff |u|² ≤ (rA + rB)², the squared distance against the squared sum (like with like;
// touching counts); the penetration is (rA + rB) − |u|.
inline bool contactHit(double squared, double sum) {
    return squared <= sum * sum;
}
inline double contactPenetration(double sum, double distance) {
    return sum - distance;
}
// Container C holding O: hit iff |u| + r ≥ R, with R = C's radius toward O (the wall) and r = O's
// radius the same way (its side facing the wall; touching counts); the penetration is |u| + r − R.
inline bool wallHit(double distance, double side, double wall) {
    return distance + side >= wall;
}
inline double wallPenetration(double distance, double side, double wall) {
    return distance + side - wall;
}

}  // namespace polar
