#pragma once
#include "polar/collision.h"
#include "polar/game_object.h"

namespace polar {

// Whether everything the engine hands out about an object is finite: position, rotation, scale,
// velocity, spin, damping. The world asserts it for every object at the end of each step (Debug),
// so a NaN or an infinity is caught in the step that made it, not frames later.
bool isFinite(const GameObject& object);
// Whether a pair test's numbers (distance, radii, normal, penetration) are all finite.
bool isFinite(const PairTest& test);

}  // namespace polar
