#pragma once
// Box2D 2.4 (Debian's libbox2d-dev) stepping the scale benchmark's rock field, so that the scale
// table can put a measured reference beside Polarcade's figures.
#include "polar/world.h"

namespace polar::bench {

// What Box2D spent per step (medians over the measured steps, milliseconds) and what it found.
struct Box2dResult {
    bool ok = false;
    double stepMs = 0;         // b2Profile::step: the whole b2World::Step
    double pairsNarrowMs = 0;  // b2Profile::broadphase + collide: finding pairs plus the narrow phase
    double broadPhaseMs = 0;   // b2Profile::broadphase: moving proxies and finding new pairs
    double collideMs = 0;      // b2Profile::collide: updating every contact's manifold
    double solveMs = 0;        // b2Profile::solve: islands, the contact solver, integration
    double wallMs = 0;         // b2World::Step by the clock
    double contacts = 0;       // contacts (pairs whose fattened boxes overlap), first measured steps
    double touching = 0;       // of those, touching (manifold points), first measured steps
    double beginContacts = 0;  // BeginContact calls per step (new touching pairs), first measured steps
};

// Builds the same field in Box2D, scaled to 10 units per metre (one dynamic body per object at its position,
// angle, velocity and spin; one circle fixture per Bound at its centre with its largest radius;
// restitution `restitution`, no friction, unit density; one static container: a chain loop around the field),
// steps it `warmup` times, then measures `steps` steps of 1/60 s with 8 velocity and 3 position
// iterations, continuous collision off and sleeping off (Polarcade's field has neither).
Box2dResult measureBox2d(const World& field, double restitution, int warmup, int steps,
                         std::size_t countedSteps);

}  // namespace polar::bench
