#pragma once
#include <cstdint>
#include <span>
#include <vector>

#include "broad_phase/disc.h"
#include "narrow_phase/pair_rule.h"
#include "narrow_phase/pair_test.h"
#include "polar/collision.h"
#include "polar/game_object.h"
#include "polar/tasks.h"
#include "shapes/outline.h"

namespace polar {

// A circle that holds everything of an object a pair test can reach, with an allowance for rounding.
// For any radii k of the object and any direction, the narrow phase's world radius is ≤ σmax·maxRadius_k
// (σmax = the largest singular value of L = R·S, which is max(|sx|, |sy|)), because |L·d̂| ≤ σmax and a
// sample or a straight edge between samples is never farther out than its farthest sample.
struct ReachCircle {
    static constexpr std::uint32_t kNotFast = ~std::uint32_t(0);
    double x = 0.0;
    double y = 0.0;
    double radius = 0.0;
    float margin = 0.0f;  // absolute allowance for the narrow phase's rounding (rounded up to a float)
    std::uint32_t fast = kNotFast;  // for a fast slot, its index in StepData::fastSlots

    // The same circle with its margin added to the radius. The sum's rounding (half an ulp) is lost
    // in the margin, which is some 10⁷ ulps of the radius.
    Disc disc() const { return {x, y, radius + static_cast<double>(margin)}; }
};

// An axis-aligned box in world units.
struct Box {
    double minX = 0.0;
    double minY = 0.0;
    double maxX = 0.0;
    double maxY = 0.0;

    bool overlaps(const Box& o) const {
        return minX <= o.maxX && o.minX <= maxX && minY <= o.maxY && o.minY <= maxY;
    }
    Box merged(const Box& o) const;
    static Box around(const ReachCircle& c);
};

// A container's radii as the pair rule can see them from inside: a world centre and a radius the
// wall never comes nearer than (σmin·innerRadius, σmin = min(|sx|, |sy|)).
struct InnerCircle {
    double x = 0.0;
    double y = 0.0;
    double inner = 0.0;
    double margin = 0.0;
};

// The bound-space distance from a bound's centre to the nearest point of the outline the narrow
// phase reads at this accuracy level (shapeAt: the file's rule, or the level's own): the smallest
// sample under the nearest rule; under the chord rule, the nearest straight edge (the distance from
// the origin to the segment between neighbouring sample points). Outline computes it once, when the
// radii are built.
inline double innerBoundRadius(const Bound& radii, Accuracy accuracy) {
    return outlineOf(radii, shapeAt(radii, accuracy)).minRadius();
}

// Where a fast object was before this step's integration.
struct FastStart {
    std::uint32_t object = 0;  // index in creation order
    double x = 0.0;
    double y = 0.0;
};

// A fast object among the slots, with where it started the step and the box its reach covers on
// the way to where it ended (its cast).
struct FastSlot {
    std::uint32_t slot = 0;
    double startX = 0.0;
    double startY = 0.0;
    Box castBox;
};

// What a detection pass is asked, handed down whole: from World::collide through Detector::prepare
// to StepData::build and each slot it places. The objects stay the world's; the broad phase only
// reads them.
struct DetectionInput {
    std::span<const GameObject> objects;        // every object, in creation order
    std::span<const std::uint32_t> candidates;  // the indices of those flagged collisions, in slot order
    bool containers = false;                    // container pairs are tested (the containers effect)
    Accuracy accuracy = Accuracy::Bounds;       // the narrow phase's level (accuracy.h)
    std::span<const FastStart> fastStarts;      // fast objects' starts (ccd), sorted by object
};

// An object's pose for the narrow phase: its position, L = R·S, bounds and flags.
ObjectPose poseOf(const GameObject& object);

// What one step tells the next about its candidates when they come in the order it laid out (the
// grid's cell order): the first `slots` of them had slots, and `compoundBefore[b]` counts the
// compound radii of those before block b, of kBlock candidates each (the total last). With it, one
// pass over the objects fills every slot, each block writing its radii circles from its own offset.
// build checks each figure it uses: a plan that no longer holds costs time, never a result.
struct SlotPlan {
    static constexpr std::uint32_t kBlock = 1024;
    std::uint32_t slots = 0;
    std::vector<std::uint32_t> compoundBefore;
};

// The hot per-step data of the collision candidates, in contiguous arrays indexed by slot.
//
// Why slots? Detection reads a few numbers per object many times (once per nearby object), while a
// GameObject is a wide struct that game logic owns. Copying what pairs need into packed arrays once
// per object per step (the pose, a reach circle, a box, the world circles of compound radii) keeps the
// pair loops on contiguous memory. The caller picks the slot order: creation order for all-pairs and
// sort-and-sweep, the grid's last cell order for the grid, so that neighbours in space are
// neighbours in memory. The arrays keep their capacity: in a steady state a step allocates nothing.
class StepData {
  public:
    // Fills the slots, in the order of `in.candidates`, from those objects that can take part in a
    // tested pair: flagged collisions (the caller's list) with at least one bound; containers only
    // when `in.containers`, with inner circles for the narrow phase at `in.accuracy`. Fast objects with
    // a start get a box that covers their cast from their start to their position. The indices that
    // got no regular slot go to `others`, in order. With `tasks`, at least `parallelMin` candidates and
    // more than one worker, the poses and reach circles are computed on the workers (the same bits).
    // `plan`, when given, is the last step's word on these candidates (the same result, sooner).
    void build(const DetectionInput& in, std::vector<std::uint32_t>& others, TaskSystem* tasks = nullptr,
               std::uint32_t parallelMin = 0, const SlotPlan* plan = nullptr);
    // Recomputes a slot's pose and reach circle after its object moved (its box is kept).
    void refresh(std::uint32_t slot, const GameObject& object);

    std::size_t size() const { return objectIndex.size(); }
    // The slot's box: around its reach circle, or for a fast slot, around its cast from its start.
    Box box(std::uint32_t slot) const {
        const ReachCircle& c = reach[slot];
        return c.fast == ReachCircle::kNotFast ? Box::around(c) : fastSlots[c.fast].castBox;
    }
    bool isContainer(std::uint32_t slot) const { return (poses[slot].flags & kContainer) != 0; }
    // A conservative test: false only when the pair's narrow phase cannot report a hit.
    bool mayHit(std::uint32_t a, std::uint32_t b) const;
    // The part of mayHit after the reach circles, for a broad phase that has tested those itself:
    // for compound radii, whether some pair of the radii's circles touches (true for two single ones).
    bool radiiMayTouch(std::uint32_t a, std::uint32_t b) const {
        return (single(a) && single(b)) || compoundRadiiMayTouch(a, b);
    }
    bool single(std::uint32_t slot) const { return radiiBegin[slot] == radiiBegin[slot + 1]; }
    // For the c-th container (containerSlots[c]) and a non-container slot: > 0 means no hit is
    // possible, and none becomes possible until the held object moves by more than this.
    double containerGap(std::size_t c, std::uint32_t held) const;
    // The position of a finite container slot in containerSlots.
    std::size_t containerOrdinal(std::uint32_t slot) const;
    // For two non-container slots: > 0 means no hit, and none until one moves by more than this.
    double contactGap(std::uint32_t a, std::uint32_t b) const;
    // The same two gaps for a held object's reach circle placed anywhere (along a cast).
    double containerGap(std::size_t c, const ReachCircle& held) const;
    static double contactGap(const ReachCircle& a, const ReachCircle& b);
    // The memory held, and the part of it that only the containers effect uses.
    std::size_t bytes() const;
    std::size_t containerBytes() const;

    std::vector<std::uint32_t> objectIndex;  // creation-order index of each slot's object
    std::vector<ObjectPose> poses;
    std::vector<ReachCircle> reach;
    std::vector<std::uint32_t> radiiBegin;      // size() + 1 offsets into radiiReach (compound objects only)
    std::vector<Disc> radiiReach;               // per radii of compound objects
    std::vector<std::uint32_t> regularSlots;    // finite, non-container slots: what a broad phase pairs
    std::vector<std::uint32_t> containerSlots;  // finite container slots
    std::vector<std::uint32_t> innerBegin;      // per container slot, offsets into inner
    std::vector<InnerCircle> inner;
    std::vector<FastSlot> fastSlots;  // fast slots that moved this step, in creation order

  private:
    // Empties every array that build fills slot by slot (poses and reach circles keep theirs).
    void clearSlots(std::vector<std::uint32_t>& others);
    // build one candidate at a time: a slot for the object if it gets one, placed at once; else it
    // joins `others`. radiiBegin holds size() + 1 offsets before and after.
    void addCandidate(const DetectionInput& in, std::uint32_t index, std::vector<std::uint32_t>& others);
    // build by `plan`: one pass over its slots (on the workers when `shared`), place() from the
    // first slot that is not only regular, then the candidates after the plan's slots one at a
    // time. False, with nothing built, when the plan does not hold.
    bool buildPlanned(const DetectionInput& in, std::vector<std::uint32_t>& others, const SlotPlan& plan,
                      TaskSystem* tasks, bool shared);
    // build on the workers: which candidates get a slot (counted per candidate in parallel, placed in
    // order here), their poses and circles (in parallel, each slot its own), then place() in order.
    void buildShared(const DetectionInput& in, std::vector<std::uint32_t>& others, TaskSystem& tasks);
    // Whether place() would only add the slot to regularSlots: no container, not fast while there
    // are casts (`casts`: fast starts were given), and finite.
    bool onlyRegular(std::uint32_t slot, bool casts) const;
    // After the slot's pose and reach circle: its fast cast, and whether it is regular, a container
    // (with its inner circles) or, not finite, among `others`. Slots are placed in slot order.
    void place(std::uint32_t slot, const GameObject& object, const DetectionInput& in,
               std::vector<std::uint32_t>& others);
    // Writes a slot's pose and reach circles afresh, on the workers' passes (radiiBegin[slot] set).
    void writeSlot(std::uint32_t slot, const GameObject& object);
    // Writes the slot's reach circle and, for compound radii, the circles from radiiBegin[slot] on.
    void computeReach(std::uint32_t slot, const GameObject& object);
    // radiiMayTouch when at least one of the two has compound radii.
    bool compoundRadiiMayTouch(std::uint32_t a, std::uint32_t b) const;
};

}  // namespace polar
