#pragma once
#include <cstdint>
#include <vector>

#include "polar/world.h"

namespace polar {

// A small seeded generator whose sequence is the same on every platform (polar/splitmix64.h; the
// standard library's distributions are not specified bit for bit, so they are not used).
class SceneRandom {
  public:
    explicit SceneRandom(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next();
    // Uniform in [lo, hi).
    double uniform(double lo, double hi);
    // Uniform in [0, n).
    std::uint32_t below(std::uint32_t n);
    bool chance(double p) { return uniform(0.0, 1.0) < p; }

  private:
    std::uint64_t state_;
};

// Rock-like adaptive bounds of mean radius `size` (bound-space pixels): `boundCount` bounds
// (the first about the centre, the others off-centre lobes), 7–12 jittered samples each.
BoundsPtr makeRockBounds(SceneRandom& random, double size, int boundCount, bool interpolate);

// A scene as tests and benchmarks build it: world settings, objects in creation order, and the
// side of the square the objects were scattered in.
struct GeneratedScene {
    WorldDef def;
    std::vector<ObjectDef> objects;
    double side = 0.0;
};

// The scale benchmark's scene: n moving rocks (sizes 10–30 px, a third of them with 2–3 radii,
// flagged physics and collisions) scattered uniformly at a fixed density: on average `neighbours`
// other centres within contact reach of each object, contact reach being R_a + R_b for reach radii
// R (the farthest any outline point gets from the object's position). Effects: physics, collisions,
// response. The bounds come from a pool of 32 shapes, shared as sprites share them in a game.
GeneratedScene makeRockField(std::uint64_t seed, std::size_t n, double neighbours, BroadPhase method);
// The same world, built without holding every definition at once (for memory measurements), its
// step on `workers` threads (WorldDef::workers).
World buildRockField(std::uint64_t seed, std::size_t n, double neighbours, BroadPhase method,
                     std::uint32_t workers = 1);

// A scene that tries the broad phases' corner cases: sizes from 1 to 60 px with a few giants, compound
// and single radii with and without interpolation, non-uniform, mirrored and zero scales, ghosts,
// static and moving objects, an arena container (objects inside, astride its wall and outside) and
// objects ignoring it, objects without radii or without the collisions flag. Every effect but ccd.
GeneratedScene makeMixedScene(std::uint64_t seed, std::size_t n, BroadPhase method);

// A world holding the scene's objects.
World buildWorld(const GeneratedScene& scene);

}  // namespace polar
