#pragma once
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "polar/bound.h"
#include "polar/effects.h"
#include "polar/object_flags.h"
#include "polar/transform.h"

namespace polar {

// The file name of a single flag ("ignore_containers"), and back.
const char* flagName(ObjectFlag flag);
std::optional<ObjectFlag> flagFromName(std::string_view name);
// Every flag, in declaration order.
inline constexpr ObjectFlag kAllFlags[] = {kPhysics,   kCollisions,       kGhost,
                                           kContainer, kIgnoreContainers, kFast};

// The effects a world must run for these flags to act, together with what those effects need in
// turn: physics → physics; collisions → collisions; container → containers and collisions; fast →
// ccd, physics and collisions. ghost and ignore_containers only qualify collisions and add nothing.
constexpr Effects effectsFor(ObjectFlags flags) {
    Effects effects = 0;
    if (flags & kPhysics) effects |= kEffectPhysics;
    if (flags & kCollisions) effects |= kEffectCollisions;
    if (flags & kContainer) effects |= kEffectContainers | kEffectCollisions;
    if (flags & kFast) effects |= kEffectCcd | kEffectPhysics | kEffectCollisions;
    return effects;
}
// The flags among `flags` that do nothing under `effects`: those whose effectsFor is not all running.
constexpr ObjectFlags inertFlags(ObjectFlags flags, Effects effects) {
    ObjectFlags inert = 0;
    for (ObjectFlag flag : kAllFlags)
        if ((flags & flag) && (effectsFor(flag) & ~effects)) inert |= flag;
    return inert;
}

// A creation number: objects are stored, stepped and hashed in ascending id order.
using ObjectId = std::uint32_t;

// How to create an object: everything but its id. Defaults make a static, untransformed object.
// What the game draws it with, and which file its bounds came from, are the game's to keep (through
// userData, say): the engine never looks at them.
// Field order: what collision detection reads every step (bounds, transform, flags) sits last and
// together, 84 bytes that span two cache lines or three, never four.
struct ObjectDef {
    std::string name;              // unique in its world, or empty for an object nobody looks up by name
    Vec2 velocity = Vec2::Zero();  // world units per second
    double spin = 0.0;             // radians per second (files give degrees per second)
    double damping = 0.0;          // per second: v ← v / (1 + dt·damping)
    // The game's own word on this object: an index into its tables, a key, anything that fits. The
    // engine copies it with the object, keeps it in snapshots and never reads it; it is not hashed.
    std::uint64_t userData = 0;
    BoundsPtr bounds;  // may be null: no radii
    Transform transform;
    ObjectFlags flags = 0;
};

// A thing in the world: a transform, optional adaptive bounds, motion and flags.
//
// Why a plain struct? Game logic reads and writes objects freely between steps (steer the ship,
// split a rock), and the World owns the rules. What an object touched during the last step is the
// World's to answer (World::collidedWith), from one list built per step: a list per object cost
// 56 bytes for every object, touched or not, and a scattered write per hit.
struct GameObject : ObjectDef {
    ObjectId id = 0;

    bool has(ObjectFlag flag) const { return (flags & flag) != 0; }
    // Its bounds (every Bound, in file order), or an empty list without bounds. Inline: the
    // per-step data reads it for every candidate.
    const Bounds& boundsOrEmpty() const {
        static const Bounds kNone;
        return bounds ? *bounds : kNone;
    }
};

}  // namespace polar
