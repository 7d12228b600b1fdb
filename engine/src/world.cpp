#include "polar/world.h"

#include <algorithm>
#include <cassert>

#include "polar/numeric_guard.h"

namespace polar {
namespace {

// Response leaves this fraction of the radius sum overlapping, so a resting contact stays a hit
// from step to step instead of flickering across the exact tangency (Box2D's "linear slop" idea,
// made relative so it works at any scale).
constexpr double kRelativeSlop = 1e-4;

}  // namespace

World::World(const WorldDef& def) : def_(def) {}

ObjectId World::add(ObjectDef def) {
    assert(!def.name.empty() && !nameTaken(def.name));
    GameObject object;
    static_cast<ObjectDef&>(object) = std::move(def);
    object.id = nextId_++;
    names_.emplace(object.name, object.id);
    objects_.push_back(std::move(object));
    return objects_.back().id;
}

std::size_t World::indexOf(ObjectId id) const {
    auto it = std::lower_bound(objects_.begin(), objects_.end(), id,
                               [](const GameObject& o, ObjectId i) { return o.id < i; });
    return (it != objects_.end() && it->id == id) ? static_cast<std::size_t>(it - objects_.begin())
                                                   : objects_.size();
}

bool World::remove(ObjectId id) {
    std::size_t index = indexOf(id);
    if (index == objects_.size()) return false;
    names_.erase(objects_[index].name);
    objects_.erase(objects_.begin() + static_cast<std::ptrdiff_t>(index));
    return true;
}

GameObject* World::find(ObjectId id) {
    std::size_t index = indexOf(id);
    return index == objects_.size() ? nullptr : &objects_[index];
}

const GameObject* World::find(ObjectId id) const {
    std::size_t index = indexOf(id);
    return index == objects_.size() ? nullptr : &objects_[index];
}

GameObject* World::findByName(std::string_view name) {
    auto it = names_.find(std::string(name));
    return it == names_.end() ? nullptr : find(it->second);
}

void World::step(double dt) {
    if (runs(kEffectPhysics)) integrate(dt);
    if (runs(kEffectCollisions)) {
        for (GameObject& object : objects_) object.collidedWithThisFrame.clear();
        hits_ = detect(false);
        // Contacts first, then the container walls, each in pair order: a push between two held
        // objects can no longer shove one of them through the wall after the wall was dealt with.
        for (const PairReport& hit : hits_)
            if (hit.test.kind == ContactKind::Contact) respond(hit);
        for (const PairReport& hit : hits_)
            if (hit.test.kind == ContactKind::Container) respond(hit);
    }
#ifndef NDEBUG
    // No NaN or infinity leaves the engine: checked at the step boundary.
    for (const GameObject& object : objects_) assert(isFinite(object));
    for (const PairReport& hit : hits_) assert(isFinite(hit.test));
#endif
}

void World::integrate(double dt) {
    for (GameObject& object : objects_) {
        if (!object.has(kPhysics)) continue;
        // Damping first (v ← v / (1 + dt·c)), then rotation, then translation: the seed's order.
        double keep = 1.0 / (1.0 + dt * object.damping);
        object.velocity *= keep;
        object.spin *= keep;
        object.transform.rotate(object.spin * dt);
        object.transform.translate(object.velocity * dt);
    }
}

std::vector<PairReport> World::detect(bool all) const {
    std::vector<ObjectPose> poses;
    poses.reserve(objects_.size());
    for (const GameObject& object : objects_) poses.push_back(ObjectPose::of(object));
    bool containers = runs(kEffectContainers);
    std::vector<PairReport> reports;
    for (std::uint32_t i = 0; i < poses.size(); ++i) {
        for (std::uint32_t j = i + 1; j < poses.size(); ++j) {
            if (!pairIsTested(poses[i], poses[j], containers)) continue;
            PairTest test = testPair(poses[i], poses[j], def_.accuracy);
            if (all || test.hit) reports.push_back({i, j, test});
        }
    }
    return reports;
}

void World::respond(const PairReport& hit) {
    GameObject& a = objects_[hit.a];
    GameObject& b = objects_[hit.b];
    a.collidedWithThisFrame.push_back(b.id);
    b.collidedWithThisFrame.push_back(a.id);
    if (!runs(kEffectResponse)) return;

    // The ghost flag alone says whose movement a collision may change.
    bool movesA = !a.has(kGhost), movesB = !b.has(kGhost);
    if (!movesA && !movesB) return;
    // A wall is measured again where the contacts before it left the object (the hit itself was
    // decided on the snapshot), so the object ends the step inside whatever pushed it.
    const PairTest t =
        hit.test.kind == ContactKind::Container ? testPair(ObjectPose::of(a), ObjectPose::of(b), def_.accuracy) : hit.test;
    const Vec2& n = t.normal;

    double correction = t.penetration - kRelativeSlop * (t.ra + t.rb);
    if (correction > 0) {
        double shareA = movesA ? (movesB ? 0.5 : 1.0) : 0.0;
        double shareB = movesB ? (movesA ? 0.5 : 1.0) : 0.0;
        a.transform.translate(-correction * shareA * n);
        b.transform.translate(correction * shareB * n);
    }

    // Reflect the approaching part of the relative velocity along n: vₙ' = −e·vₙ, shared between
    // the movers with physics as between equal masses; a lone mover bounces off the other.
    double weightA = (movesA && a.has(kPhysics)) ? 1.0 : 0.0;
    double weightB = (movesB && b.has(kPhysics)) ? 1.0 : 0.0;
    if (weightA + weightB == 0.0) return;
    double approach = (b.velocity - a.velocity).dot(n);
    if (approach >= 0.0) return;
    double impulse = -(1.0 + def_.restitution) * approach / (weightA + weightB);
    a.velocity -= impulse * weightA * n;
    b.velocity += impulse * weightB * n;
}

}  // namespace polar
