#pragma once
// What an object takes part in: the flags the world, the broad phase and the narrow phase read.
// Their names and the effects they call for are in game_object.h.
#include <cstdint>

namespace polar {

// What an object takes part in, as a bit set. A flag acts only while the world runs its effect
// (effectsFor below); a scene file that sets a flag without its effect is an error.
enum ObjectFlag : std::uint32_t {
    kPhysics = 1u << 0,           // integrated and damped by the physics effect
    kCollisions = 1u << 1,        // takes part in collision detection
    kGhost = 1u << 2,             // never moved by a collision (bullets, pickups, a fixed arena)
    kContainer = 1u << 3,         // holds objects inside its outline instead of keeping them out
    kIgnoreContainers = 1u << 4,  // passes through container walls
    kFast = 1u << 5,              // cast along its step's motion by the ccd effect (bullets)
};
using ObjectFlags = std::uint32_t;

}  // namespace polar
