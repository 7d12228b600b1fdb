#pragma once
#include <cstdint>

#include "polar/game_object.h"
#include "polar/state_hash.h"

namespace polar {

// What World::hash covers for one object, fed into `hash`: its id, transform factors (position,
// angle, scale), velocity, spin, damping and flags, each double to the last bit. Names, sprites and
// bounds are left out: they never change while an object lives, and replays check the files the
// bounds came from separately.
void addObjectState(StateHash& hash, const GameObject& object);

// The hash of one object's state alone (addObjectState on a fresh StateHash), for telling which
// objects differ when two worlds' hashes do.
std::uint64_t objectHash(const GameObject& object);

}  // namespace polar
