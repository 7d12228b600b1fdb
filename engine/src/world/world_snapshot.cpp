#include "polar/world_snapshot.h"

#include <cmath>
#include <string>
#include <type_traits>

#include "math/transform_factors.h"
#include "polar/snapshot_bytes.h"
#include "world/world_impl.h"

namespace polar {
namespace {

constexpr SnapshotKind kWorldSnapshot{0x504e5350, kWorldSnapshotVersion, "world snapshot",
                                      "saveSnapshot"};  // magic "PSNP"
constexpr ObjectFlags kKnownFlags = kPhysics | kCollisions | kGhost | kContainer | kIgnoreContainers | kFast;
constexpr Effects kKnownEffects =
    kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers | kEffectCcd;
constexpr std::uint32_t kNoEntry = ~0u;

// An object's record: id, flags, bounds entry, a mask of what follows the fixed part, then the
// transform (its factors and cached cosine and sine, as they are in memory), velocity, spin and
// damping; then the game's user data if it is not 0, and the name if it has one. Most objects of a
// big field have neither, so their records stay at the fixed size.
enum TailMask : std::uint8_t { kOwnName = 1, kUserData = 2 };
constexpr std::size_t kObjectDoubles = 11;  // the transform's 7, velocity, spin, damping
static_assert(TransformFactors::kCount == 7);
constexpr std::size_t kObjectRecordBytes = 4 + 4 + 4 + 1 + kObjectDoubles * 8;
static_assert(std::is_trivially_copyable_v<StepStats> && sizeof(StepStats) % 8 == 0 &&
                  sizeof(StepStats) == (5 * kEffectCount + 4) * sizeof(std::uint64_t),
              "a snapshot writes StepStats as its counters, with no padding");
constexpr std::size_t kHitRecordBytes = 4 + 4 + 6 * 8 + 1 + 1 + 4 + 4;

Error snapshotError(std::string what) {
    return polar::snapshotError(kWorldSnapshot, std::move(what));
}

bool finite(const double* d, std::size_t n) {
    for (std::size_t k = 0; k < n; ++k)
        if (!std::isfinite(d[k])) return false;
    return true;
}

// Whether an object record's values are ones a stepping world can hold: finite is not enough, since
// a crafted buffer with a valid checksum could carry a cosine or sine past ±1, a vast scale, or a position so
// far out that the step's products overflow. The bounds are far past any real scene (world units are sprite
// pixels) and cost a few compares an object.
bool sane(const double* d) {
    constexpr double kFar = 1e12, kScale = 1e6;
    for (int k : {0, 1, 2, 7, 8, 9, 10})
        if (!(std::fabs(d[k]) <= kFar)) return false;
    for (int k : {5, 6})
        if (!(std::fabs(d[k]) <= kScale)) return false;
    return std::fabs(d[3]) <= 1 && std::fabs(d[4]) <= 1;
}

// Scratch for saving: the bounds already in the snapshot's table, by pointer (open addressing). One
// per thread, so a warm save allocates nothing and a snapshot carries no scratch of its own.
struct BoundsSlot {
    const void* key = nullptr;
    std::uint32_t entry = kNoEntry;
};
thread_local std::vector<BoundsSlot> tBoundsIndex;

// This thread's index, found once a save and then passed on as a plain reference (a compiler that saw
// the thread-local itself in entryOf would look it up again on every call).
[[gnu::noinline]] std::vector<BoundsSlot>& boundsIndexOfThisThread() {
    return tBoundsIndex;
}

std::size_t slotOf(const void* key, std::size_t mask) {
    auto bits = reinterpret_cast<std::uintptr_t>(key) >> 4;
    return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 20) & mask;
}

// The entry of `key` when the index holds it, else kNoEntry: the common case, probed in the save loop.
std::uint32_t knownEntry(const std::vector<BoundsSlot>& index, const void* key) {
    std::size_t mask = index.size() - 1;
    for (std::size_t k = slotOf(key, mask);; k = (k + 1) & mask) {
        if (index[k].key == key || index[k].entry == kNoEntry) return index[k].entry;
    }
}

}  // namespace

struct WorldSnapshotAccess {
    static void save(const World& world, WorldSnapshot& out);
    static std::optional<Error> restore(World& world, const WorldSnapshot& snapshot);

  private:
    static void save(const World::Impl& world, WorldSnapshot& out);
    // The bounds entry of `bounds` in out's table, adding it if new. Kept out of the save loop, which
    // probes for a known entry itself (knownEntry): inlined whole, the adding and growing cost the
    // loop its registers, and a 10k-object save took 12 % longer.
    [[gnu::noinline]] static std::uint32_t entryOf(WorldSnapshot& out, std::vector<BoundsSlot>& index,
                                                   const BoundsPtr& bounds);
    // Reads the payload; with kApply it writes the world, without it only checks. Both read every
    // byte the same way, so a payload that passes the check is applied without a failure half-way.
    template <bool kApply>
    static std::optional<Error> read(World::Impl& world, const WorldSnapshot& snapshot, ByteReader in);
};

std::uint32_t WorldSnapshotAccess::entryOf(WorldSnapshot& out, std::vector<BoundsSlot>& index,
                                           const BoundsPtr& bounds) {
    const void* key = bounds.get();
    std::size_t mask = index.size() - 1;
    for (std::size_t k = slotOf(key, mask);; k = (k + 1) & mask) {
        BoundsSlot& slot = index[k];
        if (slot.entry == kNoEntry) {
            slot = {key, static_cast<std::uint32_t>(out.bounds.size())};
            out.bounds.push_back(bounds);
            if (2 * out.bounds.size() > index.size()) {
                // Grow to keep it at most half full.
                std::vector<BoundsSlot> old = std::move(index);
                index.assign(2 * old.size(), {});
                std::size_t grown = index.size() - 1;
                for (const BoundsSlot& s : old) {
                    if (s.entry == kNoEntry) continue;
                    std::size_t j = slotOf(s.key, grown);
                    while (index[j].entry != kNoEntry) j = (j + 1) & grown;
                    index[j] = s;
                }
            }
            return static_cast<std::uint32_t>(out.bounds.size() - 1);
        }
        if (slot.key == key) return slot.entry;
    }
}

void WorldSnapshotAccess::save(const World& world, WorldSnapshot& out) {
    save(*world.impl_, out);
}

void WorldSnapshotAccess::save(const World::Impl& world, WorldSnapshot& out) {
    out.bounds.clear();
    std::vector<BoundsSlot>& index = boundsIndexOfThisThread();
    if (index.empty()) index.resize(64);
    std::fill(index.begin(), index.end(), BoundsSlot{});

    ByteWriter w = startSnapshotFrame(out.bytes, kWorldSnapshot);

    const WorldDef& def = world.def_;
    w.put(std::uint32_t{def.effects});
    w.put(static_cast<std::uint8_t>(def.accuracy));
    w.put(static_cast<std::uint8_t>(def.broadPhase));
    w.put(std::uint16_t{0});
    w.put(def.restitution);
    w.put(std::uint32_t{world.nextId_});
    w.put(world.steps_);
    w.put(world.last_);
    w.put(world.total_);

    const std::vector<GameObject>& objects = world.objects_;
    w.put(static_cast<std::uint32_t>(objects.size()));
    for (std::uint32_t i = 0; i < objects.size(); ++i) {
        const GameObject& o = objects[i];
        std::uint32_t entry = knownEntry(index, o.bounds.get());
        if (entry == kNoEntry) entry = entryOf(out, index, o.bounds);
        std::uint8_t mask = (o.name.empty() ? 0 : kOwnName) | (o.userData == 0 ? 0 : kUserData);
        w.put(std::uint32_t{o.id});
        w.put(std::uint32_t{o.flags});
        w.put(entry);
        w.put(mask);
        double state[kObjectDoubles];
        TransformFactors::read(o.transform, state);
        state[7] = o.velocity.x();
        state[8] = o.velocity.y();
        state[9] = o.spin;
        state[10] = o.damping;
        w.bytes(state, sizeof state);
        if (mask & kUserData) w.put(o.userData);
        if (mask & kOwnName) w.text(o.name);
    }
    w.put(static_cast<std::uint32_t>(out.bounds.size()));

    w.put(static_cast<std::uint32_t>(world.collidedBegin_.size()));
    w.bytes(world.collidedBegin_.data(), world.collidedBegin_.size() * sizeof(std::uint32_t));
    w.put(static_cast<std::uint32_t>(world.collidedIds_.size()));
    w.bytes(world.collidedIds_.data(), world.collidedIds_.size() * sizeof(ObjectId));

    std::span<const PairReport> hits = world.hits();
    w.put(static_cast<std::uint32_t>(hits.size()));
    for (const PairReport& hit : hits) {
        const PairTest& t = hit.test;
        w.put(hit.a);
        w.put(hit.b);
        w.put(t.normal.x());
        w.put(t.normal.y());
        w.put(t.distance);
        w.put(t.ra);
        w.put(t.rb);
        w.put(t.penetration);
        w.put(static_cast<std::uint8_t>(t.kind));
        w.put(static_cast<std::uint8_t>(t.hit));
        w.put(t.radiiA);
        w.put(t.radiiB);
    }

    endSnapshotFrame(w);
}

template <bool kApply>
std::optional<Error> WorldSnapshotAccess::read(World::Impl& world, const WorldSnapshot& snapshot,
                                               ByteReader in) {
    auto effects = in.get<std::uint32_t>();
    auto accuracy = in.get<std::uint8_t>();
    auto broadPhase = in.get<std::uint8_t>();
    (void)in.get<std::uint16_t>();
    auto restitution = in.get<double>();
    auto nextId = in.get<std::uint32_t>();
    auto steps = in.get<std::uint64_t>();
    auto last = in.get<StepStats>();
    auto total = in.get<StepStats>();
    if (!in.ok()) return snapshotError("cut off in the world's rules");
    if (effects & ~kKnownEffects) return snapshotError("unknown effects " + std::to_string(effects));
    if (accuracy >= std::size(kAllAccuracies)) return snapshotError("unknown accuracy");
    if (broadPhase >= std::size(kAllBroadPhases)) return snapshotError("unknown broad phase");
    if (!(restitution >= 0 && restitution <= 1)) return snapshotError("a restitution outside 0 to 1");

    if constexpr (kApply) {
        WorldDef& def = world.def_;
        if (def.effects != effects) {
            def.effects = effects;
            world.detector_.reset();
            world.cast_.reset();
            if (world.runs(kEffectCollisions)) world.detector_ = std::make_unique<Detector>();
            if (world.runs(kEffectCcd)) world.cast_ = std::make_unique<FastCast>();
            if (world.detector_) world.detector_->setTasks(world.tasks_, def.parallelMin);
        }
        def.accuracy = static_cast<Accuracy>(accuracy);
        def.broadPhase = static_cast<BroadPhase>(broadPhase);
        def.restitution = restitution;
        world.nextId_ = nextId;
        world.steps_ = steps;
        world.last_ = last;
        world.total_ = total;
    }

    auto count = in.get<std::uint32_t>();
    if (!in.canHold(count, kObjectRecordBytes)) return snapshotError("cut off before its objects");
    std::vector<GameObject>& objects = world.objects_;
    if constexpr (kApply) {
        objects.resize(count);
        world.physicsList_.clear();
        world.collisionList_.clear();
        world.fastList_.clear();
    }
    std::uint32_t entries = 0;
    ObjectId previous = 0;
    const std::size_t tableSize = snapshot.bounds.size();
    for (std::uint32_t i = 0; i < count; ++i) {
        auto id = in.get<std::uint32_t>();
        auto flags = in.get<std::uint32_t>();
        auto entry = in.get<std::uint32_t>();
        auto mask = in.get<std::uint8_t>();
        double d[kObjectDoubles];
        in.bytes(d, sizeof d);
        if (!in.ok()) return snapshotError("cut off in object " + std::to_string(i));
        if constexpr (!kApply) {
            auto bad = [i](const char* what) {
                return snapshotError(what + (" in object " + std::to_string(i)));
            };
            if (id <= previous || id >= nextId) return bad("an id out of order");
            if (flags & ~kKnownFlags) return bad("unknown flags");
            if (mask & ~(kOwnName | kUserData)) return bad("an unknown field");
            if (entry > entries || entry >= tableSize) return bad("a bounds entry out of range");
            if (!finite(d, kObjectDoubles)) return bad("a value that is not finite");
            if (!sane(d)) return bad("a transform or motion no world holds");
        }
        previous = id;
        if (entry == entries) ++entries;
        std::uint64_t userData = (mask & kUserData) ? in.get<std::uint64_t>() : 0;
        std::string_view name = (mask & kOwnName) ? in.text() : std::string_view();
        if (!in.ok()) return snapshotError("cut off in the tail of object " + std::to_string(i));
        if constexpr (kApply) {
            GameObject& o = objects[i];
            o.id = id;
            o.flags = flags;
            if (o.bounds != snapshot.bounds[entry]) o.bounds = snapshot.bounds[entry];
            TransformFactors::write(o.transform, d);
            o.velocity = Vec2(d[7], d[8]);
            o.spin = d[9];
            o.damping = d[10];
            o.userData = userData;
            o.name.assign(name);
            if (world.runs(kEffectPhysics) && (flags & kPhysics)) world.physicsList_.push_back(i);
            if (world.runs(kEffectCollisions) && (flags & kCollisions)) world.collisionList_.push_back(i);
            if (world.runs(kEffectCcd) && (flags & kFast)) world.fastList_.push_back(i);
        }
    }
    auto tableCount = in.get<std::uint32_t>();
    if (!in.ok()) return snapshotError("cut off after the objects");
    if (tableCount != entries || tableCount != tableSize)
        return snapshotError("a bounds table of " + std::to_string(tableSize) + " entries for " +
                             std::to_string(entries));

    auto begins = in.get<std::uint32_t>();
    if (!in.canHold(begins, 4)) return snapshotError("cut off in the collided lists");
    if (begins != 0 && begins != count + 1) return snapshotError("collided lists of the wrong length");
    std::uint32_t idsEnd = 0;
    if constexpr (kApply) {
        world.collidedBegin_.resize(begins);
        in.bytes(world.collidedBegin_.data(), begins * 4);
    } else {
        for (std::uint32_t k = 0; k < begins; ++k) {
            auto b = in.get<std::uint32_t>();
            if (b < idsEnd || (k == 0 && b != 0)) return snapshotError("collided lists out of order");
            idsEnd = b;
        }
    }
    auto idCount = in.get<std::uint32_t>();
    if (!in.canHold(idCount, 4)) return snapshotError("cut off in the collided ids");
    if (!kApply && begins != 0 && idsEnd != idCount)
        return snapshotError("collided lists of the wrong length");
    if constexpr (kApply) {
        world.collidedIds_.resize(idCount);
        in.bytes(world.collidedIds_.data(), idCount * 4);
    } else {
        in.skip(std::size_t{idCount} * 4);
    }

    auto hitCount = in.get<std::uint32_t>();
    if (!in.canHold(hitCount, kHitRecordBytes)) return snapshotError("cut off in the hits");
    if (hitCount > 0 && !(effects & kEffectCollisions))
        return snapshotError("hits in a world without collisions");
    if constexpr (kApply) {
        if (world.detector_) world.detector_->clearHits(hitCount);
    } else {
        // Only the kind and the hit flag can be wrong: every other field is any bits.
        for (std::uint32_t k = 0; k < hitCount; ++k) {
            in.skip(4 + 4 + 6 * 8);
            auto kind = in.get<std::uint8_t>();
            auto hitFlag = in.get<std::uint8_t>();
            in.skip(4 + 4);
            if (kind > static_cast<std::uint8_t>(ContactKind::Container) || hitFlag > 1)
                return snapshotError("a hit of unknown kind");
        }
    }
    for (std::uint32_t k = 0; kApply && k < hitCount; ++k) {
        PairReport hit;
        hit.a = in.get<std::uint32_t>();
        hit.b = in.get<std::uint32_t>();
        PairTest& t = hit.test;
        double nx = in.get<double>(), ny = in.get<double>();
        t.normal = Vec2(nx, ny);
        t.distance = in.get<double>();
        t.ra = in.get<double>();
        t.rb = in.get<double>();
        t.penetration = in.get<double>();
        auto kind = in.get<std::uint8_t>();
        auto hitFlag = in.get<std::uint8_t>();
        t.radiiA = in.get<std::uint32_t>();
        t.radiiB = in.get<std::uint32_t>();
        t.kind = static_cast<ContactKind>(kind);
        t.hit = hitFlag != 0;
        world.detector_->addHit(hit);
    }
    if (!in.ok()) return snapshotError("cut off in the hits");
    if (in.left() != 0) return snapshotError(std::to_string(in.left()) + " bytes past the end of the state");

    if constexpr (kApply) {
        // The name index is rebuilt, not copied: its layout depends on the order names came and went,
        // and lookups do not. The lists follow from the flags; the detector forgets its cell order
        // and slot plan (layout_), and the next step's fast starts are taken afresh.
        world.names_.rebuild(objects);
        world.fastStarts_.clear();
        ++world.layout_;
    }
    return std::nullopt;
}

std::optional<Error> WorldSnapshotAccess::restore(World& world, const WorldSnapshot& snapshot) {
    Result<ByteReader> in = openSnapshotFrame(snapshot.bytes, kWorldSnapshot);
    if (!in) return in.error();
    if (std::optional<Error> error = read<false>(*world.impl_, snapshot, *in)) return error;
    read<true>(*world.impl_, snapshot, *in);
    return std::nullopt;
}

void saveSnapshot(const World& world, WorldSnapshot& out) {
    WorldSnapshotAccess::save(world, out);
}

std::optional<Error> restoreSnapshot(World& world, const WorldSnapshot& snapshot) {
    return WorldSnapshotAccess::restore(world, snapshot);
}

}  // namespace polar
