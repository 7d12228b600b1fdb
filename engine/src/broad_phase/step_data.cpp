#include "broad_phase/step_data.h"

#include <algorithm>
#include <atomic>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>

#include "math/bit_cast.h"
#include "narrow_phase/pair_test.h"
#include "tasks/parallel_for.h"

namespace polar {
namespace {

// Rounding allowances. The narrow phase's world radii carry a relative error near 1e-15 and its
// centre differences an absolute error near one ulp of the coordinates; these are far larger, so a
// pair the narrow phase calls a hit is never culled, and far smaller than anything visible.
constexpr double kRelativeMargin = 1e-9;
constexpr double kCoordinateMargin = 1e-14;

double marginFor(double x, double y, double radius) {
    return kRelativeMargin * radius + kCoordinateMargin * (std::fabs(x) + std::fabs(y));
}

// A reach circle with its margin rounded up to a float; a margin too large for a float (coordinates
// beyond 10^52) joins the radius instead, which is just as safe.
ReachCircle makeReach(double x, double y, double radius, std::uint32_t fast = ReachCircle::kNotFast) {
    double margin = marginFor(x, y, radius);
    if (!(margin <= static_cast<double>(std::numeric_limits<float>::max()) / 2))
        return {x, y, radius + margin, 0.0f, fast};
    float rounded = static_cast<float>(margin);
    // One float up: the next bit pattern, since rounded is finite and ≥ 0 (nextafter's answer,
    // without its library call on every other object of every step).
    if (static_cast<double>(rounded) < margin) rounded = bitCast<float>(bitCast<std::uint32_t>(rounded) + 1u);
    return {x, y, radius, rounded, fast};
}

// Candidates fetched ahead of use, and the bytes of an object a step reads: from the bounds pointer
// to the flags. Three probes 60 bytes apart cover every 64-byte line of that range, however the
// object is aligned.
constexpr std::size_t kPrefetchAhead = 16;
constexpr std::size_t kHotFirst = offsetof(ObjectDef, bounds), kHotLast = offsetof(ObjectDef, flags);
static_assert(kHotLast - kHotFirst <= 120, "the hot part of an object spans at most three lines");

void prefetchHotPart(const GameObject& object) {
    const char* bytes = reinterpret_cast<const char*>(&object);
    __builtin_prefetch(bytes + kHotFirst);
    __builtin_prefetch(bytes + kHotFirst + 60);
    __builtin_prefetch(bytes + kHotLast);
}

// Candidates per range when build is shared: enough that a range outlasts claiming it.
constexpr std::uint32_t kMinShare = 1024;

// Whether a candidate gets a slot: it has radii, and it is no container or containers run.
bool getsSlot(const GameObject& object, bool containers) {
    return !object.boundsOrEmpty().empty() && (!object.has(kContainer) || containers);
}

// Whether a slot's reach circle and box are finite: place() keeps any other out of every broad phase.
bool finite(const ReachCircle& c, const Box& box) {
    return std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.radius) &&
           std::isfinite(box.minX + box.maxX + box.minY + box.maxY);
}

// The room an object's radii take in radiiReach: only compound radii have circles of their own.
std::uint32_t compoundCount(const GameObject& object) {
    std::size_t radii = object.boundsOrEmpty().size();
    return radii > 1 ? static_cast<std::uint32_t>(radii) : 0;
}

// Whether two reach circles overlap, each radius widened by its margin.
bool within(const ReachCircle& a, const ReachCircle& b) {
    double reach = a.radius + b.radius + (static_cast<double>(a.margin) + static_cast<double>(b.margin));
    return circlesOverlap(a.x - b.x, a.y - b.y, reach);
}

}  // namespace

Box Box::merged(const Box& o) const {
    return {std::min(minX, o.minX), std::min(minY, o.minY), std::max(maxX, o.maxX), std::max(maxY, o.maxY)};
}

Box Box::around(const ReachCircle& c) {
    double r = c.radius + static_cast<double>(c.margin);
    return {c.x - r, c.y - r, c.x + r, c.y + r};
}

ObjectPose poseOf(const GameObject& object) {
    return ObjectPose(object.transform.position(), object.transform.linear(), &object.boundsOrEmpty(),
                      object.flags);
}

void StepData::build(const DetectionInput& in, std::vector<std::uint32_t>& others, TaskSystem* tasks,
                     std::uint32_t parallelMin, const SlotPlan* plan) {
    std::span<const GameObject> objects = in.objects;
    std::span<const std::uint32_t> indices = in.candidates;
    clearSlots(others);
    // Room for every candidate at once: grown by doubling, the arrays would hold up to twice what
    // they need, and each growth would briefly hold the old copy beside the new (peak memory).
    objectIndex.reserve(indices.size());
    poses.reserve(indices.size());
    reach.reserve(indices.size());
    radiiBegin.reserve(indices.size() + 1);
    regularSlots.reserve(indices.size());

    bool shared = worthSharing(tasks, indices.size(), parallelMin);
    if (plan && buildPlanned(in, others, *plan, tasks, shared)) {
        // One pass did it (the grid's steady state).
    } else if (shared) {
        buildShared(in, others, *tasks);
    } else {
        poses.clear();
        reach.clear();
        radiiBegin.push_back(0);
        // The objects are visited in the caller's order, which is not memory order: fetch a few
        // ahead so that their cache lines arrive in parallel instead of one miss at a time.
        for (std::size_t k = 0; k < indices.size(); ++k) {
            if (k + kPrefetchAhead < indices.size()) prefetchHotPart(objects[indices[k + kPrefetchAhead]]);
            addCandidate(in, indices[k], others);
        }
    }
    if (!containerSlots.empty()) innerBegin.push_back(static_cast<std::uint32_t>(inner.size()));
    std::sort(fastSlots.begin(), fastSlots.end(), [&](const FastSlot& a, const FastSlot& b) {
        return objectIndex[a.slot] < objectIndex[b.slot];  // cast in creation order
    });
    for (std::uint32_t k = 0; k < fastSlots.size(); ++k) reach[fastSlots[k].slot].fast = k;
}

void StepData::clearSlots(std::vector<std::uint32_t>& others) {
    objectIndex.clear();
    radiiBegin.clear();
    radiiReach.clear();
    regularSlots.clear();
    containerSlots.clear();
    innerBegin.clear();
    inner.clear();
    fastSlots.clear();
    others.clear();
}

void StepData::addCandidate(const DetectionInput& in, std::uint32_t index,
                            std::vector<std::uint32_t>& others) {
    const GameObject& object = in.objects[index];
    if (!getsSlot(object, in.containers)) {
        others.push_back(index);
        return;
    }
    auto slot = static_cast<std::uint32_t>(objectIndex.size());
    objectIndex.push_back(index);
    poses.push_back(poseOf(object));
    reach.emplace_back();
    radiiBegin.push_back(radiiBegin.back() + compoundCount(object));
    radiiReach.resize(radiiBegin.back());
    computeReach(slot, object);
    place(slot, object, in, others);
}

bool StepData::buildPlanned(const DetectionInput& in, std::vector<std::uint32_t>& others,
                            const SlotPlan& plan, TaskSystem* tasks, bool shared) {
    std::span<const GameObject> objects = in.objects;
    std::span<const std::uint32_t> indices = in.candidates;
    bool containers = in.containers;
    constexpr std::uint32_t kBlock = SlotPlan::kBlock;
    std::uint32_t slots = plan.slots;
    if (slots > indices.size() || plan.compoundBefore.size() != (slots + kBlock - 1) / kBlock + 1)
        return false;
    auto blocks = static_cast<std::uint32_t>(plan.compoundBefore.size() - 1);
    objectIndex.resize(slots);
    poses.resize(slots);
    reach.resize(slots);
    radiiBegin.resize(slots + 1);
    radiiReach.resize(plan.compoundBefore.back());
    // Whether the plan failed, and the first slot place() must see: before it, every slot is regular.
    std::atomic<bool> wrong{false};
    std::atomic<std::uint32_t> firstToPlace{slots};
    bool casts = !in.fastStarts.empty();
    auto fill = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        std::uint32_t toPlace = slots;
        for (std::uint32_t b = begin; b < end && !wrong.load(std::memory_order_relaxed); ++b) {
            // The block writes radii circles only in its own room, [at, room), so a wrong plan
            // never races.
            std::uint32_t at = plan.compoundBefore[b], room = plan.compoundBefore[b + 1];
            if (at > room || room > radiiReach.size()) {
                wrong.store(true, std::memory_order_relaxed);
                return;
            }
            std::uint32_t last = std::min(slots, (b + 1) * kBlock);
            for (std::uint32_t k = b * kBlock; k < last; ++k) {
                if (k + kPrefetchAhead < last) prefetchHotPart(objects[indices[k + kPrefetchAhead]]);
                const GameObject& object = objects[indices[k]];
                std::uint32_t compound = compoundCount(object);
                if (!getsSlot(object, containers) || compound > room - at) {
                    wrong.store(true, std::memory_order_relaxed);
                    return;
                }
                objectIndex[k] = indices[k];
                radiiBegin[k] = at;
                at += compound;
                writeSlot(k, object);
                if (toPlace == slots && !onlyRegular(k, casts)) toPlace = k;
            }
            if (at != room) {
                wrong.store(true, std::memory_order_relaxed);
                return;
            }
        }
        std::uint32_t seen = firstToPlace.load(std::memory_order_relaxed);
        while (toPlace < seen &&
               !firstToPlace.compare_exchange_weak(seen, toPlace, std::memory_order_relaxed)) {
        }
    };
    if (shared)
        parallelFor(*tasks, blocks, 1, fill);
    else
        fill(0, blocks, 0);
    if (wrong.load(std::memory_order_relaxed)) {
        clearSlots(others);
        return false;
    }
    radiiBegin[slots] = plan.compoundBefore.back();
    std::uint32_t start = firstToPlace.load(std::memory_order_relaxed);
    regularSlots.resize(start);
    std::iota(regularSlots.begin(), regularSlots.end(), 0u);
    for (std::uint32_t slot = start; slot < slots; ++slot)
        place(slot, objects[objectIndex[slot]], in, others);
    for (std::size_t k = slots; k < indices.size(); ++k) addCandidate(in, indices[k], others);
    return true;
}

void StepData::buildShared(const DetectionInput& in, std::vector<std::uint32_t>& others, TaskSystem& tasks) {
    std::span<const GameObject> objects = in.objects;
    std::span<const std::uint32_t> indices = in.candidates;
    bool containers = in.containers;
    // Each candidate's radii count (0: no slot), written where its slot's offset will go: slot ≤
    // candidate, so the pass below reads each count before any offset overwrites it.
    auto count = static_cast<std::uint32_t>(indices.size());
    radiiBegin.resize(count);
    auto countRadii = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t k = begin; k < end; ++k) {
            if (k + kPrefetchAhead < end) prefetchHotPart(objects[indices[k + kPrefetchAhead]]);
            const GameObject& object = objects[indices[k]];
            radiiBegin[k] =
                getsSlot(object, containers) ? static_cast<std::uint32_t>(object.boundsOrEmpty().size()) : 0;
        }
    };
    parallelFor(tasks, count, kMinShare, countRadii);
    // Slots in candidate order; only compound radii take room in radiiReach.
    std::uint32_t compound = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
        std::uint32_t radii = radiiBegin[k];
        if (radii == 0) continue;
        radiiBegin[objectIndex.size()] = compound;
        objectIndex.push_back(indices[k]);
        if (radii > 1) compound += radii;
    }
    auto slots = static_cast<std::uint32_t>(objectIndex.size());
    radiiBegin.resize(slots);
    radiiBegin.push_back(compound);
    // Every pose and reach circle is written below, on the workers: resizing keeps the last step's
    // elements instead of writing each one twice.
    poses.resize(slots);
    reach.resize(slots);
    radiiReach.resize(compound);
    auto computePoses = [&](std::uint32_t begin, std::uint32_t end, std::uint32_t) {
        for (std::uint32_t slot = begin; slot < end; ++slot) {
            if (slot + kPrefetchAhead < end) prefetchHotPart(objects[objectIndex[slot + kPrefetchAhead]]);
            const GameObject& object = objects[objectIndex[slot]];
            writeSlot(slot, object);
        }
    };
    parallelFor(tasks, slots, kMinShare, computePoses);
    // The candidates without a slot and the slots, placed in candidate order as build places them:
    // the slots are the candidates with one, in order.
    std::uint32_t slot = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
        if (slot == slots || objectIndex[slot] != indices[k]) {
            others.push_back(indices[k]);
            continue;
        }
        place(slot, objects[indices[k]], in, others);
        ++slot;
    }
}

void StepData::place(std::uint32_t slot, const GameObject& object, const DetectionInput& in,
                     std::vector<std::uint32_t>& others) {
    std::span<const FastStart> fastStarts = in.fastStarts;
    // The pose's copy of the flags is read, not the object's: buildShared's pass in slot order then
    // touches only the fast objects and the containers.
    std::uint32_t index = objectIndex[slot];
    ObjectFlags flags = poses[slot].flags;
    Box box = Box::around(reach[slot]);

    if ((flags & kFast) && !fastStarts.empty()) {
        auto start = std::lower_bound(fastStarts.begin(), fastStarts.end(), index,
                                      [](const FastStart& f, std::uint32_t i) { return f.object < i; });
        const Vec2& end = object.transform.position();
        if (start != fastStarts.end() && start->object == index &&
            (start->x != end.x() || start->y != end.y())) {
            ReachCircle before = reach[slot];
            before.x -= end.x() - start->x;
            before.y -= end.y() - start->y;
            box = box.merged(Box::around(before));
            fastSlots.push_back({slot, start->x, start->y, box});
        }
    }

    if (!finite(reach[slot], box)) {
        // Such an object never hits (NaN comparisons are false): no broad phase sees it.
        others.push_back(index);
        return;
    }
    if (!(flags & kContainer)) {
        regularSlots.push_back(slot);
        return;
    }
    others.push_back(index);
    containerSlots.push_back(slot);
    innerBegin.push_back(static_cast<std::uint32_t>(inner.size()));
    const Bounds& radii = object.boundsOrEmpty();
    Vec2 s = object.transform.scaleFactors();
    double sigmaMin = std::min(std::fabs(s.x()), std::fabs(s.y()));
    for (std::size_t k = 0; k < radii.size(); ++k) {
        Vec2 c = poses[slot].worldCentre(k);
        double r = sigmaMin * innerBoundRadius(radii[k], in.accuracy);
        inner.push_back({c.x(), c.y(), r, marginFor(c.x(), c.y(), r)});
    }
}

bool StepData::onlyRegular(std::uint32_t slot, bool casts) const {
    ObjectFlags flags = poses[slot].flags;
    return !(flags & kContainer) && !((flags & kFast) && casts) &&
           finite(reach[slot], Box::around(reach[slot]));
}

void StepData::writeSlot(std::uint32_t slot, const GameObject& object) {
    poses[slot] = poseOf(object);
    reach[slot] = ReachCircle{};
    computeReach(slot, object);
}

void StepData::computeReach(std::uint32_t slot, const GameObject& object) {
    const Bounds& radii = object.boundsOrEmpty();
    const ObjectPose& pose = poses[slot];
    Vec2 s = object.transform.scaleFactors();
    double sigmaMax = std::max(std::fabs(s.x()), std::fabs(s.y()));
    ReachCircle& c = reach[slot];
    std::uint32_t fast = c.fast;
    if (radii.size() == 1) {
        Vec2 centre = pose.worldCentre(0);
        double r = sigmaMax * radii[0].maxRadius();
        c = makeReach(centre.x(), centre.y(), r, fast);
        return;
    }
    // Compound: a circle about the position holding every bound's circle, R = max_k |L·c_k| +
    // σmax·maxRadius_k.
    double farthest = 0.0;
    std::uint32_t first = radiiBegin[slot];
    for (std::size_t k = 0; k < radii.size(); ++k) {
        Vec2 offset = pose.linear * radii[k].centre();
        double r = sigmaMax * radii[k].maxRadius();
        farthest = std::max(farthest, offset.norm() + r);
        Vec2 centre = pose.position + offset;
        radiiReach[first + k] = makeReach(centre.x(), centre.y(), r).disc();
    }
    c = makeReach(pose.position.x(), pose.position.y(), farthest, fast);
}

void StepData::refresh(std::uint32_t slot, const GameObject& object) {
    poses[slot] = poseOf(object);
    computeReach(slot, object);
    if (!isContainer(slot) || !std::binary_search(containerSlots.begin(), containerSlots.end(), slot)) return;
    std::size_t c = containerOrdinal(slot);
    for (std::uint32_t k = innerBegin[c]; k < innerBegin[c + 1]; ++k) {
        Vec2 centre = poses[slot].worldCentre(k - innerBegin[c]);
        InnerCircle& w = inner[k];
        w.x = centre.x();
        w.y = centre.y();
        w.margin = marginFor(w.x, w.y, w.inner);
    }
}

bool StepData::mayHit(std::uint32_t a, std::uint32_t b) const {
    return within(reach[a], reach[b]) && radiiMayTouch(a, b);
}

bool StepData::compoundRadiiMayTouch(std::uint32_t a, std::uint32_t b) const {
    std::uint32_t a0 = radiiBegin[a], a1 = radiiBegin[a + 1], b0 = radiiBegin[b], b1 = radiiBegin[b + 1];
    // Compound radii: the narrow phase compares one bound of each, so some pair of radii circles
    // must overlap. A single radii's circle is the object's reach circle.
    Disc onlyA = reach[a].disc(), onlyB = reach[b].disc();
    std::span<const Disc> as =
        a0 == a1 ? std::span<const Disc>(&onlyA, 1) : std::span<const Disc>(radiiReach).subspan(a0, a1 - a0);
    std::span<const Disc> bs =
        b0 == b1 ? std::span<const Disc>(&onlyB, 1) : std::span<const Disc>(radiiReach).subspan(b0, b1 - b0);
    for (const Disc& ca : as)
        for (const Disc& cb : bs)
            if (ca.touches(cb)) return true;
    return false;
}

double StepData::contactGap(std::uint32_t a, std::uint32_t b) const {
    return contactGap(reach[a], reach[b]);
}

double StepData::contactGap(const ReachCircle& a, const ReachCircle& b) {
    return std::hypot(a.x - b.x, a.y - b.y) - (a.radius + b.radius + double(a.margin) + double(b.margin));
}

std::size_t StepData::containerOrdinal(std::uint32_t slot) const {
    auto at = std::lower_bound(containerSlots.begin(), containerSlots.end(), slot);
    assert(at != containerSlots.end() && *at == slot);
    return static_cast<std::size_t>(at - containerSlots.begin());
}

double StepData::containerGap(std::size_t c, std::uint32_t held) const {
    return containerGap(c, reach[held]);
}

double StepData::containerGap(std::size_t c, const ReachCircle& o) const {
    // The pair hits iff |u| + r ≥ R. With u between any radii centres, |u| ≤ |w_k − c_O| + (the held
    // object's reach about its circle's centre), r ≤ that reach, and R ≥ the inner circle's radius.
    double gap = INFINITY;
    for (std::uint32_t k = innerBegin[c]; k < innerBegin[c + 1]; ++k) {
        const InnerCircle& w = inner[k];
        gap = std::min(gap, w.inner - std::hypot(w.x - o.x, w.y - o.y) - w.margin);
    }
    return gap - o.radius - double(o.margin);
}

std::size_t StepData::bytes() const {
    return objectIndex.capacity() * sizeof(std::uint32_t) + poses.capacity() * sizeof(ObjectPose) +
           reach.capacity() * sizeof(ReachCircle) + radiiBegin.capacity() * sizeof(std::uint32_t) +
           radiiReach.capacity() * sizeof(Disc) + regularSlots.capacity() * sizeof(std::uint32_t) +
           fastSlots.capacity() * sizeof(FastSlot) + containerBytes();
}

std::size_t StepData::containerBytes() const {
    return containerSlots.capacity() * sizeof(std::uint32_t) + innerBegin.capacity() * sizeof(std::uint32_t) +
           inner.capacity() * sizeof(InnerCircle);
}

}  // namespace polar
