#include "app/hud/interpolation.h"

#include <cmath>

namespace polar::game {

void Interpolation::capture(const World& world) {
    previous_.clear();
    for (const GameObject& o : world.objects()) previous_.emplace(o.id, o.transform);
}

Transform Interpolation::at(const GameObject& object, double alpha) const {
    auto it = previous_.find(object.id);
    if (it == previous_.end() || alpha >= 1.0) return object.transform;
    const Transform& a = it->second;
    const Transform& b = object.transform;
    // A jump no motion makes in one tick is a wrap across the field: drawn where it landed, not
    // swept across the screen.
    constexpr double kJump = 200;
    if ((b.position() - a.position()).squaredNorm() > kJump * kJump) return b;
    double turn = std::remainder(b.rotation() - a.rotation(), kTwoPi);
    return Transform(a.position() + (b.position() - a.position()) * alpha, a.rotation() + turn * alpha,
                     a.scaleFactors() + (b.scaleFactors() - a.scaleFactors()) * alpha);
}

}  // namespace polar::game
