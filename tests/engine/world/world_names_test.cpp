// World's compact name index: names stay findable through adds, removes and growth.
#include <gtest/gtest.h>

#include <set>

#include "polar/world.h"

namespace polar {
namespace {

TEST(WorldNames, FindsEveryLiveNameThroughAddsAndRemoves) {
    World world;
    std::set<std::string> live;
    auto add = [&](const std::string& name) {
        ObjectDef o;
        o.name = name;
        world.add(o);
        live.insert(name);
    };
    for (int i = 0; i < 3000; ++i) add("rock-" + std::to_string(i));
    for (int i = 0; i < 3000; i += 3) {
        std::string name = "rock-" + std::to_string(i);
        ASSERT_TRUE(world.remove(world.findByName(name)->id));
        live.erase(name);
    }
    for (int i = 0; i < 500; ++i) add("bullet-" + std::to_string(i));
    for (int i = 0; i < 3000; ++i) {
        std::string name = "rock-" + std::to_string(i);
        GameObject* o = world.findByName(name);
        ASSERT_EQ(o != nullptr, live.count(name) == 1) << name;
        if (o) {
            EXPECT_EQ(o->name, name);
        }
        EXPECT_EQ(world.nameTaken(name), live.count(name) == 1);
    }
    EXPECT_EQ(world.findByName("bullet-499")->name, "bullet-499");
    EXPECT_FALSE(world.nameTaken("bullet-500"));
    EXPECT_FALSE(world.nameTaken(""));
    // A copy has its own index.
    World copy = world;
    ASSERT_TRUE(copy.remove(copy.findByName("bullet-7")->id));
    EXPECT_FALSE(copy.nameTaken("bullet-7"));
    EXPECT_TRUE(world.nameTaken("bullet-7"));
    EXPECT_EQ(copy.objects().size() + 1, world.objects().size());
}

}  // namespace
}  // namespace polar
