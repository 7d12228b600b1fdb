#pragma once
#include "shapes/outline.h"

namespace polar {

// The exact tests behind the `exact` accuracy level: do two outlines, each placed in the world by
// its linear map and world centre, really overlap; is a held outline really inside its container?
//
// Why this way? Each outline is star-shaped about its centre and is exact in its own bound space:
// a point y is inside iff |y| ≤ radius toward y, which the sector table answers in O(1). So the
// test runs in one outline's bound space (the host), where the other outline (the guest) is mapped
// by the affine map q = t + M·y, M = L_host⁻¹·L_guest. Straight edges stay straight; circular arcs
// become elliptic arcs, written exactly as rational quadratics q(τ) = V(τ)/(1 + τ²). Each guest
// piece is cut where it crosses the host's sector rays, and on each cut the host's boundary is one
// line n·q = h or one circle |q| = r, so "does the piece come inside (or get outside)" is the sign
// of a linear, quadratic or quartic polynomial's extremum on an interval: endpoints, a closed-form
// vertex, or Newton's method on a monotone derivative. No tolerance decides an answer: the quick
// rejections keep a 1e-9 margin so that they only ever pass a borderline case on to the full test.
// The guest is chosen so that its pieces are straight whenever either outline is a polygon, and
// only the guest sectors that face the host's bounding circle are visited.
//
// A singular map (a scale of 0) makes an outline the single point at its centre, as the Foundation
// rule's world radius of 0 does.

// Whether outlines a and b share a point (touching counts); u = b's world centre − a's.
bool outlinesOverlap(const Outline& a, const LinearMap& ma, const Outline& b, const LinearMap& mb,
                     const Vec2& u);

// Whether the held outline is not wholly inside the container's, i.e. some point of it lies on or
// outside the container's wall; u = held world centre − container world centre.
bool outlineLeaves(const Outline& held, const LinearMap& mh, const Outline& container, const LinearMap& mc,
                   const Vec2& u);

}  // namespace polar
