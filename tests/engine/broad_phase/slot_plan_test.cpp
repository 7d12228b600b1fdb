// StepData::build with a SlotPlan, the last step's word on its candidates: the same slots, bit for
// bit, as a build without one, whether the plan still holds or not, on one thread or several.
#include <gtest/gtest.h>

#include <functional>
#include <string>
#include <vector>

#include "bits.h"
#include "broad_phase/step_data.h"
#include "polar/authoring/random_scene.h"
#include "polar/tasks.h"
#include "polar/world.h"

namespace polar {
namespace {

// A mixed scene (one to three radii, containers, no radii, scale 0) of more than three plan blocks,
// a few objects flagged fast with a start to cast from, and one whose position is not finite.
struct Candidates {
    std::vector<GameObject> objects;
    std::vector<std::uint32_t> indices;  // the slotted ones first, as the grid orders them
    std::vector<FastStart> starts;
};

Candidates makeCandidates() {
    World world = buildWorld(makeMixedScene(23, 3500, BroadPhase::AllPairs));
    Candidates c{{world.objects().begin(), world.objects().end()}, {}, {}};
    for (std::uint32_t i = 0; i < c.objects.size(); ++i) {
        GameObject& object = c.objects[i];
        if (!object.has(kCollisions)) continue;
        c.indices.push_back(i);
        if (i % 97 == 5 && object.bounds) {
            object.flags |= kFast;
            c.starts.push_back({i, object.transform.position().x() - 30.0, object.transform.position().y()});
        }
    }
    c.objects[c.indices[1500]].transform.setPosition(Vec2(INFINITY, 0.0));
    // Slotted candidates first, in a scrambled order; the rest after them.
    StepData first;
    std::vector<std::uint32_t> others;
    first.build({.objects = c.objects,
                 .candidates = c.indices,
                 .containers = true,
                 .accuracy = Accuracy::Bounds,
                 .fastStarts = c.starts},
                others);
    std::vector<std::uint32_t> slotted = first.objectIndex, rest;
    for (std::uint32_t i : c.indices)
        if (c.objects[i].boundsOrEmpty().empty()) rest.push_back(i);
    for (std::size_t k = 0; k + 7 < slotted.size(); k += 7) std::swap(slotted[k], slotted[k + 3]);
    c.indices = slotted;
    c.indices.insert(c.indices.end(), rest.begin(), rest.end());
    return c;
}

// The plan a detector would write for these candidates: how many have slots, and where each block
// of them starts in radiiReach.
SlotPlan planFor(const Candidates& c) {
    StepData data;
    std::vector<std::uint32_t> others;
    data.build({.objects = c.objects,
                .candidates = c.indices,
                .containers = true,
                .accuracy = Accuracy::Bounds,
                .fastStarts = c.starts},
               others);
    SlotPlan plan;
    plan.slots = static_cast<std::uint32_t>(data.size());
    for (std::uint32_t s = 0; s < plan.slots; s += SlotPlan::kBlock)
        plan.compoundBefore.push_back(data.radiiBegin[s]);
    plan.compoundBefore.push_back(data.radiiBegin[plan.slots]);
    return plan;
}

void expectSame(const StepData& a, const std::vector<std::uint32_t>& aOthers, const StepData& b,
                const std::vector<std::uint32_t>& bOthers, const std::string& what) {
    ASSERT_EQ(a.objectIndex, b.objectIndex) << what;
    EXPECT_EQ(aOthers, bOthers) << what;
    EXPECT_EQ(a.radiiBegin, b.radiiBegin) << what;
    EXPECT_EQ(a.regularSlots, b.regularSlots) << what;
    EXPECT_EQ(a.containerSlots, b.containerSlots) << what;
    EXPECT_EQ(a.innerBegin, b.innerBegin) << what;
    for (std::uint32_t s = 0; s < a.size(); ++s) {
        ASSERT_EQ(bits(a.poses[s].position.x()), bits(b.poses[s].position.x())) << what << ", slot " << s;
        ASSERT_EQ(bits(a.poses[s].position.y()), bits(b.poses[s].position.y())) << what << ", slot " << s;
        for (int e = 0; e < 4; ++e) ASSERT_EQ(bits(a.poses[s].linear(e)), bits(b.poses[s].linear(e))) << what;
        ASSERT_EQ(a.poses[s].flags, b.poses[s].flags) << what;
        ASSERT_EQ(a.poses[s].bounds, b.poses[s].bounds) << what;
        ASSERT_EQ(bits(a.reach[s].x), bits(b.reach[s].x)) << what << ", slot " << s;
        ASSERT_EQ(bits(a.reach[s].y), bits(b.reach[s].y)) << what << ", slot " << s;
        ASSERT_EQ(bits(a.reach[s].radius), bits(b.reach[s].radius)) << what << ", slot " << s;
        ASSERT_EQ(a.reach[s].margin, b.reach[s].margin) << what << ", slot " << s;
        ASSERT_EQ(a.reach[s].fast, b.reach[s].fast) << what << ", slot " << s;
    }
    ASSERT_EQ(a.radiiReach.size(), b.radiiReach.size()) << what;
    for (std::size_t k = 0; k < a.radiiReach.size(); ++k) {
        ASSERT_EQ(bits(a.radiiReach[k].x), bits(b.radiiReach[k].x)) << what << ", circle " << k;
        ASSERT_EQ(bits(a.radiiReach[k].y), bits(b.radiiReach[k].y)) << what << ", circle " << k;
        ASSERT_EQ(bits(a.radiiReach[k].reach), bits(b.radiiReach[k].reach)) << what << ", circle " << k;
    }
    ASSERT_EQ(a.inner.size(), b.inner.size()) << what;
    for (std::size_t k = 0; k < a.inner.size(); ++k) {
        EXPECT_EQ(bits(a.inner[k].x), bits(b.inner[k].x)) << what;
        EXPECT_EQ(bits(a.inner[k].inner), bits(b.inner[k].inner)) << what;
    }
    ASSERT_EQ(a.fastSlots.size(), b.fastSlots.size()) << what;
    for (std::size_t k = 0; k < a.fastSlots.size(); ++k) {
        EXPECT_EQ(a.fastSlots[k].slot, b.fastSlots[k].slot) << what;
        EXPECT_EQ(bits(a.fastSlots[k].castBox.minX), bits(b.fastSlots[k].castBox.minX)) << what;
    }
}

// Builds with `plan` (reusing one StepData, as the detector does) on one thread and on three, and
// checks both against a build without a plan.
void expectPlanGivesTheSame(const Candidates& c, const SlotPlan& plan, const std::string& what) {
    StepData fresh;
    std::vector<std::uint32_t> freshOthers;
    fresh.build({.objects = c.objects,
                 .candidates = c.indices,
                 .containers = true,
                 .accuracy = Accuracy::Bounds,
                 .fastStarts = c.starts},
                freshOthers);
    ThreadPool pool(3);
    StepData planned;
    std::vector<std::uint32_t> others;
    for (TaskSystem* tasks : {static_cast<TaskSystem*>(nullptr), static_cast<TaskSystem*>(&pool)}) {
        planned.build({.objects = c.objects,
                       .candidates = c.indices,
                       .containers = true,
                       .accuracy = Accuracy::Bounds,
                       .fastStarts = c.starts},
                      others, tasks, 0, &plan);
        expectSame(fresh, freshOthers, planned, others, what + (tasks ? ", 3 workers" : ", 1 worker"));
    }
}

TEST(SlotPlan, APlanThatHoldsGivesTheSameSlots) {
    Candidates c = makeCandidates();
    SlotPlan plan = planFor(c);
    ASSERT_GT(plan.compoundBefore.size(), 4u);
    ASSERT_LT(plan.slots, c.indices.size()) << "some candidates get no slot";
    expectPlanGivesTheSame(c, plan, "the plan as laid out");
    // A plan that knows fewer slots leaves the rest to be placed one at a time.
    SlotPlan shorter;
    shorter.slots = 2 * SlotPlan::kBlock;
    shorter.compoundBefore.assign(plan.compoundBefore.begin(), plan.compoundBefore.begin() + 3);
    expectPlanGivesTheSame(c, shorter, "a plan of two blocks");
    expectPlanGivesTheSame(c, SlotPlan{}, "an empty plan");
}

TEST(SlotPlan, APlanThatNoLongerHoldsStillGivesTheSameSlots) {
    Candidates c = makeCandidates();
    const SlotPlan plan = planFor(c);
    std::vector<std::pair<std::string, std::function<void(SlotPlan&)>>> wrongs = {
        {"one slot too many", [](SlotPlan& p) { ++p.slots; }},
        {"one slot too few", [](SlotPlan& p) { --p.slots; }},
        {"more slots than candidates", [](SlotPlan& p) { p.slots = 1u << 20; }},
        {"a block's start one late", [](SlotPlan& p) { ++p.compoundBefore[2]; }},
        {"a block's start one early", [](SlotPlan& p) { --p.compoundBefore[2]; }},
        {"a total too large", [](SlotPlan& p) { p.compoundBefore.back() += 5; }},
        {"a start past the total", [](SlotPlan& p) { p.compoundBefore[1] = p.compoundBefore.back() + 9; }},
        {"a block missing", [](SlotPlan& p) { p.compoundBefore.pop_back(); }},
        {"a block too many", [](SlotPlan& p) { p.compoundBefore.push_back(p.compoundBefore.back()); }},
    };
    for (const auto& [what, spoil] : wrongs) {
        SlotPlan wrong = plan;
        spoil(wrong);
        expectPlanGivesTheSame(c, wrong, what);
    }
}

TEST(SlotPlan, ObjectsThatChangedSinceThePlanGiveTheSameSlots) {
    const Candidates original = makeCandidates();
    const SlotPlan plan = planFor(original);
    BoundsPtr three;
    for (const GameObject& o : original.objects)
        if (o.bounds && o.bounds->size() == 3) three = o.bounds;
    ASSERT_TRUE(three);
    std::vector<std::pair<std::string, std::function<void(GameObject&)>>> changes = {
        {"lost its radii", [](GameObject& o) { o.bounds = nullptr; }},
        {"became compound", [&](GameObject& o) { o.bounds = three; }},
        {"became a container", [](GameObject& o) { o.flags |= kContainer; }},
        {"moved out of the finite", [](GameObject& o) { o.transform.setPosition(Vec2(0.0, NAN)); }},
    };
    for (const auto& [what, change] : changes) {
        for (std::uint32_t k : {0u, 1100u, plan.slots - 1}) {
            Candidates c = original;
            change(c.objects[c.indices[k]]);
            expectPlanGivesTheSame(c, plan, "candidate " + std::to_string(k) + " " + what);
        }
    }
}

}  // namespace
}  // namespace polar
