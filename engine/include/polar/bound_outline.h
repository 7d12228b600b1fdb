#pragma once
#include <vector>

#include "polar/bound.h"

namespace polar {

// The boundary of one Bound exactly as the collision rule sees it, as a closed polygon
// (the last point joins the first) in the target space of `toTarget`, a homogeneous 3×3 matrix
// from bound space (a world matrix T·R·S, or view · world for a canvas).
//
// Why one routine for everyone who draws bounds? A game's debug overlay and a bounds viewer must
// show the same outline the collision test uses, or a modder tunes the wrong shape.
//   - chord rule (interpolate): the sample points c + rₖ·(cos aₖ, sin aₖ) joined by straight edges;
//     an affine map keeps edges straight, so these vertices are exact;
//   - nearest rule: for each sample, an arc of radius rₖ from the bisector before it to the bisector
//     after it ((aₖ₋₁ + aₖ)/2 to (aₖ + aₖ₊₁)/2, circularly), then a radial step to the next arc;
//   - one sample: the circle of its radius.
// Arcs are cut into chords whose sagitta in target units, s = σ·r·(1 − cos(Δ/2)) with σ ≥ the
// largest stretch of the map, is at most `tolerance` (at least 8 chords per full turn).
std::vector<Vec2> boundOutline(const Bound& bound, const Mat3& toTarget, double tolerance = 0.25);

// The sample points c + rₖ·(cos aₖ, sin aₖ) in target space, in ascending angle order (the
// Bound's order, not the file's).
std::vector<Vec2> boundSamplePoints(const Bound& bound, const Mat3& toTarget);

// The older name of boundOutline, kept so programs written against it still compile.
inline std::vector<Vec2> radiiOutline(const Bound& bound, const Mat3& toTarget, double tolerance = 0.25) {
    return boundOutline(bound, toTarget, tolerance);
}
// The older name of boundSamplePoints, kept so programs written against it still compile.
inline std::vector<Vec2> radiiSamplePoints(const Bound& bound, const Mat3& toTarget) {
    return boundSamplePoints(bound, toTarget);
}

}  // namespace polar
