#pragma once
#include <cstdint>

#include "polar/game_object.h"

namespace polar {

// What a pair test needs from one object, computed once per object per step.
struct ObjectPose {
    Vec2 position = Vec2::Zero();
    Mat2 linear = Mat2::Identity();  // L = R·S
    const Bounds* radii = nullptr;
    ObjectFlags flags = 0;

    static ObjectPose of(const GameObject& object);
    // The world centre of radii k: position + L·centre.
    Vec2 worldCentre(std::size_t k) const { return position + linear * (*radii)[k].centre(); }
};

enum class ContactKind { Contact, Container };
const char* contactKindName(ContactKind kind);

// The outcome of the seed's rule for one pair (A earlier in the scene than B).
struct PairTest {
    ContactKind kind = ContactKind::Contact;
    bool hit = false;
    std::uint32_t radiiA = 0;  // the CollisionRadii of A that took part (Acr), in file order
    std::uint32_t radiiB = 0;  // Bcr
    double distance = 0.0;     // |u|, u = Bcr's world centre − Acr's world centre
    double ra = 0.0;           // A's world radius as the rule used it
    double rb = 0.0;           // B's
    Vec2 normal = Vec2::UnitX();  // unit; B separates by moving along +normal, A along −normal
    double penetration = 0.0;     // how far apart to move them; > 0 means overlap
};

// Whether the rules test this pair at all: both flagged collisions with at least one radii, not
// two containers, not a container with an object flagged ignore_containers, and container pairs
// only when `containers` is on.
bool pairIsTested(const ObjectPose& a, const ObjectPose& b, bool containers);

// The seed's narrow phase, with its two arithmetic slips fixed:
//   Acr = A's radii whose world centre is closest to B's position; Bcr = B's radii closest to
//   Acr's world centre (ties: first in file order); u = Bcr centre − Acr centre (u = +x when 0).
//   Contact:   rA = radius of Acr toward u, rB = radius of Bcr toward −u; hit iff |u|² ≤ (rA + rB)².
//   Container C holding O: R = radius of C toward O, r = radius of O the same way; hit iff |u| + r ≥ R.
PairTest testPair(const ObjectPose& a, const ObjectPose& b);

}  // namespace polar
