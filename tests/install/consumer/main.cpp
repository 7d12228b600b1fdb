// A rock field's first second, through the installed headers only: a box of a container, rocks of
// several radii, an unnamed bullet; it prints every hit and the final hash.
#include <cstdio>

#include <polar/polar.h>

int main() {
    using namespace polar;
    WorldDef def;
    def.effects = effectsFor(kPhysics | kCollisions | kContainer | kFast) | kEffectResponse;
    World world(def);

    ObjectDef box;
    box.name = "box";
    box.bounds = makeBounds(Bound::fromDegrees(
        Vec2::Zero(),
        {{0, 80}, {45, 113}, {90, 80}, {135, 113}, {180, 80}, {225, 113}, {270, 80}, {315, 113}}, true));
    box.flags = kCollisions | kContainer | kGhost;
    world.add(box);

    const BoundsPtr pebble = circleBounds(6.0);
    for (int i = 0; i < 4; ++i) {
        ObjectDef rock;
        rock.name = "rock-" + std::to_string(i);
        rock.bounds = i == 3 ? makeBounds({Bound(Vec2(-5, 0), 6.0), Bound(Vec2(5, 0), 6.0)}) : pebble;
        rock.transform = Transform(Vec2(-40.0 + 25.0 * i, 10.0 * (i % 2)), 0.3 * i, Vec2(1.0, 1.0));
        rock.velocity = Vec2(30.0 - 20.0 * i, 15.0 * i);
        rock.spin = 1.0;
        rock.flags = kPhysics | kCollisions;
        world.add(rock);
    }
    ObjectDef bullet;  // unnamed: only its id finds it
    bullet.bounds = circleBounds(1.0);
    bullet.transform.setPosition(Vec2(0.0, -60.0));
    bullet.velocity = Vec2(0.0, 2000.0);
    bullet.flags = kPhysics | kCollisions | kFast;
    ObjectId bulletId = world.add(bullet);

    for (int tick = 1; tick <= 60; ++tick) {
        world.step(1.0 / 60.0);
        for (const PairReport& hit : world.hits()) {
            const GameObject& a = world.objects()[hit.a];
            const GameObject& b = world.objects()[hit.b];
            auto label = [](const GameObject& o) { return o.name.empty() ? "the bullet" : o.name.c_str(); };
            if (hit.test.kind == ContactKind::Container) {
                const GameObject& wall = a.has(kContainer) ? a : b;
                std::printf("tick %2d: %s reached the wall of %s\n", tick, label(&wall == &a ? b : a),
                            label(wall));
            } else {
                std::printf("tick %2d: %s hit %s\n", tick, label(a), label(b));
            }
        }
    }
    std::printf("the bullet touched %zu objects in the last step; rock-3 is %s\n",
                world.collidedWith(bulletId).size(), world.findByName("rock-3") ? "there" : "missing");
    std::printf("hash %016llx\n", static_cast<unsigned long long>(world.hash()));
}
