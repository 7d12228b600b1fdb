#pragma once
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "broad_phase/detector.h"
#include "polar/world.h"
#include "world/ccd.h"
#include "world/name_index.h"
#include "world/shared_response.h"

namespace polar {

// Everything a World holds, and the step's phases.
//
// Why behind World::Impl? polar/world.h then shows what a program may use and nothing else: the
// name index, the per-effect lists, the detector and the step's phases change without the public
// header changing, and without recompiling every file that includes it. World's member functions
// reach the state here; the step and its phases are the Impl's own (world.cpp); snapshots
// read and write it whole (world_snapshot.cpp, through WorldSnapshotAccess).
struct World::Impl {
    explicit Impl(const WorldDef& def);
    // The copied state, with fresh scratch buffers and a pool of its own (see World's comment).
    Impl(const Impl& other);
    Impl& operator=(const Impl&) = delete;

    bool runs(Effect effect) const { return (def_.effects & effect) != 0; }
    // objects_.size() when there is no such id.
    std::size_t indexOf(ObjectId id) const;
    std::span<const PairReport> hits() const {
        return detector_ ? detector_->hits() : std::span<const PairReport>();
    }
    bool listsMatchFlags() const;

    void step(double dt);
    void recordFastStarts();
    void integrate(double dt);
    void collide();
    void respondAll(EffectStats& response);  // every hit, in order (see step())
    void respond(const PairReport& hit);
    void listCollided();
    void measureMemory();

    WorldDef def_;
    std::vector<GameObject> objects_;  // in creation order, so ids ascend
    NameIndex names_;
    ObjectId nextId_ = 1;

    // Per running effect: indices (ascending) of the objects that take part.
    std::vector<std::uint32_t> physicsList_;
    std::vector<std::uint32_t> collisionList_;
    std::vector<std::uint32_t> fastList_;
    // What each object touched in the last step: object i's partners' ids are
    // collidedIds_[collidedBegin_[i], collidedBegin_[i + 1]). Both are empty when nothing was touched.
    std::vector<std::uint32_t> collidedBegin_;
    std::vector<ObjectId> collidedIds_;
    std::vector<FastStart> fastStarts_;
    std::unique_ptr<Detector> detector_;  // only when collisions run
    std::unique_ptr<FastCast> cast_;      // only when ccd runs
    SharedResponse shared_;               // the lists and responses on several workers
    std::unique_ptr<ThreadPool> pool_;    // only when the world owns its workers
    TaskSystem* tasks_ = nullptr;         // def_.tasks, pool_, or null: one thread

    std::uint64_t layout_ = 0;  // changes whenever an effect's list may have
    StepStats last_;
    StepStats total_;
    std::uint64_t steps_ = 0;
    bool timing_ = false;

  private:
    void startTasks();  // the task system from def_: given, owned, or none
};

}  // namespace polar
