#include "app/hud/scene_thumbnail.h"

#include <gtest/gtest.h>

#include "files/assets.h"

namespace polar::game {
namespace {

// How many pixels of two same-sized canvases differ.
int differing(const render::Canvas& a, const render::Canvas& b) {
    int n = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) n += !(a.pixel(x, y) == b.pixel(x, y));
    return n;
}

TEST(SceneThumbnailTest, EachSceneHasItsOwnSmallPicture) {
    AssetFs assets(POLAR_ASSET_DIR);
    SpriteCache sprites(assets);
    Result<render::Canvas> cave = sceneThumbnail(assets, sprites, "scenes/cave.json");
    Result<render::Canvas> field = sceneThumbnail(assets, sprites, "scenes/field.json");
    ASSERT_TRUE(cave.ok()) << cave.error().message();
    ASSERT_TRUE(field.ok()) << field.error().message();
    EXPECT_EQ(cave->width(), kScreenWidth / 4);
    EXPECT_EQ(cave->height(), kScreenHeight / 4);
    // The cave's wall is in its picture and not in the open field's.
    EXPECT_GT(differing(*cave, *field), cave->width() * cave->height() / 20);
    // Drawn twice, the same picture.
    Result<render::Canvas> again = sceneThumbnail(assets, sprites, "scenes/cave.json");
    ASSERT_TRUE(again.ok());
    EXPECT_EQ(differing(*cave, *again), 0);
}

TEST(SceneThumbnailTest, AMissingSceneIsAnErrorNotAPicture) {
    AssetFs assets(POLAR_ASSET_DIR);
    SpriteCache sprites(assets);
    Result<render::Canvas> none = sceneThumbnail(assets, sprites, "scenes/no-such.json");
    ASSERT_FALSE(none.ok());
    EXPECT_NE(none.error().message().find("no-such.json"), std::string::npos) << none.error().message();
}

}  // namespace
}  // namespace polar::game
