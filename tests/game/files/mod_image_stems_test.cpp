// A mod's image replaces a lower layer's image of the same folder and stem in any format the loader
// reads (AssetFs's rule, in assets.h): resolve, the summary the game prints, the ship as it is drawn,
// the scenes screen's picture, hot reload and replays all see the mod's sprites/ship.gif in place of
// assets/sprites/ship.png, while a file that is no image never stands in for one.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "app/hud/game_drawing.h"
#include "app/hud/scene_thumbnail.h"
#include "files/assets.h"
#include "files/hot_reload.h"
#include "polar/image_extensions.h"
#include "polar/platform/image_file.h"
#include "polar/platform/png_io.h"
#include "rules/game.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

// tests/data/images/, beside assets/ in the source tree: sprite.gif is 16 × 16 with a white pixel at
// (2, 3); the game's ship.png is 20 × 20.
const fs::path kImages = fs::path(POLAR_ASSET_DIR) / "../tests/data/images";

using polar::testing::readFile;
using polar::testing::writeFile;

void copyInto(const fs::path& from, const fs::path& to) {
    fs::create_directories(to.parent_path());
    fs::copy_file(from, to, fs::copy_options::overwrite_existing);
}

// A w × h PNG of one opaque colour.
void writeSolidPng(const fs::path& p, int w, int h, std::uint32_t argb) {
    fs::create_directories(p.parent_path());
    RgbaImage image{w, h, std::vector<std::uint32_t>(static_cast<std::size_t>(w * h), argb)};
    ASSERT_FALSE(savePng(image, p.string()).has_value());
}

bool samePixels(const render::Canvas& a, const render::Canvas& b) {
    if (a.width() != b.width() || a.height() != b.height()) return false;
    for (int y = 0; y < a.height(); ++y)
        if (!std::equal(a.row(y), a.row(y) + a.width(), b.row(y))) return false;
    return true;
}

class ModImageStems : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = polar::testing::freshTestFolder("polar-stems");
        copyInto(kImages / "sprite.gif", gifMod() / "sprites/ship.gif");
    }
    void TearDown() override { fs::remove_all(folder_); }

    fs::path gifMod() const { return folder_ / "gif-mod"; }
    fs::path mod(const std::string& name) const { return folder_ / name; }
    std::string inMod(const fs::path& mod, const std::string& logical) const {
        return (mod / logical).generic_string();
    }
    static std::string inAssets(const std::string& logical) {
        return (fs::path(POLAR_ASSET_DIR) / logical).generic_string();
    }

    fs::path folder_;
};

TEST_F(ModImageStems, AModsGifReplacesTheGamesPng) {
    AssetFs assets(POLAR_ASSET_DIR, {gifMod().string()});
    EXPECT_EQ(assets.resolve("sprites/ship.png"), inMod(gifMod(), "sprites/ship.gif"));
    EXPECT_EQ(assets.resolve("sprites/ship.gif"), inMod(gifMod(), "sprites/ship.gif")) << "its own name too";
    EXPECT_EQ(assets.resolve("sprites/ship.bounds.json"), inAssets("sprites/ship.bounds.json"))
        << "the bounds are the game's: only images go by stem";
    EXPECT_EQ(assets.resolve("sprites/bullet.png"), inAssets("sprites/bullet.png"));

    // The sprite the game draws for the ship is the GIF's: its size and its white pixel.
    SpriteCache sprites(assets);
    const render::Image& ship = sprites.get("sprites/ship.png");
    EXPECT_TRUE(sprites.problems().empty());
    EXPECT_EQ(ship.width(), 16);
    EXPECT_EQ(ship.height(), 16);
    EXPECT_EQ(ship.pixel(2, 3), (render::Color{255, 255, 255, 255}));
    AssetFs plain(POLAR_ASSET_DIR);
    SpriteCache gameSprites(plain);
    EXPECT_EQ(gameSprites.get("sprites/ship.png").width(), 20) << "without the mod, the game's ship.png";

    std::vector<AssetFs::ModSummary> summary = assets.summarise();
    ASSERT_EQ(summary.size(), 1u);
    EXPECT_EQ(summary[0].replaces, std::vector<std::string>{"sprites/ship.gif"});
    EXPECT_TRUE(summary[0].adds.empty());
}

// The ship in a game and the scenes screen's picture (drawn by sceneThumbnail, at full size here):
// the frame with the mod's GIF is the frame with the same pixels saved as the mod's ship.png, and
// not the game's own frame.
TEST_F(ModImageStems, TheShipAndTheScenesPictureDrawTheModsGif) {
    Result<RgbaImage> gif = loadRgbaImage(inMod(gifMod(), "sprites/ship.gif"));
    ASSERT_TRUE(gif.ok()) << gif.error().message();
    fs::create_directories(mod("png-mod") / "sprites");
    ASSERT_FALSE(savePng(*gif, inMod(mod("png-mod"), "sprites/ship.png")).has_value());

    auto frame = [](const AssetFs& assets) {
        SpriteCache sprites(assets);
        Result<render::Canvas> picture = sceneThumbnail(assets, sprites, "scenes/cave.json", 1);
        EXPECT_TRUE(picture.ok()) << (picture.ok() ? "" : picture.error().message());
        EXPECT_TRUE(sprites.problems().empty());
        return picture.ok() ? std::move(*picture) : render::Canvas(1, 1);
    };
    render::Canvas withGif = frame(AssetFs(POLAR_ASSET_DIR, {gifMod().string()}));
    render::Canvas withPng = frame(AssetFs(POLAR_ASSET_DIR, {mod("png-mod").string()}));
    render::Canvas game = frame(AssetFs(POLAR_ASSET_DIR));
    EXPECT_TRUE(samePixels(withGif, withPng));
    EXPECT_FALSE(samePixels(withGif, game)) << "the ship is drawn from the mod's GIF";
}

// Layer by layer from the last mod down; in one layer the exact name first, then PNG before GIF.
TEST_F(ModImageStems, ALayerWithBothServesTheNamedFileAndTheLastLayerWins) {
    writeSolidPng(mod("both") / "sprites/ship.png", 8, 8, 0xff00ff00);
    copyInto(kImages / "sprite.gif", mod("both") / "sprites/ship.gif");
    AssetFs both(POLAR_ASSET_DIR, {mod("both").string()});
    EXPECT_EQ(both.resolve("sprites/ship.png"), inMod(mod("both"), "sprites/ship.png"));
    EXPECT_EQ(both.resolve("sprites/ship.gif"), inMod(mod("both"), "sprites/ship.gif"));
    EXPECT_EQ(both.resolve("sprites/ship.webp"), inMod(mod("both"), "sprites/ship.png"))
        << "neither is named: PNG comes first in kImageExtensions";
    SpriteCache sprites(both);
    EXPECT_EQ(sprites.get("sprites/ship.png").width(), 8) << "the ship drawn is the mod's ship.png";
    std::vector<AssetFs::ModSummary> summary = both.summarise();
    ASSERT_EQ(summary.size(), 1u);
    EXPECT_EQ(summary[0].replaces, (std::vector<std::string>{"sprites/ship.gif", "sprites/ship.png"}));

    writeSolidPng(mod("png-mod") / "sprites/ship.png", 8, 8, 0xff00ff00);
    AssetFs gifLast(POLAR_ASSET_DIR, {mod("png-mod").string(), gifMod().string()});
    EXPECT_EQ(gifLast.resolve("sprites/ship.png"), inMod(gifMod(), "sprites/ship.gif"))
        << "a later mod's GIF wins over an earlier mod's exact name";
    AssetFs pngLast(POLAR_ASSET_DIR, {gifMod().string(), mod("png-mod").string()});
    EXPECT_EQ(pngLast.resolve("sprites/ship.png"), inMod(mod("png-mod"), "sprites/ship.png"));
    EXPECT_EQ(pngLast.resolve("sprites/ship.gif"), inMod(mod("png-mod"), "sprites/ship.png"))
        << "the later mod holds the stem, so it serves the GIF's name too";
    std::vector<AssetFs::ModSummary> layered = pngLast.summarise();
    ASSERT_EQ(layered.size(), 2u);
    EXPECT_EQ(layered[1].replaces, std::vector<std::string>{"sprites/ship.png"});

    // Two endings of one kind that differ only by case: the lower name, so the answer never depends
    // on the order a folder lists its files in (nine stems, so a folder's order shows).
    std::vector<std::string> rocks;
    for (const char* size : {"small", "medium", "large"})
        for (int v = 1; v <= 3; ++v)
            rocks.push_back(std::string("sprites/rock-") + size + "-" + std::to_string(v));
    for (const std::string& rock : rocks) {
        copyInto(kImages / "sprite.gif", mod("cases") / (rock + ".gif"));
        copyInto(kImages / "sprite.gif", mod("cases") / (rock + ".GIF"));
    }
    AssetFs cases(POLAR_ASSET_DIR, {mod("cases").string()});
    for (const std::string& rock : rocks)
        EXPECT_EQ(cases.resolve(rock + ".png"), inMod(mod("cases"), rock + ".GIF")) << rock;
}

TEST_F(ModImageStems, WhatIsNoImageNeverReplacesOne) {
    writeFile(mod("other") / "sprites/ship.txt", "notes on the ship\n");
    writeFile(mod("other") / "sprites/bullet.bounds.gif", "not a sprite of the bullet\n");
    fs::create_directories(mod("other") / "sprites/comet.gif");  // a folder, not a file
    writeFile(mod("other") / "sprites/rock-small-2.gif.txt", "a GIF's notes\n");
    writeFile(mod("other") / "sprites/pickup.png", "a sprite of another stem\n");
    AssetFs assets(POLAR_ASSET_DIR, {mod("other").string()});
    for (const char* sprite : {"sprites/ship.png", "sprites/bullet.png", "sprites/comet.png",
                               "sprites/rock-small-2.png", "sprites/pickup-life.png"})
        EXPECT_EQ(assets.resolve(sprite), inAssets(sprite)) << sprite;
    EXPECT_EQ(assets.resolve("sprites/ship.json"), std::nullopt) << "only images go by stem";
    std::vector<AssetFs::ModSummary> summary = assets.summarise();
    ASSERT_EQ(summary.size(), 1u);
    EXPECT_TRUE(summary[0].replaces.empty());
    EXPECT_EQ(summary[0].adds,
              (std::vector<std::string>{"sprites/bullet.bounds.gif", "sprites/pickup.png",
                                        "sprites/rock-small-2.gif.txt", "sprites/ship.txt"}));
}

// Without mods every file of assets/ is the file of that name, as before stems counted (the golden
// replays and frames, checked by their own tests, keep their bits on top of this).
TEST_F(ModImageStems, TheGameWithoutModsResolvesEveryFileToItself) {
    AssetFs assets(POLAR_ASSET_DIR);
    std::vector<std::string> files = assets.list("");
    ASSERT_GT(files.size(), 40u);
    for (const std::string& file : files) EXPECT_EQ(assets.resolve(file), inAssets(file)) << file;
    EXPECT_EQ(assets.resolve("sprites/ship.gif"), inAssets("sprites/ship.png"))
        << "the rule holds in assets/ too: an image of the same stem";
    EXPECT_EQ(assets.resolve("sprites/nothing.png"), std::nullopt);
}

// A GIF dropped into a mod while the game runs is seen at the next look, and so is its removal.
TEST_F(ModImageStems, HotReloadSeesAGifArriveAndGo) {
    fs::remove(gifMod() / "sprites/ship.gif");
    AssetFs assets(POLAR_ASSET_DIR, {gifMod().string()});
    HotReload reload(assets, 1);  // looks on every update()
    Game::Config config;
    config.reader = reload.reader();
    Result<Game> game = Game::create(config);
    ASSERT_TRUE(game.ok()) << game.error().message();
    reload.update({&*game});
    auto changed = [&] {
        HotReload::Report report = reload.update({&*game});
        EXPECT_TRUE(report.looked);
        return std::find(report.spritesChanged.begin(), report.spritesChanged.end(), "sprites/ship.png") !=
               report.spritesChanged.end();
    };
    EXPECT_FALSE(changed()) << "nothing changed yet";
    copyInto(kImages / "sprite.gif", gifMod() / "sprites/ship.gif");
    EXPECT_TRUE(changed()) << "the mod's ship.gif now stands for sprites/ship.png";
    EXPECT_FALSE(changed());
    fs::remove(gifMod() / "sprites/ship.gif");
    EXPECT_TRUE(changed()) << "back to the game's ship.png";
}

// Replays stamp the scene and bounds files a game reads (sprites never touch the simulation), so a
// replay plays the same with the mod's GIF; its screenshots show the sprite, so a changed sprite is
// caught there, as for a PNG.
TEST_F(ModImageStems, AReplayOfTheModdedGameVerifiesAndAChangedSpriteIsCaught) {
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short.replay", folder_ / "short.replay");
    fs::copy(fs::path(POLAR_REPLAY_DIR) / "short-600.png", folder_ / "short-600.png");
    auto replay = [&](const std::string& flags) {
        const std::string command = "cd '" + folder_.string() + "' && '" + std::string(POLARCADE_REPLAY_EXE) +
                                    "' " + flags + " short.replay >out.txt 2>&1";
        const int status = std::system(command.c_str());
        return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    };
    auto out = [&] { return readFile(folder_ / "out.txt"); };
    ASSERT_EQ(replay(""), 0) << out();
    EXPECT_EQ(replay("--mod gif-mod"), 1) << "the ship is drawn from the GIF now: " << out();
    EXPECT_NE(out().find("screenshot after tick 600"), std::string::npos) << out();
    EXPECT_NE(out().find("0 passed, 0 desynced, 0 damaged, 1 with differing screenshots"), std::string::npos)
        << "every tick still verifies: " << out();
    EXPECT_EQ(out().find("is not the file"), std::string::npos) << "the same file stamps: " << out();
    ASSERT_EQ(replay("--mod gif-mod --update-screenshots"), 0) << out();
    EXPECT_EQ(replay("--mod gif-mod"), 0) << out();
    writeSolidPng(gifMod() / "sprites/ship.gif", 16, 16, 0xffff00ff);  // other pixels, the same name
    EXPECT_EQ(replay("--mod gif-mod"), 1) << "the changed sprite is caught: " << out();
    EXPECT_NE(out().find("screenshot after tick 600"), std::string::npos) << out();
}

// The modding guide spells out the order of the endings; it is kImageExtensions's, every one of them.
TEST(ModImageStemsGuide, TheGuideListsTheEndingsInTheRulesOrder) {
    const std::string guide = readFile(fs::path(POLAR_ASSET_DIR) / "README.md");
    const std::size_t rule = guide.find("**A picture goes by its folder and name, not its ending.**");
    ASSERT_NE(rule, std::string::npos);
    const std::string paragraph = guide.substr(rule, guide.find("\n- ", rule) - rule);
    std::size_t at = 0;
    for (std::string_view ext : kImageExtensions) {
        at = paragraph.find("`" + std::string(ext) + "`", at);
        ASSERT_NE(at, std::string::npos) << ext << " missing or out of order in the guide's rule";
    }
}

}  // namespace
}  // namespace polar::game
