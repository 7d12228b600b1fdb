// Hello, world: the engine with no window. A round wall holds two rocks thrown at each other; every
// step prints what touched what.
#include <cstdio>
#include <string_view>

#include <polar/polar.h>

using namespace polar;

int main(int argc, char** argv) {
    if (argc > 1) {  // it takes no options: --help says so, anything else is an error
        bool help = std::string_view(argv[1]) == "--help" && argc == 2;
        std::fputs("Usage: polar-example-hello\nSteps a wall and two rocks for 4 s; prints every hit.\n",
                   help ? stdout : stderr);
        return help ? 0 : 2;
    }
    const ObjectFlags rock = kPhysics | kCollisions;
    WorldDef def;
    def.effects = effectsFor(rock | kContainer) | kEffectResponse;  // move, collide, contain, bounce
    World world(def);

    ObjectDef wall;
    wall.name = "wall";
    wall.bounds = circleBounds(100.0);
    wall.flags = kCollisions | kContainer | kGhost;  // holds what is inside it; hits never move it
    world.add(wall);

    ObjectDef left;
    left.name = "left rock";
    left.bounds = circleBounds(10.0);
    left.transform.setPosition(Vec2(-50.0, 0.0));
    left.velocity = Vec2(60.0, 0.0);  // world units per second
    left.flags = rock;
    world.add(left);

    ObjectDef right = left;
    right.name = "right rock";
    right.transform.setPosition(Vec2(50.0, 5.0));
    right.velocity = Vec2(-60.0, 0.0);
    world.add(right);

    for (int tick = 1; tick <= 240; ++tick) {
        world.step(1.0 / 60.0);
        for (const PairReport& hit : world.hits())
            std::printf("tick %3d: %s and %s touch (%s)\n", tick, world.objects()[hit.a].name.c_str(),
                        world.objects()[hit.b].name.c_str(), contactKindName(hit.test.kind));
    }
    std::printf("hash %016llx\n", static_cast<unsigned long long>(world.hash()));
}
