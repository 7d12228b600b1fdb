// testPairs: the narrow phase on many pairs at once, with the same results as testPair to the bit.
//
// Why batch? One chord pair test is a chain: a division for the sector look-ups, two table reads, a
// square root and a second division, each waiting on the one before. The divider is one unit shared
// by divisions and square roots, and one pair keeps it busy for most of its time, so pairs tested one
// after the other queue on it. Here the pairs of a batch go through the rule in phases, each phase a
// loop over arrays of lanes (one lane per pair): the arithmetic phases have no loop-carried
// dependency, so the compiler turns them into vector instructions (two or four lanes per division),
// and the table reads run between them. Every lane performs exactly the operations testPair performs,
// in the same order, so the results are the same bits; a lane whose numbers leave the range where
// that holds (extreme scales: testPair's own fallback conditions) is handed to testPair itself.
// Pairs the lanes do not cover (other levels, nearest radii, coincident centres) go to testPair too.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "pair_rule.h"
#include "polar/collision.h"

namespace polar {
namespace {

constexpr std::size_t kLanes = 64;

// One kind of chord pair (contact or container) as arrays, one entry per lane. A and B are the
// pair's objects in scene order, e their bound-space directions, t the sector look-up's key.
struct Lanes {
    std::size_t size = 0;
    std::uint32_t pair[kLanes];
    std::uint32_t radiiA[kLanes], radiiB[kLanes];
    const Outline* outlineA[kLanes];
    const Outline* outlineB[kLanes];
    alignas(32) double ux[kLanes], uy[kLanes], squared[kLanes];
    alignas(32) double eax[kLanes], eay[kLanes], ebx[kLanes], eby[kLanes];
    alignas(32) double detA[kLanes], detB[kLanes];
    alignas(32) double ta[kLanes], tb[kLanes];
    alignas(32) double nax[kLanes], nay[kLanes], levelA[kLanes], nbx[kLanes], nby[kLanes], levelB[kLanes];
    alignas(32) std::int64_t containerA[kLanes];  // container lanes: 1 when A holds B, 0 when B holds A
    // The outcome.
    alignas(32) double distance[kLanes], ra[kLanes], rb[kLanes], penetration[kLanes];
    alignas(32) double normalX[kLanes], normalY[kLanes];
    alignas(32) std::int64_t hit[kLanes], ok[kLanes];

    void add(std::uint32_t k, const ObjectPose& a, std::uint32_t i, const Outline& oa, const ObjectPose& b,
             std::uint32_t j, const Outline& ob, const Vec2& u, double uSquared) {
        pair[size] = k;
        radiiA[size] = i;
        radiiB[size] = j;
        outlineA[size] = &oa;
        outlineB[size] = &ob;
        ux[size] = u.x();
        uy[size] = u.y();
        squared[size] = uSquared;
        detA[size] = a.absDet;
        detB[size] = b.absDet;
        ++size;
    }
    // The directions as testPair's chordContact takes them: e_A = L_A⁻¹|det|·u, e_B = −L_B⁻¹|det|·u.
    void addContact(std::uint32_t k, const ObjectPose& a, std::uint32_t i, const Outline& oa,
                    const ObjectPose& b, std::uint32_t j, const Outline& ob, const Vec2& u, double uSquared) {
        Vec2 ea = a.toBound(u), eb = -b.toBound(u);
        eax[size] = ea.x();
        eay[size] = ea.y();
        ebx[size] = eb.x();
        eby[size] = eb.y();
        add(k, a, i, oa, b, j, ob, u, uSquared);
    }
    // As the container rule takes them: both radii toward `out`, from the container to the held.
    void addContainer(std::uint32_t k, const ObjectPose& a, std::uint32_t i, const Outline& oa,
                      const ObjectPose& b, std::uint32_t j, const Outline& ob, const Vec2& u,
                      double uSquared) {
        bool holderA = a.flags & kContainer;
        Vec2 out = holderA ? u : Vec2(-u);
        Vec2 ea = a.toBound(out), eb = b.toBound(out);
        eax[size] = ea.x();
        eay[size] = ea.y();
        ebx[size] = eb.x();
        eby[size] = eb.y();
        containerA[size] = holderA;
        add(k, a, i, oa, b, j, ob, u, uSquared);
    }

    // The sector of each side's direction, as Outline::sectorOf finds it (table reads: not vectorised).
    [[gnu::always_inline]] void readSectors() {
        for (std::size_t l = 0; l < size; ++l) {
            const Outline::Sector& sa = outlineA[l]->sectors()[outlineA[l]->sectorOf(eax[l], eay[l], ta[l])];
            const Outline::Sector& sb = outlineB[l]->sectors()[outlineB[l]->sectorOf(ebx[l], eby[l], tb[l])];
            nax[l] = sa.nx;
            nay[l] = sa.ny;
            levelA[l] = sa.level;
            nbx[l] = sb.nx;
            nby[l] = sb.ny;
            levelB[l] = sb.level;
        }
    }

    // Contact lanes: chordContact's formulas (collision.cpp), its two divisions shared by both sides.
    [[gnu::always_inline]] void contactKeys() {
        for (std::size_t l = 0; l < size; ++l) {
            double sa = std::fabs(eax[l]) + std::fabs(eay[l]), sb = std::fabs(ebx[l]) + std::fabs(eby[l]);
            double sProduct = sa * sb;
            bool good = (sProduct > 1e-280) & (sProduct < 1e280);
            double q = 1.0 / sProduct;
            double ka = std::fabs(eay[l]) * sb * q, kb = std::fabs(eby[l]) * sa * q;
            // A key outside [0, 1] (rounding, or a product out of range) is not read here: the lane
            // reads sector 0 and testPair redoes it.
            bool inTable = (ka >= 0.0) & (ka <= 1.0) & (kb >= 0.0) & (kb <= 1.0);
            ta[l] = inTable ? ka : 0.0;
            tb[l] = inTable ? kb : 0.0;
            ok[l] = good & inTable;
        }
    }
    [[gnu::always_inline]] void contactRule() {
        for (std::size_t l = 0; l < size; ++l) {
            double da = nax[l] * eax[l] + nay[l] * eay[l], db = nbx[l] * ebx[l] + nby[l] * eby[l];
            double d = std::sqrt(squared[l]);
            double dProduct = da * db * d;
            bool good = (dProduct > 1e-280) & (dProduct < 1e280);
            double k = 1.0 / dProduct;
            double scaledK = squared[l] * k;
            double rA = levelA[l] * detA[l] * (db * scaledK), rB = levelB[l] * detB[l] * (da * scaledK);
            double sum = rA + rB;
            double toNormal = da * db * k;
            distance[l] = d;
            ra[l] = rA;
            rb[l] = rB;
            hit[l] = squared[l] <= sum * sum;
            penetration[l] = sum - d;
            normalX[l] = ux[l] * toNormal;
            normalY[l] = uy[l] * toNormal;
            ok[l] &= good;
        }
    }

    // Container lanes: applyRule's formulas (collision.cpp) with Outline::worldRadius for each side.
    [[gnu::always_inline]] void containerKeys() {
        for (std::size_t l = 0; l < size; ++l) {
            double sa = std::fabs(eax[l]) + std::fabs(eay[l]), sb = std::fabs(ebx[l]) + std::fabs(eby[l]);
            double ka = std::fabs(eay[l]) / sa, kb = std::fabs(eby[l]) / sb;
            // Also false for a NaN key (a direction of infinite size): testPair decides those.
            bool inTable = (ka >= 0.0) & (ka <= 1.0) & (kb >= 0.0) & (kb <= 1.0);
            ta[l] = inTable ? ka : 0.0;
            tb[l] = inTable ? kb : 0.0;
            ok[l] = inTable;
        }
    }
    [[gnu::always_inline]] void containerRule() {
        for (std::size_t l = 0; l < size; ++l) {
            double d = std::sqrt(squared[l]);
            double da = nax[l] * eax[l] + nay[l] * eay[l], db = nbx[l] * ebx[l] + nby[l] * eby[l];
            double rA = levelA[l] * detA[l] * (d / da), rB = levelB[l] * detB[l] * (d / db);
            double wall = containerA[l] ? rA : rB, side = containerA[l] ? rB : rA;
            distance[l] = d;
            ra[l] = rA;
            rb[l] = rB;
            hit[l] = d + side >= wall;
            penetration[l] = d + side - wall;
            normalX[l] = -(ux[l] / d);  // the held object moves back toward the container's centre
            normalY[l] = -(uy[l] / d);
        }
    }

    // Writes each lane's outcome, or has testPair decide the lanes that left the safe range.
    void write(ContactKind kind, std::span<const PosePair> pairs, Accuracy accuracy, PairTest* out) const {
        for (std::size_t l = 0; l < size; ++l) {
            PairTest& t = out[pair[l]];
            if (!ok[l]) {
                t = testPair(*pairs[pair[l]].a, *pairs[pair[l]].b, accuracy);
                continue;
            }
            t.normal = Vec2(normalX[l], normalY[l]);
            t.distance = distance[l];
            t.ra = ra[l];
            t.rb = rb[l];
            t.penetration = penetration[l];
            t.kind = kind;
            t.hit = hit[l] != 0;
            t.radiiA = radiiA[l];
            t.radiiB = radiiB[l];
        }
    }
};

// Puts pair k into a lane, or has testPair decide it now: the choices testPair makes, in its order.
void sortIntoLanes(std::uint32_t k, const ObjectPose& a, const ObjectPose& b, Accuracy accuracy,
                   Lanes& contacts, Lanes& containers, PairTest* out) {
    if (singleChordContact(a, b, accuracy)) {
        Vec2 u = singleRadiiOffset(a, b);
        double squared = u.squaredNorm();
        if (squared > 0) {
            contacts.addContact(k, a, 0, *a.onlyChord, b, 0, *b.onlyChord, u, squared);
            return;
        }
    }
    bool rule = accuracy == Accuracy::Bounds || accuracy == Accuracy::Nearest || accuracy == Accuracy::Chord;
    if (rule) {
        // closestPairTest's choice of radii and its u, written as it writes them.
        Vec2 bFromA = b.position - a.position;
        std::uint32_t i = closestRadiiTo(a, bFromA);
        const CollisionRadii& acr = (*a.radii)[i];
        Vec2 acrOffset = a.linear * acr.centre();
        std::uint32_t j = closestRadiiTo(b, acrOffset - bFromA);
        const CollisionRadii& bcr = (*b.radii)[j];
        Vec2 u = bFromA + b.linear * bcr.centre() - acrOffset;
        const Outline& oa = acr.outline(shapeAt(acr, accuracy));
        const Outline& ob = bcr.outline(shapeAt(bcr, accuracy));
        double squared = u.squaredNorm();
        if (oa.chord() && ob.chord() && squared > 0) {
            if (!((a.flags | b.flags) & kContainer)) {
                contacts.addContact(k, a, i, oa, b, j, ob, u, squared);
                return;
            }
            if (!a.singular() && !b.singular()) {
                containers.addContainer(k, a, i, oa, b, j, ob, u, squared);
                return;
            }
        }
    }
    out[k] = testPair(a, b, accuracy);
}

// The lanes' phases. Compiled twice, the ifunc resolver picking one when the program loads: for
// AVX2, which has the vector compares and selects the loops need on 64-bit lanes, and for any x86-64.
// Both perform the same IEEE operations on each lane (no fused multiply-add: -ffp-contract=off), so
// the choice changes the speed only.
[[gnu::target_clones("avx2", "default")]] void runLanes(Lanes& contacts, Lanes& containers) {
    contacts.contactKeys();
    contacts.readSectors();
    contacts.contactRule();
    containers.containerKeys();
    containers.readSectors();
    containers.containerRule();
}

}  // namespace

void testPairs(std::span<const PosePair> pairs, Accuracy accuracy, PairTest* out) {
    Lanes contacts, containers;
    for (std::size_t begin = 0; begin < pairs.size(); begin += kLanes) {
        std::size_t end = std::min(pairs.size(), begin + kLanes);
        contacts.size = containers.size = 0;
        for (std::size_t k = begin; k < end; ++k)
            sortIntoLanes(static_cast<std::uint32_t>(k), *pairs[k].a, *pairs[k].b, accuracy, contacts,
                          containers, out);
        runLanes(contacts, containers);
        contacts.write(ContactKind::Contact, pairs, accuracy, out);
        containers.write(ContactKind::Container, pairs, accuracy, out);
    }
}

}  // namespace polar
