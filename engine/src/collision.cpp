#include "polar/collision.h"

#include <cmath>

namespace polar {
namespace {

// The index of the radii whose world centre (position + L·centre) is closest to `target`, given as
// target − position so that far-from-origin positions cancel before any rounding. Ties: the first.
std::uint32_t closestRadiiTo(const ObjectPose& pose, const Vec2& targetFromPosition) {
    std::uint32_t best = 0;
    double bestDistance = INFINITY;
    for (std::size_t k = 0; k < pose.radii->size(); ++k) {
        double d = (pose.linear * (*pose.radii)[k].centre() - targetFromPosition).squaredNorm();
        if (d < bestDistance) {
            bestDistance = d;
            best = static_cast<std::uint32_t>(k);
        }
    }
    return best;
}

}  // namespace

ObjectPose ObjectPose::of(const GameObject& object) {
    return ObjectPose{object.transform.position(), object.transform.linear(), &object.radii(), object.flags};
}

const char* contactKindName(ContactKind kind) { return kind == ContactKind::Container ? "container" : "contact"; }

bool pairIsTested(const ObjectPose& a, const ObjectPose& b, bool containers) {
    if (!(a.flags & kCollisions) || !(b.flags & kCollisions)) return false;
    if (a.radii == nullptr || b.radii == nullptr || a.radii->empty() || b.radii->empty()) return false;
    bool containerA = a.flags & kContainer, containerB = b.flags & kContainer;
    if (containerA && containerB) return false;
    if (containerA || containerB) {
        if (!containers) return false;
        const ObjectPose& held = containerA ? b : a;
        if (held.flags & kIgnoreContainers) return false;
    }
    return true;
}

PairTest testPair(const ObjectPose& a, const ObjectPose& b) {
    PairTest t;
    Vec2 bFromA = b.position - a.position;  // exact for nearby objects, even 10⁷ units out
    t.radiiA = closestRadiiTo(a, bFromA);
    Vec2 acrOffset = a.linear * (*a.radii)[t.radiiA].centre();
    t.radiiB = closestRadiiTo(b, acrOffset - bFromA);
    const CollisionRadii& acr = (*a.radii)[t.radiiA];
    const CollisionRadii& bcr = (*b.radii)[t.radiiB];

    Vec2 u = bFromA + b.linear * bcr.centre() - acrOffset;
    double squared = u.squaredNorm();
    t.distance = std::sqrt(squared);
    Vec2 dir = squared == 0.0 ? Vec2(Vec2::UnitX()) : Vec2(u / t.distance);

    bool containerA = a.flags & kContainer, containerB = b.flags & kContainer;
    if (!containerA && !containerB) {
        t.kind = ContactKind::Contact;
        t.ra = acr.worldRadius(a.linear, dir);
        t.rb = bcr.worldRadius(b.linear, -dir);
        double sum = t.ra + t.rb;
        t.hit = squared <= sum * sum;  // squared distance against the squared sum: like with like
        t.penetration = sum - t.distance;
        t.normal = dir;
        return t;
    }
    // C holds O. `out` points from C's centre toward O; both radii are taken in that direction, so
    // r is O's side facing the wall, and the wall is met when that side reaches it.
    t.kind = ContactKind::Container;
    Vec2 out = containerA ? dir : Vec2(-dir);
    double wall = (containerA ? acr : bcr).worldRadius(containerA ? a.linear : b.linear, out);
    double side = (containerA ? bcr : acr).worldRadius(containerA ? b.linear : a.linear, out);
    t.ra = containerA ? wall : side;
    t.rb = containerA ? side : wall;
    t.hit = t.distance + side >= wall;
    t.penetration = t.distance + side - wall;
    t.normal = -dir;  // O moves back toward C's centre whichever of A and B it is
    return t;
}

}  // namespace polar
