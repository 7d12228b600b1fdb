#include "polar/world.h"

#include <algorithm>
#include <cassert>
#include <chrono>

#include "broad_phase/counting_sort.h"
#include "narrow_phase/pair_test.h"
#include "tasks/parallel_for.h"
#include "world/numeric_guard.h"
#include "world/world_impl.h"

namespace polar {
namespace {

// Response leaves this fraction of the radius sum overlapping, so a resting contact stays a hit
// from step to step instead of flickering across the exact tangency (Box2D's "linear slop" idea,
// made relative so it works at any scale).
constexpr double kRelativeSlop = 1e-4;

// Adds the time until it goes out of scope to a counter, when timing is on. Only stats read it.
class EffectTimer {
  public:
    EffectTimer(bool on, std::uint64_t& nanoseconds) : nanoseconds_(on ? &nanoseconds : nullptr) {
        if (nanoseconds_) start_ = std::chrono::steady_clock::now();
    }
    ~EffectTimer() {
        if (!nanoseconds_) return;
        auto elapsed = std::chrono::steady_clock::now() - start_;
        *nanoseconds_ +=
            static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(elapsed).count());
    }
    EffectTimer(const EffectTimer&) = delete;
    EffectTimer& operator=(const EffectTimer&) = delete;

  private:
    std::uint64_t* nanoseconds_;
    std::chrono::steady_clock::time_point start_;
};

// Removes `index` from an ascending index list (if present) and renumbers the later ones.
void dropIndex(std::vector<std::uint32_t>& list, std::uint32_t index) {
    auto at = std::lower_bound(list.begin(), list.end(), index);
    if (at != list.end() && *at == index) at = list.erase(at);
    for (; at != list.end(); ++at) --*at;
}

// Puts `index` in or out of an ascending index list.
void setMember(std::vector<std::uint32_t>& list, std::uint32_t index, bool member) {
    auto at = std::lower_bound(list.begin(), list.end(), index);
    bool present = at != list.end() && *at == index;
    if (member && !present) list.insert(at, index);
    if (!member && present) list.erase(at);
}

// Asks for an object's cache lines ahead of use: hits and touched objects are visited in pair order,
// not memory order, and waiting for each miss in turn would dominate those passes.
void prefetch(const GameObject& object) {
    const char* p = reinterpret_cast<const char*>(&object);
    for (std::size_t line = 0; line < sizeof(GameObject); line += 64) __builtin_prefetch(p + line);
}

// Semi-implicit Euler with damping: v ← v / (1 + dt·c) (and spin alike), then the rotation and the
// translation move by the damped spin and velocity, in that order.
inline void integrateObject(GameObject& object, double dt) {
    double keep = 1.0 / (1.0 + dt * object.damping);
    object.velocity *= keep;
    object.spin *= keep;
    object.transform.rotate(object.spin * dt);
    object.transform.translate(object.velocity * dt);
}

// Workers from which the lists and responses run as contact groups (SharedResponse): the groups cost
// about 1.5 times the work of one thread, so below three workers side by side is faster.
constexpr std::uint32_t kGroupsFrom = 3;

// Objects per range of a shared integration: enough that a range outlasts claiming it.
constexpr std::uint32_t kMinIntegrateRange = 2048;

template <class T>
std::size_t heldBytes(const std::vector<T>& v) {
    return v.capacity() * sizeof(T);
}

}  // namespace

World::Impl::Impl(const WorldDef& def) : def_(def) {
    if (runs(kEffectCollisions)) detector_ = std::make_unique<Detector>();
    if (runs(kEffectCcd)) cast_ = std::make_unique<FastCast>();
    startTasks();
}

World::Impl::Impl(const Impl& other)
    : def_(other.def_),
      objects_(other.objects_),
      names_(other.names_),
      nextId_(other.nextId_),
      physicsList_(other.physicsList_),
      collisionList_(other.collisionList_),
      fastList_(other.fastList_),
      collidedBegin_(other.collidedBegin_),
      collidedIds_(other.collidedIds_),
      layout_(other.layout_ + 1),
      last_(other.last_),
      total_(other.total_),
      steps_(other.steps_),
      timing_(other.timing_) {
    // Scratch buffers are not state: a copy starts with empty ones, and a pool of its own. The last
    // step's hits are state.
    if (runs(kEffectCollisions)) {
        detector_ = std::make_unique<Detector>();
        detector_->copyHits(other.hits());
    }
    if (runs(kEffectCcd)) cast_ = std::make_unique<FastCast>();
    startTasks();
}

void World::Impl::startTasks() {
    if (def_.tasks) {
        tasks_ = def_.tasks;
    } else if (def_.workers > 1) {
        pool_ = std::make_unique<ThreadPool>(def_.workers);
        tasks_ = pool_.get();
    }
    if (detector_) detector_->setTasks(tasks_, def_.parallelMin);
}

World::World(const WorldDef& def) : impl_(std::make_unique<Impl>(def)) {}

World::World(const World& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}

World::World(World&& other) noexcept = default;

World& World::operator=(World other) noexcept {
    // The whole state moves as one, the detector with the layout it remembers.
    std::swap(impl_, other.impl_);
    return *this;
}

World::~World() = default;

ObjectId World::add(ObjectDef def) {
    assert(!nameTaken(def.name));  // an empty name is never taken: unnamed objects skip the index
    Impl& w = *impl_;
    GameObject object;
    static_cast<ObjectDef&>(object) = std::move(def);
    object.id = w.nextId_++;
    auto index = static_cast<std::uint32_t>(w.objects_.size());
    if (w.runs(kEffectPhysics) && object.has(kPhysics)) w.physicsList_.push_back(index);
    if (w.runs(kEffectCollisions) && object.has(kCollisions)) w.collisionList_.push_back(index);
    if (!w.collidedBegin_.empty())
        w.collidedBegin_.push_back(w.collidedBegin_.back());  // touched nothing yet
    if (w.runs(kEffectCcd) && object.has(kFast)) w.fastList_.push_back(index);
    w.objects_.push_back(std::move(object));
    const GameObject& added = w.objects_.back();
    if (!added.name.empty()) w.names_.insert(added.id, added.name, w.objects_.size());
    ++w.layout_;
    return added.id;
}

void World::reserve(std::size_t objects) {
    impl_->objects_.reserve(objects);
    impl_->names_.reserve(objects);
}

std::size_t World::Impl::indexOf(ObjectId id) const {
    auto it = std::lower_bound(objects_.begin(), objects_.end(), id,
                               [](const GameObject& o, ObjectId i) { return o.id < i; });
    return (it != objects_.end() && it->id == id) ? static_cast<std::size_t>(it - objects_.begin())
                                                  : objects_.size();
}

bool World::Impl::listsMatchFlags() const {
    auto matches = [&](const std::vector<std::uint32_t>& list, Effect effect, ObjectFlag flag) {
        std::size_t k = 0;
        for (std::uint32_t i = 0; i < objects_.size(); ++i) {
            if (!runs(effect) || !objects_[i].has(flag)) continue;
            if (k == list.size() || list[k] != i) return false;
            ++k;
        }
        return k == list.size();
    };
    return matches(physicsList_, kEffectPhysics, kPhysics) &&
           matches(collisionList_, kEffectCollisions, kCollisions) && matches(fastList_, kEffectCcd, kFast);
}

bool World::remove(ObjectId id) {
    Impl& w = *impl_;
    std::size_t index = w.indexOf(id);
    if (index == w.objects_.size()) return false;
    w.names_.erase(w.objects_[index].name, w.objects_);
    w.objects_.erase(w.objects_.begin() + static_cast<std::ptrdiff_t>(index));
    auto removed = static_cast<std::uint32_t>(index);
    for (auto* list : {&w.physicsList_, &w.collisionList_, &w.fastList_}) dropIndex(*list, removed);
    if (!w.collidedBegin_.empty()) {
        // Its partners leave the list, and the later objects' ranges move down by as many.
        std::vector<std::uint32_t>& begins = w.collidedBegin_;
        std::uint32_t begin = begins[index], end = begins[index + 1];
        w.collidedIds_.erase(w.collidedIds_.begin() + begin, w.collidedIds_.begin() + end);
        begins.erase(begins.begin() + static_cast<std::ptrdiff_t>(index) + 1);
        for (std::size_t k = index + 1; k < begins.size(); ++k) begins[k] -= end - begin;
    }
    ++w.layout_;
    return true;
}

bool World::setFlags(ObjectId id, ObjectFlags flags) {
    Impl& w = *impl_;
    std::size_t index = w.indexOf(id);
    if (index == w.objects_.size()) return false;
    w.objects_[index].flags = flags;
    auto i = static_cast<std::uint32_t>(index);
    if (w.runs(kEffectPhysics)) setMember(w.physicsList_, i, (flags & kPhysics) != 0);
    if (w.runs(kEffectCollisions)) setMember(w.collisionList_, i, (flags & kCollisions) != 0);
    if (w.runs(kEffectCcd)) setMember(w.fastList_, i, (flags & kFast) != 0);
    ++w.layout_;
    return true;
}

GameObject* World::find(ObjectId id) {
    std::size_t index = impl_->indexOf(id);
    return index == impl_->objects_.size() ? nullptr : &impl_->objects_[index];
}

const GameObject* World::find(ObjectId id) const {
    std::size_t index = impl_->indexOf(id);
    return index == impl_->objects_.size() ? nullptr : &impl_->objects_[index];
}

GameObject* World::findByName(std::string_view name) {
    ObjectId id = impl_->names_.find(name, impl_->objects_);
    return id == 0 ? nullptr : find(id);
}

const GameObject* World::findByName(std::string_view name) const {
    ObjectId id = impl_->names_.find(name, impl_->objects_);
    return id == 0 ? nullptr : find(id);
}

bool World::nameTaken(std::string_view name) const {
    return impl_->names_.find(name, impl_->objects_) != 0;
}

std::span<GameObject> World::objects() {
    return impl_->objects_;
}
std::span<const GameObject> World::objects() const {
    return impl_->objects_;
}

const WorldDef& World::def() const {
    return impl_->def_;
}
bool World::runs(Effect effect) const {
    return impl_->runs(effect);
}
std::uint32_t World::workerCount() const {
    return impl_->tasks_ ? impl_->tasks_->workerCount() : 1;
}
void World::setBroadPhase(BroadPhase method) {
    impl_->def_.broadPhase = method;
}

void World::step(double dt) {
    impl_->step(dt);
}

void World::Impl::step(double dt) {
    assert(listsMatchFlags() && "flags changed without World::setFlags");
    last_ = StepStats{};
    if (runs(kEffectCcd)) recordFastStarts();
    if (runs(kEffectPhysics)) integrate(dt);
    if (runs(kEffectCollisions)) collide();
#ifndef NDEBUG
    // No NaN or infinity leaves the engine: checked at the step boundary.
    for (const GameObject& object : objects_) assert(isFinite(object));
    for (const PairReport& hit : hits()) assert(isFinite(hit.test));
#endif
    measureMemory();
    total_ += last_;
    ++steps_;
}

void World::Impl::recordFastStarts() {
    EffectStats& stats = last_[kEffectCcd];
    EffectTimer timer(timing_, stats.nanoseconds);
    fastStarts_.clear();
    if (fastList_.empty()) return;
    ++stats.calls;
    for (std::uint32_t index : fastList_) {
        const Vec2& p = objects_[index].transform.position();
        fastStarts_.push_back({index, p.x(), p.y()});
    }
    stats.objects += fastList_.size();
}

void World::Impl::integrate(double dt) {
    EffectStats& stats = last_[kEffectPhysics];
    EffectTimer timer(timing_, stats.nanoseconds);
    if (physicsList_.empty()) return;
    ++stats.calls;
    stats.objects += physicsList_.size();
    // Each object moves by its own state alone: ranges of the list on the workers.
    auto body = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t k = begin; k < end; ++k) integrateObject(objects_[physicsList_[k]], dt);
    };
    parallelForIfWorth(tasks_, physicsList_.size(), def_.parallelMin, kMinIntegrateRange, body);
}

void World::Impl::collide() {
    EffectStats& collisions = last_[kEffectCollisions];
    EffectStats& containers = last_[kEffectContainers];
    {
        EffectTimer timer(timing_, collisions.nanoseconds);
        EffectTimer broad(timing_, last_.broadPhaseNanoseconds);
        ++collisions.calls;
        collisions.objects += collisionList_.size();
        detector_->prepare({.objects = objects_,
                            .candidates = collisionList_,
                            .containers = runs(kEffectContainers),
                            .accuracy = def_.accuracy,
                            .fastStarts = fastStarts_},
                           def_.broadPhase, layout_);
        last_.candidates = detector_->data().size();
    }
    if (runs(kEffectCcd)) {
        EffectStats& ccd = last_[kEffectCcd];
        EffectTimer timer(timing_, ccd.nanoseconds);
        cast_->run(*detector_, objects_, ccd);
    }
    if (runs(kEffectContainers)) {
        EffectTimer timer(timing_, containers.nanoseconds);
        detector_->testContainers(containers);
    }
    {
        EffectTimer timer(timing_, collisions.nanoseconds);
        detector_->findHits(false, objects_.size(), collisions, containers);
    }
    std::span<const PairReport> hits = detector_->hits();
    bool responds = runs(kEffectResponse) && !hits.empty();
    // The lists of what each object touched, and the responses. The lists are timed with the
    // responses when those run (the shared pass makes both at once), else with the collisions.
    EffectStats& response = last_[kEffectResponse];
    EffectTimer timer(timing_, responds ? response.nanoseconds : collisions.nanoseconds);
    bool shared = !hits.empty() && worthSharing(tasks_, hits.size(), def_.parallelMin);
    if (shared && tasks_->workerCount() >= kGroupsFrom) {
        SharedResponse::Responder responder{
            [](void* impl, const PairReport& hit) { static_cast<Impl*>(impl)->respond(hit); }, this};
        shared_.run(*tasks_, hits, objects_, collidedBegin_, collidedIds_, responds ? &responder : nullptr);
        if (responds) {
            ++response.calls;
            response.pairs += hits.size();
        }
    } else if (shared && responds) {
        // Two workers: the lists and the responses side by side, each whole on one thread (neither
        // reads what the other writes), which costs no more work than one thread does.
        collidedBegin_.reserve(objects_.size() + 1);
        if (2 * hits.size() > collidedIds_.capacity())
            collidedIds_.reserve(std::max(2 * hits.size(), 2 * collidedIds_.capacity()));  // as resize would
        auto body = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
            for (std::uint32_t job = begin; job < end; ++job)
                job == 0 ? listCollided() : respondAll(response);
        };
        parallelFor(*tasks_, 2, 1, body);
    } else {
        listCollided();
        if (responds) respondAll(response);
    }
    last_.hits = hits.size();
    for (const EffectStats& e : last_.effects) last_.pairsTested += e.pairs;
    last_.pairsTested -= last_[kEffectResponse].pairs;
}

std::span<const PairReport> World::hits() const {
    return impl_->hits();
}

void World::Impl::listCollided() {
    std::span<const PairReport> hits = detector_->hits();
    collidedIds_.clear();
    if (hits.empty()) {
        collidedBegin_.clear();
        return;
    }
    // A counting sort of the hits' two ends by object: each partner is written in its object's run,
    // in pair order.
    CountingSort byObject(collidedBegin_, objects_.size());
    for (const PairReport& hit : hits) {
        byObject.count(hit.a);
        byObject.count(hit.b);
    }
    byObject.startRuns();
    collidedIds_.resize(2 * hits.size());
    for (std::size_t k = 0; k < hits.size(); ++k) {
        // The hits run in A's order, so B's objects are scattered: fetch them a few hits ahead.
        if (k + 8 < hits.size()) __builtin_prefetch(&objects_[hits[k + 8].b].id);
        const PairReport& hit = hits[k];
        collidedIds_[byObject.place(hit.a)] = objects_[hit.b].id;
        collidedIds_[byObject.place(hit.b)] = objects_[hit.a].id;
    }
    byObject.rewindRuns();
}

std::span<const ObjectId> World::collidedWith(ObjectId id) const {
    const Impl& w = *impl_;
    std::size_t index = w.indexOf(id);
    if (w.collidedBegin_.empty() || index == w.objects_.size()) return {};
    std::uint32_t begin = w.collidedBegin_[index], end = w.collidedBegin_[index + 1];
    return std::span<const ObjectId>(w.collidedIds_).subspan(begin, end - begin);
}

void World::Impl::respondAll(EffectStats& response) {
    std::span<const PairReport> hits = detector_->hits();
    ++response.calls;
    response.pairs += hits.size();
    // Contacts first, then the container walls, each in pair order: the walls act last, so a push
    // between two held objects cannot leave one of them through a wall it touches.
    for (ContactKind kind : {ContactKind::Contact, ContactKind::Container}) {
        for (std::size_t k = 0; k < hits.size(); ++k) {
            if (k + 8 < hits.size()) {
                prefetch(objects_[hits[k + 8].a]);
                prefetch(objects_[hits[k + 8].b]);
            }
            if (hits[k].test.kind == kind) respond(hits[k]);
        }
    }
}

void World::Impl::respond(const PairReport& hit) {
    GameObject& a = objects_[hit.a];
    GameObject& b = objects_[hit.b];

    // The ghost flag alone says whose movement a collision may change.
    bool movesA = !a.has(kGhost), movesB = !b.has(kGhost);
    if (!movesA && !movesB) return;
    // A wall is measured again where the contacts before it left the object (the hit itself was
    // decided on the snapshot), so the object ends the step inside whatever pushed it.
    const PairTest t =
        hit.test.kind == ContactKind::Container ? testPair(poseOf(a), poseOf(b), def_.accuracy) : hit.test;
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

void World::Impl::measureMemory() {
    last_[kEffectPhysics].bytes = heldBytes(physicsList_);
    if (detector_) {
        last_[kEffectCollisions].bytes = heldBytes(collisionList_) + heldBytes(collidedBegin_) +
                                         heldBytes(collidedIds_) + detector_->bytes() -
                                         detector_->containerBytes();
        last_[kEffectContainers].bytes = detector_->containerBytes();
    }
    if (cast_) last_[kEffectCcd].bytes = heldBytes(fastList_) + heldBytes(fastStarts_) + cast_->bytes();
}

const StepStats& World::lastStepStats() const {
    return impl_->last_;
}
const StepStats& World::totalStats() const {
    return impl_->total_;
}
std::uint64_t World::stepCount() const {
    return impl_->steps_;
}
void World::setTiming(bool on) {
    impl_->timing_ = on;
}
bool World::timing() const {
    return impl_->timing_;
}

std::vector<PairReport> World::detect(bool all) const {
    const Impl& w = *impl_;
    std::vector<std::uint32_t> indices;
    for (std::uint32_t i = 0; i < w.objects_.size(); ++i)
        if (w.objects_[i].has(kCollisions)) indices.push_back(i);
    Detector detector;
    detector.prepare({.objects = w.objects_,
                      .candidates = indices,
                      .containers = w.runs(kEffectContainers),
                      .accuracy = w.def_.accuracy,
                      .fastStarts = {}},
                     all ? BroadPhase::AllPairs : w.def_.broadPhase, 0);
    EffectStats ignored;
    detector.testContainers(ignored);
    detector.findHits(all, w.objects_.size(), ignored, ignored);
    return std::vector<PairReport>(detector.hits().begin(), detector.hits().end());
}

PairTest testObjects(const GameObject& a, const GameObject& b, Accuracy accuracy) {
    assert(!a.boundsOrEmpty().empty() && !b.boundsOrEmpty().empty());
    return testPair(poseOf(a), poseOf(b), accuracy);
}

}  // namespace polar
