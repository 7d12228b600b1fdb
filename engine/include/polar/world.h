#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "polar/accuracy.h"
#include "polar/collision.h"
#include "polar/effects.h"
#include "polar/game_object.h"

namespace polar {

// How a world runs: which effects, and how bouncy collisions are.
struct WorldDef {
    Effects effects = 0;
    double restitution = 0.8;  // 0 stops dead along the normal, 1 bounces back at full speed
    Accuracy accuracy = Accuracy::Bounds;  // the narrow phase's level (accuracy.h)
};

// One tested pair of a detection pass, by object index in creation order (a < b).
struct PairReport {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
    PairTest test;
};

// The objects of a scene and the rules that move them, one fixed step at a time.
//
// Why this step order? Each step integrates motion (physics), then runs one detection pass over the
// state it produced, then applies the responses pair by pair in pair order (A's creation order, then
// B's), contacts first and container walls last, so the wall has the final word. Detection sees one
// consistent snapshot, so which pairs hit never depends on the order in which earlier responses
// moved things; only the responses themselves run in sequence. Everything
// is iterated in creation order and nothing reads a clock, so a step is a pure function of the state.
class World {
public:
    explicit World(const WorldDef& def = {});

    // Adds an object and returns its id. Its name must be non-empty and unique (asserted).
    ObjectId add(ObjectDef def);
    // Removes an object; returns false when there is no such id.
    bool remove(ObjectId id);

    GameObject* find(ObjectId id);
    const GameObject* find(ObjectId id) const;
    GameObject* findByName(std::string_view name);
    bool nameTaken(std::string_view name) const { return names_.count(std::string(name)) != 0; }
    // In creation order.
    std::vector<GameObject>& objects() { return objects_; }
    const std::vector<GameObject>& objects() const { return objects_; }

    const WorldDef& def() const { return def_; }
    bool runs(Effect effect) const { return (def_.effects & effect) != 0; }

    // Advances the world by dt seconds.
    void step(double dt);

    // One detection pass over the current state; moves nothing. With `all`, every tested pair is
    // reported, otherwise hits only. Pairs come in pair order.
    std::vector<PairReport> detect(bool all) const;
    // The hits of the last step, in pair order.
    const std::vector<PairReport>& hits() const { return hits_; }

private:
    void integrate(double dt);
    void respond(const PairReport& hit);
    std::size_t indexOf(ObjectId id) const;

    WorldDef def_;
    std::vector<GameObject> objects_;
    std::unordered_map<std::string, ObjectId> names_;
    ObjectId nextId_ = 1;
    std::vector<PairReport> hits_;
};

}  // namespace polar
