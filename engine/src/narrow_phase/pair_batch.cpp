// testPairs: the narrow phase on many pairs at once, with the same results as testPair to the bit.
//
// Why batch? One chord pair test is a chain: a division for the sector look-ups, two table reads, a
// square root and a second division, each waiting on the one before. The divider is one unit shared
// by divisions and square roots, and one pair keeps it busy for most of its time, so pairs tested one
// after the other queue on it. Here the pairs of a batch go through the rule in phases, each phase a
// loop over arrays of lanes (one lane per pair): the arithmetic phases have no loop-carried
// dependency, so the compiler turns them into vector instructions (two or four lanes per division),
// and the table reads run between them. Every lane performs exactly the operations testPair performs,
// in the same order, so the results are the same bits: both call the same inline functions
// (pair_rule.h: the choice of path, the chord path's keys and radii, the verdicts; shapes/outline.h:
// the sector key and a sector's radius), which the compiler vectorises here. A lane whose numbers
// leave the range where that holds (extreme scales: testPair's own fallback conditions; a
// nearest-rule tie) is handed to testPair itself.
//
// Two kinds of lanes, each its own arrays: chord contacts (testPair's shared-reciprocal chordContact,
// the common case: they hold only what that path reads, since sorting a pair into its lane is
// scalar work paid per pair) and rule lanes (its applyRule: a contact or container pair, each side
// read by chord or nearest). Pairs neither covers (the circle, all-radii and exact levels,
// coincident centres, a singular map) go to testPair.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <new>
#include <span>
#include <type_traits>

#include "narrow_phase/pair_rule.h"
#include "narrow_phase/pair_test.h"
#include "polar/collision.h"

namespace polar {
namespace {

constexpr std::size_t kLanes = 64;

// t = testPair(a, b, accuracy), the result built in t's place: an assignment would copy freshly
// written fields, which stalls on store forwarding (see closestPairTest in collision.cpp).
void decideAlone(PairTest& t, const ObjectPose& a, const ObjectPose& b, Accuracy accuracy) {
    static_assert(std::is_trivially_destructible_v<PairTest>);
    new (&t) PairTest(testPair(a, b, accuracy));
}

// What both kinds of lanes produce, one entry per lane: the pair it came from, its outcome, and
// whether that outcome stands (0: testPair decides the pair instead).
struct LaneOutcomes {
    std::size_t size = 0;
    std::uint32_t pair[kLanes];
    std::uint32_t radiiA[kLanes], radiiB[kLanes];
    alignas(32) double distance[kLanes], ra[kLanes], rb[kLanes], penetration[kLanes];
    alignas(32) double normalX[kLanes], normalY[kLanes];
    alignas(32) std::int64_t hit[kLanes], ok[kLanes];

    // Writes each lane's outcome, its kind from kindOf(lane), or has testPair decide the lanes that
    // left the safe range.
    template <class KindOf>
    void write(std::span<const PosePair> pairs, Accuracy accuracy, PairTest* out, KindOf kindOf) const {
        for (std::size_t l = 0; l < size; ++l) {
            PairTest& t = out[pair[l]];
            if (!ok[l]) {
                decideAlone(t, *pairs[pair[l]].a, *pairs[pair[l]].b, accuracy);
                continue;
            }
            t.normal = Vec2(normalX[l], normalY[l]);
            t.distance = distance[l];
            t.ra = ra[l];
            t.rb = rb[l];
            t.penetration = penetration[l];
            t.kind = kindOf(l);
            t.hit = hit[l] != 0;
            t.radiiA = radiiA[l];
            t.radiiB = radiiB[l];
        }
    }
};

// What both kinds of lanes read, one entry per lane. A and B are the pair's objects in scene order,
// e their bound-space directions, t the sector look-up's key.
struct LaneInputs : LaneOutcomes {
    const Outline* outlineA[kLanes];
    const Outline* outlineB[kLanes];
    alignas(32) double ux[kLanes], uy[kLanes], squared[kLanes];
    alignas(32) double eax[kLanes], eay[kLanes], ebx[kLanes], eby[kLanes];
    alignas(32) double detA[kLanes], detB[kLanes];
    alignas(32) double ta[kLanes], tb[kLanes];
    // From the sectors: the edge's offset or the arc's radius, and what the radius divides by.
    alignas(32) double offsetA[kLanes], offsetB[kLanes], denA[kLanes], denB[kLanes];

    // Stores pair k's inputs in lane `size` (the caller then fills its own fields and counts the lane).
    [[gnu::always_inline]] void take(std::uint32_t k, const ObjectPose& a, std::uint32_t i, const Outline& oa,
                                     const ObjectPose& b, std::uint32_t j, const Outline& ob, const Vec2& u,
                                     const Vec2& ea, const Vec2& eb) {
        pair[size] = k;
        radiiA[size] = i;
        radiiB[size] = j;
        outlineA[size] = &oa;
        outlineB[size] = &ob;
        ux[size] = u.x();
        uy[size] = u.y();
        eax[size] = ea.x();
        eay[size] = ea.y();
        ebx[size] = eb.x();
        eby[size] = eb.y();
        detA[size] = a.absDet;
        detB[size] = b.absDet;
    }
};

// Chord contact lanes (testPair's shared-reciprocal chordContact): only what that path reads, so
// that sorting a pair into a lane stores little. The divisor from the sectors is n·e.
struct ChordLanes : LaneInputs {
    // Lane `size` takes pair k, directions as chordContact (collision.cpp) takes them:
    // e_A = L_A⁻¹|det|·u, e_B = −L_B⁻¹|det|·u.
    [[gnu::always_inline]] void add(std::uint32_t k, const ObjectPose& a, std::uint32_t i, const Outline& oa,
                                    const ObjectPose& b, std::uint32_t j, const Outline& ob, const Vec2& u) {
        take(k, a, i, oa, b, j, ob, u, a.toBound(u), -b.toBound(u));
        ++size;
    }

    // chordContact's keys (chordKeys: one division for both sides). |u|² is u.squaredNorm()'s
    // ux² + uy²; a lane where it is 0 (testPair does not take the chord path there) goes to testPair.
    [[gnu::always_inline]] void keys() {
        for (std::size_t l = 0; l < size; ++l) {
            squared[l] = ux[l] * ux[l] + uy[l] * uy[l];
            ChordKeys k = chordKeys(eax[l], eay[l], ebx[l], eby[l]);
            bool good = k.inRange & (squared[l] > 0.0);
            // A key outside [0, 1] (rounding, or a product out of range) is not read here: the lane
            // reads sector 0 and testPair redoes it.
            bool inTable = (k.ta >= 0.0) & (k.ta <= 1.0) & (k.tb >= 0.0) & (k.tb <= 1.0);
            ta[l] = inTable ? k.ta : 0.0;
            tb[l] = inTable ? k.tb : 0.0;
            ok[l] = good & inTable;
        }
    }
    // The sector of each side's direction, as Outline::sectorOf finds it (table reads: not
    // vectorised), and its offset and n·e.
    [[gnu::always_inline]] void readSectors() {
        for (std::size_t l = 0; l < size; ++l) {
            const Outline::Sector& sa = outlineA[l]->sectors()[outlineA[l]->sectorOf(eax[l], eay[l], ta[l])];
            const Outline::Sector& sb = outlineB[l]->sectors()[outlineB[l]->sectorOf(ebx[l], eby[l], tb[l])];
            offsetA[l] = sa.offset;
            offsetB[l] = sb.offset;
            denA[l] = sa.dot(eax[l], eay[l]);
            denB[l] = sb.dot(ebx[l], eby[l]);
        }
    }
    // chordContact's radii and verdict (chordRadii: one division for both sides, contactHit).
    [[gnu::always_inline]] void rule() {
        for (std::size_t l = 0; l < size; ++l) {
            double d = std::sqrt(squared[l]);
            ChordRadii r =
                chordRadii(offsetA[l], detA[l], denA[l], offsetB[l], detB[l], denB[l], squared[l], d);
            double sum = r.ra + r.rb;
            distance[l] = d;
            ra[l] = r.ra;
            rb[l] = r.rb;
            hit[l] = contactHit(squared[l], sum);
            penetration[l] = contactPenetration(sum, d);
            normalX[l] = ux[l] * r.toNormal;
            normalY[l] = uy[l] * r.toNormal;
            ok[l] &= r.inRange;
        }
    }
};

// Rule lanes (testPair's applyRule: a contact or container pair, each side read by chord or
// nearest). The divisor from the sectors is n·e (chord) or |e| (nearest).
struct RuleLanes : LaneInputs {
    // Rule lanes only: |e| and the map's condition number (the nearest rule's tie band), which rule
    // each side is read by, and the kind of pair.
    alignas(32) double normA[kLanes], normB[kLanes], conditionA[kLanes], conditionB[kLanes];
    alignas(32) std::int64_t chordA[kLanes], chordB[kLanes];
    alignas(32) std::int64_t container[kLanes], containerA[kLanes];  // a container pair; A holds B

    // Lane `size` takes pair k, radii i of A and j of B, directions as applyRule (collision.cpp) takes
    // them: a contact reads A toward u and B toward −u; a container pair reads both toward `out`,
    // from the container to the held object.
    void addRule(std::uint32_t k, const ObjectPose& a, std::uint32_t i, const Outline& oa,
                 const ObjectPose& b, std::uint32_t j, const Outline& ob, const Vec2& u, double uSquared) {
        ReadDirections read = readDirections(a, b, u);
        take(k, a, i, oa, b, j, ob, u, a.toBound(read.a), b.toBound(read.b));
        squared[size] = uSquared;
        conditionA[size] = a.condition;
        conditionB[size] = b.condition;
        chordA[size] = oa.chord();
        chordB[size] = ob.chord();
        container[size] = containerPair(a, b);
        containerA[size] = (a.flags & kContainer) != 0;
        ++size;
    }

    // The sector of each side's direction, as Outline::sectorOf finds it, and the radius formula's
    // offset and divisor (table reads: not vectorised). A nearest-rule direction on a tie with a
    // bisector leaves the lane to testPair.
    [[gnu::always_inline]] void readSectors() {
        for (std::size_t l = 0; l < size; ++l) {
            std::size_t ja = outlineA[l]->sectorOf(eax[l], eay[l], ta[l]);
            std::size_t jb = outlineB[l]->sectorOf(ebx[l], eby[l], tb[l]);
            const Outline::Sector& sa = outlineA[l]->sectors()[ja];
            const Outline::Sector& sb = outlineB[l]->sectors()[jb];
            offsetA[l] = sa.offset;
            offsetB[l] = sb.offset;
            denA[l] = chordA[l] ? sa.dot(eax[l], eay[l]) : normA[l];
            denB[l] = chordB[l] ? sb.dot(ebx[l], eby[l]) : normB[l];
            if ((!chordA[l] && outlineA[l]->nearTie(ja, Vec2(eax[l], eay[l]), normA[l], conditionA[l])) ||
                (!chordB[l] && outlineB[l]->nearTie(jb, Vec2(ebx[l], eby[l]), normB[l], conditionB[l])))
                ok[l] = 0;
        }
    }

    // Rule lanes: applyRule's formulas, each side's sector key and radius as Outline::worldRadius
    // computes them (sectorKey, sectorRadius).
    [[gnu::always_inline]] void ruleKeys() {
        for (std::size_t l = 0; l < size; ++l) {
            double ka = sectorKey(eax[l], eay[l]), kb = sectorKey(ebx[l], eby[l]);
            normA[l] = std::sqrt(eax[l] * eax[l] + eay[l] * eay[l]);
            normB[l] = std::sqrt(ebx[l] * ebx[l] + eby[l] * eby[l]);
            // Also false for a NaN key (a zero or infinite direction): testPair decides those.
            bool inTable = (ka >= 0.0) & (ka <= 1.0) & (kb >= 0.0) & (kb <= 1.0);
            ta[l] = inTable ? ka : 0.0;
            tb[l] = inTable ? kb : 0.0;
            ok[l] = inTable;
        }
    }
    [[gnu::always_inline]] void ruleRule() {
        for (std::size_t l = 0; l < size; ++l) {
            double d = std::sqrt(squared[l]);
            // chord: h·|det L|·(|w| / (n·e)); nearest: r·|det L|·(|w| / |e|)
            double rA = sectorRadius(offsetA[l], detA[l], d, denA[l]);
            double rB = sectorRadius(offsetB[l], detB[l], d, denB[l]);
            double nx = ux[l] / d, ny = uy[l] / d;
            RuleVerdict verdict = ruleVerdict(container[l] != 0, containerA[l] != 0, rA, rB, squared[l], d);
            distance[l] = d;
            ra[l] = rA;
            rb[l] = rB;
            hit[l] = verdict.hit;
            penetration[l] = verdict.penetration;
            normalX[l] = normalComponent(container[l] != 0, nx);
            normalY[l] = normalComponent(container[l] != 0, ny);
        }
    }
};

// Puts pair k into the lane of the path testPair takes (takePath, at the closest-pair rule's levels:
// bounds, nearest, chord), or has testPair decide it now. The rule lanes read sectors only: a
// singular map (a point) or u = 0 (the rule's fixed direction) is testPair's. A chord contact with
// u = 0, which testPair does not decide by chord, leaves its lane to testPair.
void sortIntoLanes(std::uint32_t k, const ObjectPose& a, const ObjectPose& b, Accuracy accuracy,
                   ChordLanes& chordContacts, RuleLanes& rules, PairTest* out) {
    auto chord = [&](const PairPath& path) {
        chordContacts.add(k, a, path.a, *path.outlineA, b, path.b, *path.outlineB, path.u);
    };
    auto rule = [&](const PairPath& path) {
        double squared = path.u.squaredNorm();
        if (!a.singular() && !b.singular() && squared > 0)
            rules.addRule(k, a, path.a, *path.outlineA, b, path.b, *path.outlineB, path.u, squared);
        else
            decideAlone(out[k], a, b, accuracy);
    };
    takePath(a, b, accuracy, chord, rule);
}

// The lanes' phases. Compiled twice, the ifunc resolver picking one when the program loads: for
// AVX2, which has the vector compares and selects the loops need on 64-bit lanes, and for any x86-64.
// Both perform the same IEEE operations on each lane (no fused multiply-add: -ffp-contract=off), so
// the choice changes the speed only. There is one version where the target has no function
// versions (WebAssembly), and under ThreadSanitizer: its resolver would be instrumented, and it runs
// while the program loads, before the sanitizer's runtime exists.
#if defined(__x86_64__) && !defined(__SANITIZE_THREAD__)
#define POLAR_LANE_TARGETS [[gnu::target_clones("avx2", "default")]]
#else
#define POLAR_LANE_TARGETS
#endif
POLAR_LANE_TARGETS void runLanes(ChordLanes& chordContacts, RuleLanes& rules) {
    chordContacts.keys();
    chordContacts.readSectors();
    chordContacts.rule();
    rules.ruleKeys();
    rules.readSectors();
    rules.ruleRule();
}

}  // namespace

void testPairs(std::span<const PosePair> pairs, Accuracy accuracy, PairTest* out) {
    if (!closestPairByTables(accuracy)) {  // circle, all-radii, exact: no lanes
        for (std::size_t k = 0; k < pairs.size(); ++k)
            decideAlone(out[k], *pairs[k].a, *pairs[k].b, accuracy);
        return;
    }
    ChordLanes chordContacts;
    RuleLanes rules;
    for (std::size_t begin = 0; begin < pairs.size(); begin += kLanes) {
        std::size_t end = std::min(pairs.size(), begin + kLanes);
        chordContacts.size = rules.size = 0;
        for (std::size_t k = begin; k < end; ++k)
            sortIntoLanes(static_cast<std::uint32_t>(k), *pairs[k].a, *pairs[k].b, accuracy, chordContacts,
                          rules, out);
        runLanes(chordContacts, rules);
        chordContacts.write(pairs, accuracy, out, [](std::size_t) { return ContactKind::Contact; });
        rules.write(pairs, accuracy, out, [&](std::size_t l) {
            return rules.container[l] ? ContactKind::Container : ContactKind::Contact;
        });
    }
}

}  // namespace polar
