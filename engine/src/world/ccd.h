#pragma once
#include <vector>

#include "broad_phase/detector.h"

namespace polar {

// Continuous collision for objects flagged fast: each is cast (moved along a straight path) from
// where the step began to where physics put it, and stopped at its first contact along the way.
//
// Why adaptive sub-stepping with the narrow phase itself? What counts as a hit is the adaptive-bounds
// rule (testPair), not a geometric overlap, so the cast asks that rule. Along the path it samples
// every h world units, h = the smaller inner radius of the two objects (the nearest their outlines come
// to their centres, σmin·innerBoundRadius), so a wall or rock at least that thick cannot fall between
// two samples; at most kMaxSamples per pair. Where reach circles prove a pair far apart, it jumps
// ahead by the gap instead. The first sample that hits is refined by bisection, and the object is
// placed there, so the ordinary detection of the same step reports the hit and the response bounces
// it. Pairs already touching where the step began are left to the ordinary detection. Other objects
// stay where physics put them; fast objects are cast in creation order; the object's rotation is
// its end-of-step rotation throughout. A scene without the ccd effect never reaches this code.
class FastCast {
  public:
    static constexpr double kMaxSamples = 1024;
    static constexpr int kRefinements = 12;

    // Casts every fast slot of the detector's data; moves objects back to their first contact and
    // refreshes their slots.
    void run(Detector& detector, std::vector<GameObject>& objects, EffectStats& stats);

    std::size_t bytes() const { return near_.capacity() * sizeof(std::uint32_t); }

  private:
    // The earliest t ∈ (0, 1] at which fast slot f, at start + t·(end − start), hits slot j; 2 if none.
    double timeOfImpact(Detector& detector, GameObject& object, const GameObject& otherObject,
                        std::uint32_t f, std::uint32_t j, EffectStats& stats);

    std::vector<std::uint32_t> near_;
    Vec2 start_ = Vec2::Zero();
    Vec2 end_ = Vec2::Zero();
    double innerF_ = 0.0;
};

// The smallest inner world radius over an object's radii at an accuracy level: σmin·innerBoundRadius,
// σmin = min(|sx|, |sy|).
double innerWorldRadius(const GameObject& object, Accuracy accuracy);

}  // namespace polar
