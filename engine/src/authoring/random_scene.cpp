#include "polar/authoring/random_scene.h"

#include <cmath>
#include <string>

#include "polar/splitmix64.h"

namespace polar {

std::uint64_t SceneRandom::next() {
    return splitmix64(state_);
}

double SceneRandom::uniform(double lo, double hi) {
    double unit = static_cast<double>(next() >> 11) * 0x1.0p-53;  // 53 random bits in [0, 1)
    return lo + (hi - lo) * unit;
}

std::uint32_t SceneRandom::below(std::uint32_t n) {
    return static_cast<std::uint32_t>(next() % n);
}

BoundsPtr makeRockBounds(SceneRandom& random, double size, int boundCount, bool interpolate) {
    auto bounds = std::make_shared<Bounds>();
    for (int k = 0; k < boundCount; ++k) {
        // The main body, then lobes of 45–70 % of its size whose centres sit 40–60 % of it out.
        double lobe = k == 0 ? size : size * random.uniform(0.45, 0.7);
        Vec2 centre = Vec2::Zero();
        if (k > 0) {
            double s, c;
            trig::sincos(random.uniform(0.0, kTwoPi), s, c);
            centre = size * random.uniform(0.4, 0.6) * Vec2(c, s);
        }
        int count = 7 + static_cast<int>(random.below(6));
        std::vector<RadiusSample> samples;
        for (int i = 0; i < count; ++i) {
            // Evenly spread angles jittered by up to a quarter gap keep every gap under 180°.
            double gap = kTwoPi / count;
            double angle = (i + random.uniform(-0.25, 0.25)) * gap;
            samples.push_back({angle, lobe * random.uniform(0.75, 1.25)});
        }
        bounds->emplace_back(centre, std::move(samples), interpolate);
    }
    return bounds;
}

namespace {

// The reach radius of bounds under scale s: max_k |s·c_k| + s·maxRadius_k.
double reachRadius(const Bounds& bounds, double scale) {
    double reach = 0.0;
    for (const Bound& radii : bounds)
        reach = std::max(reach, scale * (radii.centre().norm() + radii.maxRadius()));
    return reach;
}

Vec2 randomDirection(SceneRandom& random) {
    double s, c;
    trig::sincos(random.uniform(0.0, kTwoPi), s, c);
    return Vec2(c, s);
}

// Builds the rock field one object at a time: a first pass over the shape choices fixes the side
// of the square, a second pass (the same random streams again) makes the objects.
template <class Add>
double generateRockField(std::uint64_t seed, std::size_t n, double neighbours, Add&& add) {
    SceneRandom shapes(seed);
    // A pool of shapes, as a game has a few rock sprites: sizes 10–30 px, a third compound.
    std::vector<BoundsPtr> pool;
    std::vector<double> poolReach;
    for (int k = 0; k < 32; ++k) {
        int radii = k % 3 == 0 ? 2 + static_cast<int>(shapes.below(2)) : 1;
        pool.push_back(makeRockBounds(shapes, shapes.uniform(10.0, 30.0), radii, k % 2 == 0));
        poolReach.push_back(reachRadius(*pool.back(), 1.0));
    }
    std::uint64_t objectSeed = shapes.next(), placeSeed = shapes.next();

    SceneRandom choose(objectSeed);
    double sumReach = 0.0, sumReachSquared = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        double reach = poolReach[choose.below(static_cast<std::uint32_t>(pool.size()))];
        sumReach += reach;
        sumReachSquared += reach * reach;
        choose.next();
        choose.next();
        choose.next();
    }
    // Expected neighbours within R_a + R_b: (n − 1)/side² · π·E[(R_a + R_b)²], and for independent
    // radii E[(R_a + R_b)²] = 2·E[R²] + 2·E[R]².
    double count = static_cast<double>(std::max<std::size_t>(n, 1));
    double meanReach = sumReach / count, meanSquare = sumReachSquared / count;
    double pairReachSquared = 2.0 * meanSquare + 2.0 * meanReach * meanReach;
    double side = std::sqrt(std::max(count - 1.0, 1.0) * kPi * pairReachSquared / neighbours);

    SceneRandom again(objectSeed), place(placeSeed);
    for (std::size_t i = 0; i < n; ++i) {
        ObjectDef o;
        o.name = "rock-" + std::to_string(i);
        o.bounds = pool[again.below(static_cast<std::uint32_t>(pool.size()))];
        o.flags = kPhysics | kCollisions;
        o.velocity = again.uniform(20.0, 80.0) * randomDirection(again);
        o.spin = degToRad(again.uniform(-90.0, 90.0));
        o.transform = Transform(Vec2(place.uniform(0.0, side), place.uniform(0.0, side)),
                                place.uniform(-kPi, kPi), Vec2::Ones());
        add(std::move(o));
    }
    return side;
}

WorldDef rockFieldDef(BroadPhase method) {
    WorldDef def;
    def.effects = kEffectPhysics | kEffectCollisions | kEffectResponse;
    def.broadPhase = method;
    def.restitution = 0.8;
    return def;
}

}  // namespace

GeneratedScene makeRockField(std::uint64_t seed, std::size_t n, double neighbours, BroadPhase method) {
    GeneratedScene scene;
    scene.def = rockFieldDef(method);
    scene.objects.reserve(n);
    scene.side =
        generateRockField(seed, n, neighbours, [&](ObjectDef&& o) { scene.objects.push_back(std::move(o)); });
    return scene;
}

World buildRockField(std::uint64_t seed, std::size_t n, double neighbours, BroadPhase method,
                     std::uint32_t workers) {
    WorldDef def = rockFieldDef(method);
    def.workers = workers;
    World world(def);
    world.reserve(n);
    generateRockField(seed, n, neighbours, [&](ObjectDef&& o) { world.add(std::move(o)); });
    return world;
}

GeneratedScene makeMixedScene(std::uint64_t seed, std::size_t n, BroadPhase method) {
    SceneRandom random(seed);
    GeneratedScene scene;
    scene.def.effects = kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers;
    scene.def.broadPhase = method;
    scene.def.restitution = random.uniform(0.0, 1.0);
    // Dense enough that many pairs touch: about 3 neighbours within reach for the typical object.
    scene.side = std::sqrt(static_cast<double>(n)) * 40.0;

    std::vector<BoundsPtr> pool;
    for (int k = 0; k < 24; ++k)
        pool.push_back(makeRockBounds(random, std::exp(random.uniform(std::log(1.0), std::log(40.0))),
                                      1 + static_cast<int>(random.below(3)), random.chance(0.5)));
    std::vector<BoundsPtr> giants;
    for (int k = 0; k < 3; ++k)
        giants.push_back(makeRockBounds(random, random.uniform(150.0, 600.0), 1 + k, k != 1));

    for (std::size_t i = 0; i < n; ++i) {
        ObjectDef o;
        o.name = "object-" + std::to_string(i);
        Vec2 position(random.uniform(0.0, scene.side), random.uniform(0.0, scene.side));
        Vec2 scale = Vec2::Ones();
        double kind = random.uniform(0.0, 1.0);
        if (i == 7) {
            // The arena: one container. A container holds every colliding object that does not
            // ignore containers, so a second one would pull everything outside it in. The field's
            // corners lie outside it.
            o.bounds = makeRockBounds(random, 0.6 * scene.side, 1, random.chance(0.5));
            o.flags = kCollisions | kContainer | (random.chance(0.5) ? ObjectFlags{kGhost} : ObjectFlags{0});
            position = Vec2(0.5 * scene.side, 0.5 * scene.side) +
                       random.uniform(0.0, 0.05 * scene.side) * randomDirection(random);
        } else if (kind < 0.01) {
            o.bounds = giants[random.below(static_cast<std::uint32_t>(giants.size()))];
            o.flags = kCollisions | (random.chance(0.5) ? ObjectFlags{kGhost} : ObjectFlags{0});
        } else {
            o.bounds = pool[random.below(static_cast<std::uint32_t>(pool.size()))];
            o.flags = kCollisions;
            if (random.chance(0.7)) o.flags |= kPhysics;
            if (random.chance(0.2)) o.flags |= kGhost;
            if (random.chance(0.1)) o.flags |= kIgnoreContainers;
            if (random.chance(0.02)) o.flags &= ~kCollisions;
            if (random.chance(0.02)) o.bounds = nullptr;
            if (random.chance(0.3)) scale = Vec2(random.uniform(0.5, 2.0), random.uniform(0.5, 2.0));
            if (random.chance(0.1)) scale.x() = -scale.x();  // mirrored
            if (random.chance(0.01)) scale = Vec2::Zero();
        }
        o.transform = Transform(position, random.uniform(-kPi, kPi), scale);
        if (o.flags & kPhysics) {
            o.velocity = random.uniform(0.0, 300.0) * randomDirection(random);
            o.spin = degToRad(random.uniform(-180.0, 180.0));
            o.damping = random.chance(0.5) ? random.uniform(0.0, 0.5) : 0.0;
        }
        scene.objects.push_back(std::move(o));
    }
    return scene;
}

World buildWorld(const GeneratedScene& scene) {
    World world(scene.def);
    world.reserve(scene.objects.size());
    for (const ObjectDef& object : scene.objects) world.add(object);
    return world;
}

}  // namespace polar
