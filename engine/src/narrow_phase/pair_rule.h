#pragma once
// The narrow phase's closest-pair rule, each part written once: which path a pair takes, which
// bounds it reads and in which directions (the wall's choice), the reach of two bounding circles,
// the chord path's formulas and the verdicts with the normal's sign. testPair (collision.cpp) calls these
// one pair at a time and the lanes of testPairs (pair_batch.cpp) on arrays of pairs, so the two
// cannot differ, and the lanes' loops still vectorise (the functions are small and inline). The
// sector key and a sector's radius are in shapes/outline.h, which Outline::worldRadius calls too.
#include <cmath>
#include <cstdint>

#include "narrow_phase/pair_test.h"
#include "polar/collision.h"

namespace polar {

// The index of the bound whose world centre (position + L·centre) is closest to `target`, given as
// target − position so that far-from-origin positions cancel before any rounding. Ties: the first.
inline std::uint32_t closestBoundTo(const ObjectPose& pose, const Vec2& targetFromPosition) {
    if (pose.bounds->size() == 1) return 0;
    std::uint32_t best = 0;
    double bestDistance = INFINITY;
    for (std::size_t k = 0; k < pose.bounds->size(); ++k) {
        double d = (pose.linear * (*pose.bounds)[k].centre() - targetFromPosition).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<std::uint32_t>(k);
        }
    }
    return best;
}

// The closest-pair rule's choice: Acr = A's bound whose world centre is closest to B's position,
// Bcr = B's bound closest to Acr's world centre, and u = Bcr's world centre − Acr's, computed as
// (bFromA + L_B·c_B) − L_A·c_A so that far-from-origin positions cancel first.
struct ClosestBounds {
    std::uint32_t a = 0;  // Acr's index
    std::uint32_t b = 0;  // Bcr's index
    Vec2 u;
};
inline ClosestBounds closestBounds(const ObjectPose& a, const ObjectPose& b) {
    Vec2 bFromA = b.position - a.position;
    ClosestBounds c;
    c.a = closestBoundTo(a, bFromA);
    Vec2 acrOffset = a.linear * (*a.bounds)[c.a].centre();
    c.b = closestBoundTo(b, acrOffset - bFromA);
    c.u = bFromA + b.linear * (*b.bounds)[c.b].centre() - acrOffset;
    return c;
}

// The shape bound r is read by at an accuracy level: nearest and chord force theirs, the other
// levels follow the file's interpolate flag.
inline OutlineShape shapeAt(const Bound& r, Accuracy level) {
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

// ---- Bounding circles

// Bounding-circle and inscribed-circle rejections allow this relative slack, so that rounding in
// the stretch bounds can never reject a pair the exact test would call a hit.
inline constexpr double kRejectSlack = 1e-9;

// The radius of a circle about r's world centre that holds all of r's outline: maxRadius·σmax(L).
inline double boundingRadius(const Bound& r, const LinearMap& map) {
    return r.maxRadius() * map.stretchMax;
}
// How far apart the world centres of bound ra of A and rb of B may be while their bounding circles
// still meet, with the rejection slack: beyond it, no outline of the two can touch.
inline double boundingReach(const Bound& ra, const LinearMap& a, const Bound& rb, const LinearMap& b) {
    return (boundingRadius(ra, a) + boundingRadius(rb, b)) * (1 + kRejectSlack);
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

// Whether a pair takes the common path: one bound each, both read by chord, a contact pair.
inline bool singleChordContact(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy) {
    bool chordA = a.onlyChord && (accuracy == Accuracy::Chord || a.onlyChordByFlag);
    bool chordB = b.onlyChord && (accuracy == Accuracy::Chord || b.onlyChordByFlag);
    return chordA && chordB && (accuracy == Accuracy::Bounds || accuracy == Accuracy::Chord) &&
           !containerPair(a, b);
}

// Whether the chosen bounds of a pair, read through outlines oa and ob, take the chord contact path
// (chordContact in collision.cpp, ChordLanes in pair_batch.cpp): both read by chord, a contact
// pair. Everything else the tables decide takes the rule's general path (applyRule, RuleLanes).
inline bool chordContactPair(const ObjectPose& a, const Outline& oa, const ObjectPose& b, const Outline& ob) {
    return oa.chord() && ob.chord() && !containerPair(a, b);
}

// u on the common path, computed as the closest-pair rule does, (bFromA + L_B·c_B) − L_A·c_A, so
// both paths agree to the bit.
inline Vec2 singleBoundOffset(const ObjectPose& a, const ObjectPose& b) {
    return ((b.position - a.position) + b.onlyCentreOffset) - a.onlyCentreOffset;
}

// A path a pair takes at the tables' levels (bounds, nearest, chord), with the bounds it reads.
struct PairPath {
    bool chord = false;   // the chord contact path (chordContact, ChordLanes); else the rule's general path
    std::uint32_t a = 0;  // Acr's index
    std::uint32_t b = 0;  // Bcr's index
    const Outline* outlineA = nullptr;
    const Outline* outlineB = nullptr;
    Vec2 u;  // Bcr's world centre − Acr's
};
// The path of bound i of A and j of B, u between their world centres: their outlines at the level,
// and whether those take the chord contact path.
inline PairPath boundPath(const ObjectPose& a, std::uint32_t i, const ObjectPose& b, std::uint32_t j,
                          const Vec2& u, Accuracy accuracy) {
    const Bound& ri = (*a.bounds)[i];
    const Bound& rj = (*b.bounds)[j];
    const Outline& oa = outlineOf(ri, shapeAt(ri, accuracy));
    const Outline& ob = outlineOf(rj, shapeAt(rj, accuracy));
    return {chordContactPair(a, oa, b, ob), i, j, &oa, &ob, u};
}
// The choice of path: testPair takes it one pair at a time, testPairs sorts pairs into lanes by it.
// The common case first (one bound each, both by chord, a contact: no choice of bounds to make),
// else the closest-pair rule's bounds, read through the outlines of the level's shapes; then
// onChord(path) for the chord contact path, onRule(path) for the rule's general path. Called with
// what to do on each, not returning the path, so that the common case reaches onChord with its
// constants and no merged branch (a returned path cost testPair 7 %).
template <class OnChord, class OnRule>
[[gnu::always_inline]] inline void takePath(const ObjectPose& a, const ObjectPose& b, Accuracy accuracy,
                                            OnChord&& onChord, OnRule&& onRule) {
    if (singleChordContact(a, b, accuracy)) {
        onChord(PairPath{true, 0, 0, a.onlyChord, b.onlyChord, singleBoundOffset(a, b)});
        return;
    }
    ClosestBounds c = closestBounds(a, b);
    PairPath path = boundPath(a, c.a, b, c.b, c.u, accuracy);
    if (path.chord)
        onChord(path);
    else
        onRule(path);
}

// ---- The wall: which radius of a container pair is the wall, and the directions both are read in
//
// A contact reads A's radius toward u and B's toward −u. In a container pair, C holds O: both radii
// are read toward `out`, from C's centre toward O, so O's is its side facing the wall, and the
// wall is met when that side reaches it.
struct ReadDirections {
    Vec2 a;
    Vec2 b;
};
inline ReadDirections readDirections(bool container, bool containerA, const Vec2& u) {
    if (!container) return {u, Vec2(-u)};
    Vec2 out = containerA ? u : Vec2(-u);
    return {out, out};
}
inline ReadDirections readDirections(const ObjectPose& a, const ObjectPose& b, const Vec2& u) {
    return readDirections(containerPair(a, b), (a.flags & kContainer) != 0, u);
}
// The wall is the container's radius, the side the held object's.
inline double wallOf(bool containerA, double ra, double rb) {
    return containerA ? ra : rb;
}
inline double sideOf(bool containerA, double ra, double rb) {
    return containerA ? rb : ra;
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

// The verdict of the rule's general path from the two radii as readDirections read them, |u|² and
// |u|: the contact or the wall rule by the pair's kind (selects, not branches, so that the lanes'
// loop vectorises).
struct RuleVerdict {
    bool hit = false;
    double penetration = 0.0;
};
inline RuleVerdict ruleVerdict(bool container, bool containerA, double ra, double rb, double squared,
                               double distance) {
    double sum = ra + rb;
    double wall = wallOf(containerA, ra, rb), side = sideOf(containerA, ra, rb);
    return {container ? wallHit(distance, side, wall) : contactHit(squared, sum),
            container ? wallPenetration(distance, side, wall) : contactPenetration(sum, distance)};
}
// A component of the normal from the same component of u/|u|: B separates along +u from A, and a
// held object moves back toward its container's centre, whichever of A and B it is.
// Written for a whole vector too (testPair stores the normal in one piece: written in halves and
// read whole, it would stall on store forwarding).
template <class Unit>
inline Unit normalComponent(bool container, const Unit& unit) {
    return container ? Unit(-unit) : unit;
}

}  // namespace polar
