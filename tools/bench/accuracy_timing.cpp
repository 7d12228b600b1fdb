#include "accuracy_timing.h"

#include <algorithm>
#include <cmath>

#include "harness/repeat.h"
#include "shapes/outline.h"

namespace polar::bench {
namespace {

// Median ns per item of `run`, which handles `count` items (pairs, poses), over 301 repetitions
// on the wall clock.
template <class Run>
double nsEach(std::size_t count, Run&& run) {
    if (count == 0) return 0.0;
    volatile std::size_t sink = 0;
    const Timings t = repeat({0, 301, CpuClock::None}, [&] { sink = sink + run(); });
    return t.wall().median * 1e6 / static_cast<double>(count);
}

}  // namespace

TimedSet timedSetOf(const std::vector<Sprite>& sprites, const std::vector<Placement>& placements,
                    const std::vector<Sample>& samples) {
    TimedSet timed;
    std::vector<ObjectPose>&timedA = timed.a, &timedB = timed.b;
    for (std::size_t i = 0; i < samples.size() && timedA.size() < 1024; ++i) {
        const Placement& p = placements[samples[i].placement];
        timedA.push_back(poseA(sprites, p));
        timedB.push_back(poseB(sprites, p, samples[i].distance));
    }
    for (std::size_t i = 0; i < timedA.size(); ++i) timed.pairs.push_back({&timedA[i], &timedB[i]});
    timed.tests.resize(timed.pairs.size());
    return timed;
}

double timeLevel(TimedSet& timed, Accuracy accuracy, bool plain, bool oneAtATime) {
    const std::vector<ObjectPose>&timedA = timed.a, &timedB = timed.b;
    const std::vector<PosePair>& timedPairs = timed.pairs;
    std::vector<PairTest>& timedTests = timed.tests;
    return nsEach(timedA.size(), [&] {
        std::size_t hits = 0;
        if (plain) {
            for (std::size_t i = 0; i < timedA.size(); ++i)
                hits += testPairPlain(timedA[i], timedB[i], accuracy).hit;
        } else if (oneAtATime) {
            for (std::size_t i = 0; i < timedA.size(); ++i)
                hits += testPair(timedA[i], timedB[i], accuracy).hit;
        } else {
            testPairs(timedPairs, accuracy, timedTests.data());
            for (const PairTest& t : timedTests) hits += t.hit;
        }
        return hits;
    });
}

std::array<KindTiming, 3> timeChordByKind(TimedSet& timed) {
    const std::vector<ObjectPose>&timedA = timed.a, &timedB = timed.b;
    std::vector<PairTest>& timedTests = timed.tests;
    std::array<KindTiming, 3> kinds = {
        {{"one bound each, contact", {}, {}}, {"several radii, contact", {}, {}}, {"container", {}, {}}}};
    for (std::size_t i = 0; i < timedA.size(); ++i) {
        const ObjectPose &a = timedA[i], &b = timedB[i];
        std::size_t kind = ((a.flags | b.flags) & kContainer)               ? 2
                           : a.bounds->size() == 1 && b.bounds->size() == 1 ? 0
                                                                            : 1;
        kinds[kind].a.push_back(a);
        kinds[kind].b.push_back(b);
    }
    for (KindTiming& kind : kinds) {
        std::vector<PosePair> pairs;
        for (std::size_t i = 0; i < kind.a.size(); ++i) pairs.push_back({&kind.a[i], &kind.b[i]});
        kind.ns = nsEach(pairs.size(), [&] {
            testPairs(pairs, Accuracy::Chord, timedTests.data());
            return static_cast<std::size_t>(timedTests[0].hit);
        });
    }
    return kinds;
}

FloorTiming timeFloor(TimedSet& timed, const KindTiming& single) {
    std::vector<PairTest>& timedTests = timed.tests;
    const std::vector<ObjectPose>&singleA = single.a, &singleB = single.b;
    auto floorPass = [&](bool lookUp) {
        for (std::size_t k = 0; k < singleA.size(); ++k) {
            const ObjectPose &a = singleA[k], &b = singleB[k];
            Vec2 u = b.position - a.position + b.onlyCentreOffset - a.onlyCentreOffset;
            Vec2 ea = a.toBound(u), eb = -b.toBound(u);
            PairTest& t = timedTests[k];
            t.normal = u;
            t.distance = ea.x();
            t.ra = a.absDet;
            t.rb = b.absDet;
            t.penetration = eb.y();
            if (lookUp && a.onlyChord && b.onlyChord) {
                double sa = std::fabs(ea.x()) + std::fabs(ea.y()), sb = std::fabs(eb.x()) + std::fabs(eb.y());
                double q = 1.0 / (sa * sb);
                const Outline &oa = *a.onlyChord, &ob = *b.onlyChord;
                const Outline::Sector& secA =
                    oa.sectors()[oa.sectorOf(ea.x(), ea.y(), std::fabs(ea.y()) * sb * q)];
                const Outline::Sector& secB =
                    ob.sectors()[ob.sectorOf(eb.x(), eb.y(), std::fabs(eb.y()) * sa * q)];
                t.ra *= secA.offset;
                t.rb *= secB.offset;
                t.penetration = secA.nx * ea.x() + secB.ny * eb.y();
            }
            t.hit = ea.y() > eb.x();
        }
        return static_cast<std::size_t>(timedTests[0].hit);
    };
    FloorTiming floor;
    floor.readWriteNs = nsEach(singleA.size(), [&] { return floorPass(false); });
    floor.lookUpNs = nsEach(singleA.size(), [&] { return floorPass(true); });
    return floor;
}

double timePose(const TimedSet& timed) {
    const std::vector<ObjectPose>& timedA = timed.a;
    return nsEach(timedA.size(), [&] {
        double acc = 0;
        for (std::size_t i = 0; i < timedA.size(); ++i) {
            ObjectPose p(timedA[i].position, timedA[i].linear, timedA[i].bounds, kCollisions);
            acc += p.absDet + p.onlyCentreOffset.x();
        }
        return static_cast<std::size_t>(acc);
    });
}

}  // namespace polar::bench
