#include "scale_box2d.h"

#include <box2d/box2d.h>

#include <algorithm>
#include <vector>

#include "harness/clock.h"
#include "harness/samples.h"

namespace polar::bench {

namespace {

// Box2D's tolerances (linear slop 5 mm, proxy margins 10 cm, at most 2 m per step) are tuned for
// moving objects of 0.1 to 10 m, so the field goes in at 10 world units (pixels) per metre: rocks
// of 1 to 3 m at 2 to 8 m/s. At one unit per metre Box2D's broad phase alone took 8 times longer.
constexpr double kMetresPerUnit = 0.1;

// Counts new touching pairs, the nearest thing Box2D has to Polarcade's hit reports.
class CountBegins final : public b2ContactListener {
  public:
    void BeginContact(b2Contact*) override { ++begins; }
    long begins = 0;
};

}  // namespace

Box2dResult measureBox2d(const World& field, double restitution, int warmup, int steps,
                         std::size_t countedSteps) {
    Box2dResult r;
    b2World world(b2Vec2(0.0f, 0.0f));
    world.SetAllowSleeping(false);
    world.SetContinuousPhysics(false);
    CountBegins listener;
    world.SetContactListener(&listener);

    const double k = kMetresPerUnit;
    double minX = 1e300, minY = 1e300, maxX = -1e300, maxY = -1e300, maxReach = 0;
    for (const GameObject& o : field.objects()) {
        const Vec2& p = o.transform.position();
        b2BodyDef body;
        body.type = b2_dynamicBody;
        body.position.Set(float(k * p.x()), float(k * p.y()));
        body.angle = float(o.transform.rotation());
        body.linearVelocity.Set(float(k * o.velocity.x()), float(k * o.velocity.y()));
        body.angularVelocity = float(o.spin);
        b2Body* b = world.CreateBody(&body);
        for (const Bound& radii : o.boundsOrEmpty()) {
            b2CircleShape circle;
            circle.m_p.Set(float(k * radii.centre().x()), float(k * radii.centre().y()));
            circle.m_radius = float(k * radii.maxRadius());
            b2FixtureDef fixture;
            fixture.shape = &circle;
            fixture.density = 1.0f;
            fixture.friction = 0.0f;
            fixture.restitution = float(restitution);
            b->CreateFixture(&fixture);
            maxReach = std::max(maxReach, k * (radii.centre().norm() + radii.maxRadius()));
        }
        minX = std::min(minX, k * p.x()), maxX = std::max(maxX, k * p.x());
        minY = std::min(minY, k * p.y()), maxY = std::max(maxY, k * p.y());
    }
    // The container: a loop one reach outside every centre, so rocks meet it only once they roam.
    const float m = float(2 * maxReach);
    const b2Vec2 corners[4] = {{float(minX) - m, float(minY) - m},
                               {float(maxX) + m, float(minY) - m},
                               {float(maxX) + m, float(maxY) + m},
                               {float(minX) - m, float(maxY) + m}};
    b2BodyDef wallDef;
    b2Body* walls = world.CreateBody(&wallDef);
    b2ChainShape loop;
    loop.CreateLoop(corners, 4);
    b2FixtureDef wallFixture;
    wallFixture.shape = &loop;
    wallFixture.friction = 0.0f;
    wallFixture.restitution = float(restitution);
    walls->CreateFixture(&wallFixture);

    const float dt = 1.0f / 60.0f;
    for (int s = 0; s < warmup; ++s) world.Step(dt, 8, 3);
    std::vector<double> step, pairsNarrow, broad, collide, solve, wall, contacts, touching, begins;
    for (int s = 0; s < steps; ++s) {
        listener.begins = 0;
        const Stopwatch watch(CpuClock::None);
        world.Step(dt, 8, 3);
        const double wallMs = watch.wallMs();
        const b2Profile& p = world.GetProfile();
        step.push_back(p.step);
        pairsNarrow.push_back(double(p.broadphase) + double(p.collide));
        broad.push_back(p.broadphase);
        collide.push_back(p.collide);
        solve.push_back(p.solve);
        wall.push_back(wallMs);
        if (std::size_t(s) < countedSteps) {
            long touchingNow = 0;
            for (b2Contact* c = world.GetContactList(); c; c = c->GetNext()) touchingNow += c->IsTouching();
            contacts.push_back(world.GetContactCount());
            touching.push_back(double(touchingNow));
            begins.push_back(double(listener.begins));
        }
    }
    r.stepMs = median(step);
    r.pairsNarrowMs = median(pairsNarrow);
    r.broadPhaseMs = median(broad);
    r.collideMs = median(collide);
    r.solveMs = median(solve);
    r.wallMs = median(wall);
    r.contacts = median(contacts);
    r.touching = median(touching);
    r.beginContacts = median(begins);
    r.ok = true;
    return r;
}

}  // namespace polar::bench
