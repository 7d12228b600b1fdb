#include "world/numeric_guard.h"

#include <cmath>

namespace polar {

bool isFinite(const GameObject& object) {
    const Transform& t = object.transform;
    return t.position().allFinite() && std::isfinite(t.rotation()) && t.scaleFactors().allFinite() &&
           t.linear().allFinite() && object.velocity.allFinite() && std::isfinite(object.spin) &&
           std::isfinite(object.damping);
}

bool isFinite(const PairTest& test) {
    return std::isfinite(test.distance) && std::isfinite(test.ra) && std::isfinite(test.rb) &&
           test.normal.allFinite() && std::isfinite(test.penetration);
}

}  // namespace polar
