#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "polar/accuracy.h"
#include "polar/broad_phase.h"
#include "polar/collision.h"
#include "polar/effects.h"
#include "polar/game_object.h"
#include "polar/step_stats.h"
#include "polar/tasks.h"

namespace polar {

// How a world runs: which effects, how pairs are found, and how bouncy collisions are.
struct WorldDef {
    Effects effects = 0;
    double restitution = 0.8;              // 0 stops dead along the normal, 1 bounces back at full speed
    Accuracy accuracy = Accuracy::Bounds;  // the narrow phase's level (accuracy.h)
    BroadPhase broadPhase = BroadPhase::Grid;
    // Threads for the step. Results are bit-identical at any count. 1 runs everything on the
    // calling thread and starts no thread; N > 1 runs the step's parallel phases on a ThreadPool
    // of N workers that the world owns. With `tasks` set, the world uses that task system instead
    // (its workerCount() counts) and `workers` is ignored; it must outlive the world.
    std::uint32_t workers = 1;
    TaskSystem* tasks = nullptr;
    // A parallel phase with fewer items than this (objects, candidates, grid entries) runs on the
    // calling thread: waking workers costs microseconds, more than a small phase takes. Results do
    // not depend on it; tests set 1 to run small worlds through the parallel paths.
    std::uint32_t parallelMin = kDefaultParallelMin;
    static constexpr std::uint32_t kDefaultParallelMin = 4096;
};

// The narrow phase on two objects as they stand, at an accuracy level (accuracy.h): the world's own
// test, bit for bit, with A in A's place (the world puts the one earlier in the scene there). Flags
// other than container are not looked at, so a game may ask about ghosts too. Both need radii
// (asserted).
PairTest testObjects(const GameObject& a, const GameObject& b, Accuracy accuracy = Accuracy::Bounds);

// The objects of a scene and the rules that move them, one fixed step at a time.
//
// Why this step order? Each step integrates motion (physics), casts fast objects (ccd), then runs
// one detection pass over the state it produced, then applies the responses pair by pair in pair
// order (A's creation order, then B's), contacts first and container walls last, so the wall has
// the final word. Detection sees one consistent snapshot, so which pairs hit never depends on the
// order in which earlier responses moved things; only the responses themselves run in sequence.
// Everything is iterated in creation order and nothing the simulation reads comes from a clock, so
// a step is a pure function of the state, whatever broad phase finds the pairs.
//
// Why lists per effect? An effect a scene does not run costs nothing: the World keeps, per running
// effect, the indices of the objects whose flags take part (physics, collisions, fast), so a step
// visits only those, and an absent effect has no list, no pass and no buffer. Objects that never move
// cost nothing per step beyond being collision candidates. Change flags with setFlags(), which keeps
// the lists right; writing GameObject::flags directly bypasses them (asserted in Debug builds).
//
// Why may a step use several threads and still be a pure function of the state? The parallel phases
// (per-step data and poses, the grid's pair search and pair tests, integration) write only outputs
// owned by their items or their block, joined in item order; the responses, which move objects that
// other pairs read, stay on one thread in pair order. A world that owns its pool (WorldDef::workers)
// gives a copy a pool of its own with as many workers; one given a task system (WorldDef::tasks)
// shares it with its copies.
class World {
  public:
    // A copy is independent and steps to the same bits as the original (its threads: see above). A
    // moved-from world may only be assigned to or destroyed.
    explicit World(const WorldDef& def = {});
    World(const World& other);
    World(World&& other) noexcept;
    World& operator=(World other) noexcept;
    ~World();

    // Adds an object and returns its id. A name, when given, must be unique in the world (asserted);
    // an empty name makes an object that findByName never finds (bullets, debris).
    ObjectId add(ObjectDef def);
    // Removes an object; returns false when there is no such id.
    bool remove(ObjectId id);
    // Sets an object's flags and the per-effect lists that follow from them; false when no such id.
    bool setFlags(ObjectId id, ObjectFlags flags);
    // Makes room for this many objects, so building a large world does not reallocate as it grows.
    void reserve(std::size_t objects);

    GameObject* find(ObjectId id);
    const GameObject* find(ObjectId id) const;
    // The object of that non-empty name, or null.
    GameObject* findByName(std::string_view name);
    const GameObject* findByName(std::string_view name) const;
    // Whether an object has that name; never true for "".
    bool nameTaken(std::string_view name) const;
    // Every object, in creation order. A span, not the vector: its fields may be changed in place,
    // but objects come and go only through add and remove, which keep the per-effect lists right;
    // flags change through setFlags (a direct write is asserted in Debug builds).
    std::span<GameObject> objects();
    std::span<const GameObject> objects() const;

    const WorldDef& def() const;
    bool runs(Effect effect) const;
    // The threads a step may use: the task system's workers, or 1 without one.
    std::uint32_t workerCount() const;
    // Switches the broad phase. Results do not change, only the speed of finding them.
    void setBroadPhase(BroadPhase method);

    // Advances the world by dt seconds. In a steady state it allocates nothing.
    void step(double dt);

    // One detection pass over the current state; moves nothing. With `all`, every pair the rules
    // test (the all-pairs loop); otherwise the hits, found with the world's broad phase. Pairs come
    // in pair order.
    std::vector<PairReport> detect(bool all) const;
    // The hits of the last step, in pair order.
    std::span<const PairReport> hits() const;
    // The ids of the objects that `id` touched during the last step, in pair order (a partner
    // removed since is still listed); empty for an object that touched nothing or does not exist.
    std::span<const ObjectId> collidedWith(ObjectId id) const;
    std::uint64_t hash() const;  // FNV-1a of every object's state in creation order (world_hash.h), bit-exact

    // What each effect did in the last step, and the sum over every step so far.
    const StepStats& lastStepStats() const;
    const StepStats& totalStats() const;
    std::uint64_t stepCount() const;
    // Measures time per effect (off by default). The times are reported, never used.
    void setTiming(bool on);
    bool timing() const;

  private:
    friend struct WorldSnapshotAccess;  // saveSnapshot and restoreSnapshot (world_snapshot.h)

    struct Impl;  // the state and the step's machinery (engine/src/world/world_impl.h)
    std::unique_ptr<Impl> impl_;
};

}  // namespace polar
