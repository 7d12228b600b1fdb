#include "world/ccd.h"

#include <algorithm>
#include <cmath>
#include "narrow_phase/pair_test.h"

namespace polar {

double innerWorldRadius(const GameObject& object, Accuracy accuracy) {
    Vec2 s = object.transform.scaleFactors();
    double sigmaMin = std::min(std::fabs(s.x()), std::fabs(s.y()));
    double inner = INFINITY;
    for (const Bound& radii : object.boundsOrEmpty())
        inner = std::min(inner, innerBoundRadius(radii, accuracy));
    return sigmaMin * inner;
}

void FastCast::run(Detector& detector, std::vector<GameObject>& objects, EffectStats& stats) {
    StepData& data = detector.data();
    if (data.fastSlots.empty()) return;
    ++stats.calls;
    for (const FastSlot& fast : data.fastSlots) {
        std::uint32_t f = fast.slot;
        GameObject& object = objects[data.objectIndex[f]];
        ++stats.objects;
        start_ = Vec2(fast.startX, fast.startY);
        end_ = object.transform.position();
        innerF_ = innerWorldRadius(object, detector.accuracy());
        near_.clear();
        detector.forEachNear(f, data.box(f), [&](std::uint32_t j) { near_.push_back(j); });
        double first = 2.0;
        for (std::uint32_t j : near_)
            first =
                std::min(first, timeOfImpact(detector, object, objects[data.objectIndex[j]], f, j, stats));
        // The same arithmetic as the cast's samples, so detection sees exactly the pose that hit.
        Vec2 delta = end_ - start_;
        object.transform.setPosition(first < 1.0 ? Vec2(start_ + first * delta) : end_);
        data.refresh(f, object);
    }
}

double FastCast::timeOfImpact(Detector& detector, GameObject& object, const GameObject& otherObject,
                              std::uint32_t f, std::uint32_t j, EffectStats& stats) {
    StepData& data = detector.data();
    const ObjectPose& other = data.poses[j];
    if (!pairIsTested(f < j ? data.poses[f] : other, f < j ? other : data.poses[f], detector.containers()))
        return 2.0;

    Vec2 delta = end_ - start_;
    double length = delta.norm();
    // Where the object is at time t: exactly `end` at t = 1, start + t·delta before.
    auto hitAt = [&](double t) {
        object.transform.setPosition(t >= 1.0 ? end_ : Vec2(start_ + t * delta));
        ObjectPose pose = poseOf(object);
        ++stats.pairs;
        return (f < j ? testPair(pose, other, detector.accuracy())
                      : testPair(other, pose, detector.accuracy()))
            .hit;
    };
    // A lower bound on how far the object must still travel before the pair can hit.
    bool otherIsContainer = data.isContainer(j), selfIsContainer = data.isContainer(f);
    std::size_t ordinal = otherIsContainer ? data.containerOrdinal(j) : 0;
    auto gapAt = [&](double t) {
        if (selfIsContainer) return 0.0;
        ReachCircle moved = data.reach[f];  // computed at `end`
        Vec2 shift = (t >= 1.0 ? end_ : Vec2(start_ + t * delta)) - end_;
        moved.x += shift.x();
        moved.y += shift.y();
        return otherIsContainer ? data.containerGap(ordinal, moved)
                                : StepData::contactGap(moved, data.reach[j]);
    };

    if (hitAt(0.0)) return 2.0;  // already touching: the ordinary detection answers
    double spacing =
        std::max(std::min(innerF_, innerWorldRadius(otherObject, detector.accuracy())), length / kMaxSamples);
    double step = spacing / length;
    double before = 0.0;  // the last time known not to hit
    for (;;) {
        double gap = gapAt(before);
        double t = std::min(1.0, before + std::max(step, gap / length));
        if (hitAt(t)) {
            // Bisect toward the first contact between a miss and a hit.
            double hit = t;
            for (int k = 0; k < kRefinements; ++k) {
                double middle = 0.5 * (before + hit);
                if (hitAt(middle))
                    hit = middle;
                else
                    before = middle;
            }
            return hit;
        }
        if (t >= 1.0) return 2.0;
        before = t;
    }
}

}  // namespace polar
