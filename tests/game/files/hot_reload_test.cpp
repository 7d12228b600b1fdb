// Hot reload, headless: the game runs tick by tick, a bounds file (in a mod laid over assets/) changes
// between two ticks, and HotReload::update applies it, or keeps the old bounds and reports the error.
#include "files/hot_reload.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "app/hud/hot_reload_hud.h"
#include "polar/platform/png_io.h"
#include "polar/render/canvas.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

std::string circleBounds(double radius) {
    return "{\"format\": 1, \"radii\": [{\"samples\": [[0, " + std::to_string(radius) + "]]}]}\n";
}

class HotReloadTest : public ::testing::Test {
  protected:
    void SetUp() override {
        mod_ = polar::testing::freshTestFolder("polar-reload");
        fs::create_directories(mod_ / "sprites");
        edit("sprites/bullet.bounds.json", circleBounds(2));
    }
    void TearDown() override { fs::remove_all(mod_); }

    // Writes a file of the mod as an editor would, and moves its time on, so that even a file
    // system with coarse timestamps shows the change.
    void edit(const std::string& logical, const std::string& text) {
        fs::path path = mod_ / logical;
        fs::create_directories(path.parent_path());
        std::ofstream(path, std::ios::binary) << text;
        fs::last_write_time(path, fs::file_time_type::clock::now() + std::chrono::seconds(++edits_));
    }

    Game newGame(const FileReader& reader) {
        Game::Config config;
        config.reader = reader;
        config.seed = 7;
        Result<Game> game = Game::create(config);
        EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
        return std::move(*game);
    }

    // The radius of every bullet in the world (bullets are circles in these tests).
    static std::vector<double> bulletRadii(const Game& game) {
        std::vector<double> out;
        for (const GameObject& o : game.world().objects())
            if (game.kindOf(o.id) == Kind::Bullet) out.push_back(o.boundsOrEmpty().at(0).maxRadius());
        return out;
    }

    // Ticks while firing until a shot is fired; returns the radius of the bullet it made.
    static double fireOne(Game& game) {
        for (int t = 0; t < 60; ++t) {
            game.tick(kFire);
            for (const GameEvent& e : game.events()) {
                if (e.type != GameEvent::Shot) continue;
                const auto& objects = game.world().objects();
                for (auto o = objects.rbegin(); o != objects.rend(); ++o)  // the newest bullet
                    if (game.kindOf(o->id) == Kind::Bullet) return o->boundsOrEmpty().at(0).maxRadius();
            }
        }
        ADD_FAILURE() << "no shot in 60 ticks";
        return 0;
    }

    fs::path mod_;
    int edits_ = 0;
};

TEST_F(HotReloadTest, AnEditAppliesBetweenTicksToLiveAndLaterObjects) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    Game twin = newGame(reload.reader());  // same seed and inputs, never reloaded
    EXPECT_TRUE(reload.update({&game}).looked) << "the first call looks at once";
    EXPECT_EQ(fireOne(game), 2);
    fireOne(twin);
    ASSERT_EQ(game.hash(), twin.hash());
    std::vector<double> before = bulletRadii(game);
    ASSERT_FALSE(before.empty());

    edit("sprites/bullet.bounds.json", circleBounds(3.5));
    // It is seen at the next look: 30 calls after the last one (half a second at 60 Hz).
    for (int call = 1; call < 30; ++call) {
        HotReload::Report report = reload.update({&game});
        EXPECT_FALSE(report.looked) << "call " << call;
        game.tick(kFire);
        twin.tick(kFire);
    }
    ASSERT_EQ(game.hash(), twin.hash()) << "nothing applied yet";
    EXPECT_EQ(bulletRadii(game), std::vector<double>(bulletRadii(game).size(), 2.0)) << "not yet";
    HotReload::Report report = reload.update({&game});
    ASSERT_TRUE(report.looked);
    ASSERT_EQ(report.reloaded, std::vector<std::string>{"sprites/bullet.bounds.json"});
    EXPECT_TRUE(report.errors.empty());
    std::vector<double> live = bulletRadii(game);
    ASSERT_FALSE(live.empty()) << "bullets live 51 ticks";
    EXPECT_EQ(report.objects, std::vector<std::size_t>{live.size()});
    for (double r : live) EXPECT_EQ(r, 3.5) << "every live bullet has the new bounds";
    EXPECT_NE(reload.notice().find("reloaded " + (mod_ / "sprites/bullet.bounds.json").generic_string()),
              std::string::npos)
        << reload.notice();

    EXPECT_EQ(fireOne(game), 3.5) << "a bullet spawned later gets them too";
    EXPECT_EQ(fireOne(twin), 2.0) << "the twin was not reloaded";
    ASSERT_EQ(game.tickCount(), twin.tickCount());
    EXPECT_TRUE(game.modified());
    EXPECT_EQ(game.boundsEdits(), 1u);
    EXPECT_FALSE(twin.modified());
    EXPECT_NE(game.hash(), twin.hash()) << "a replay checker sees that the game was modified";
    for (int t = 0; t < 120; ++t) game.tick(kFire | kTurnLeft);
}

TEST_F(HotReloadTest, F5LooksAtOnce) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    fireOne(game);
    edit("sprites/bullet.bounds.json", circleBounds(4));
    EXPECT_FALSE(reload.update({&game}).looked);
    HotReload::Report report = reload.update({&game}, true);
    ASSERT_EQ(report.reloaded.size(), 1u);
    for (double r : bulletRadii(game)) EXPECT_EQ(r, 4);
    // Touching a file without changing it, or F5 with nothing changed, applies nothing.
    fs::last_write_time(mod_ / "sprites/bullet.bounds.json",
                        fs::file_time_type::clock::now() + std::chrono::hours(1));
    EXPECT_TRUE(reload.update({&game}, true).reloaded.empty());
    EXPECT_TRUE(reload.update({&game}, true).reloaded.empty());
    EXPECT_EQ(game.boundsEdits(), 1u);
}

TEST_F(HotReloadTest, AnInvalidEditKeepsTheOldBoundsAndShowsWhereItIsWrong) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    fireOne(game);
    const std::string disk = (mod_ / "sprites/bullet.bounds.json").generic_string();

    // A modder's typo: a negative radius on line 3.
    edit("sprites/bullet.bounds.json",
         "{\n  \"format\": 1,\n  \"radii\": [{\"samples\": [[0, 2], [90, -3]]}]\n}\n");
    HotReload::Report report = reload.update({&game}, true);
    EXPECT_TRUE(report.reloaded.empty());
    ASSERT_EQ(report.errors.size(), 1u);
    EXPECT_EQ(report.errors[0].message().rfind(disk + ":3:", 0), 0u)
        << "file:line:column of the file on disk: " << report.errors[0].message();
    EXPECT_NE(report.errors[0].message().find("radius -3 is not positive"), std::string::npos);
    ASSERT_EQ(reload.problems().size(), 1u);
    for (double r : bulletRadii(game)) EXPECT_EQ(r, 2) << "the old bounds stay";
    EXPECT_EQ(fireOne(game), 2);
    EXPECT_FALSE(game.modified());
    for (int t = 0; t < 60; ++t) game.tick(kFire);  // the game goes on

    // The same problem is reported once, not at every look.
    EXPECT_TRUE(reload.update({&game}, true).errors.empty());
    // A game started meanwhile gets the last valid version, as the running one has.
    Game later = newGame(reload.reader());
    EXPECT_EQ(fireOne(later), 2);

    // Broken JSON: a new error with its own line and column.
    edit("sprites/bullet.bounds.json", "{\"format\": 1, \"radii\": [\n");
    report = reload.update({&game}, true);
    ASSERT_EQ(report.errors.size(), 1u);
    EXPECT_EQ(report.errors[0].message().rfind(disk + ":2:", 0), 0u) << report.errors[0].message();

    // Fixed: the problem goes away and the new bounds apply.
    edit("sprites/bullet.bounds.json", circleBounds(5));
    report = reload.update({&game, &later}, true);
    EXPECT_EQ(report.fixed, std::vector<std::string>{"sprites/bullet.bounds.json"});
    EXPECT_EQ(report.reloaded, std::vector<std::string>{"sprites/bullet.bounds.json"});
    EXPECT_TRUE(reload.problems().empty());
    EXPECT_EQ(fireOne(game), 5);
    EXPECT_EQ(fireOne(later), 5);
}

TEST_F(HotReloadTest, AFileCaughtHalfWrittenGetsAnotherLookBeforeItsErrorShows) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    // An editor saving in place: the file is empty for a moment, written just now.
    std::ofstream(mod_ / "sprites/bullet.bounds.json", std::ios::binary | std::ios::trunc).flush();
    HotReload::Report report;
    for (int call = 0; call < 30; ++call) report = reload.update({&game});
    ASSERT_TRUE(report.looked);
    EXPECT_TRUE(report.errors.empty()) << "too fresh to judge";
    EXPECT_TRUE(reload.problems().empty());
    // Still broken a moment later: now it is an error.
    std::this_thread::sleep_for(std::chrono::milliseconds(350));
    for (int call = 0; call < 30; ++call) report = reload.update({&game});
    ASSERT_TRUE(report.looked);
    ASSERT_EQ(report.errors.size(), 1u);
    EXPECT_EQ(report.errors[0].line, 1);
}

TEST_F(HotReloadTest, AFileAddedToAModWhileRunningTakesOver) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    const GameObject* ship = game.world().find(game.shipId());
    ASSERT_NE(ship, nullptr);
    ASSERT_NE(ship->boundsOrEmpty().at(0).maxRadius(), 6) << "assets/' ship";
    edit("sprites/ship.bounds.json", circleBounds(6));
    HotReload::Report report = reload.update({&game}, true);
    EXPECT_EQ(report.reloaded, std::vector<std::string>{"sprites/ship.bounds.json"});
    EXPECT_EQ(game.world().find(game.shipId())->boundsOrEmpty().at(0).maxRadius(), 6);
    // Removing it again falls back to assets/.
    fs::remove(mod_ / "sprites/ship.bounds.json");
    reload.update({&game}, true);
    EXPECT_NE(game.world().find(game.shipId())->boundsOrEmpty().at(0).maxRadius(), 6);
}

TEST_F(HotReloadTest, SpriteChangesAreReportedForRedrawing) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    RgbaImage red{4, 4, std::vector<std::uint32_t>(16, 0xffff0000)};
    ASSERT_FALSE(savePng(red, (mod_ / "sprites/bullet.png").string()).has_value());
    HotReload::Report report = reload.update({&game}, true);
    EXPECT_NE(std::find(report.spritesChanged.begin(), report.spritesChanged.end(), "sprites/bullet.png"),
              report.spritesChanged.end());
    EXPECT_TRUE(report.reloaded.empty());
}

// A scene may name a sprite in any format; hot reload watches it like a PNG. (The sprites of
// tests/data/images/, found beside assets/ in the source tree.)
TEST_F(HotReloadTest, ASpriteInAnotherFormatIsWatchedToo) {
    const std::string images = std::string(POLAR_ASSET_DIR) + "/../tests/data/images/";
    std::ifstream in(std::string(POLAR_ASSET_DIR) + "/scenes/cave.json", std::ios::binary);
    std::string scene((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string png = "../sprites/cave.png";
    ASSERT_NE(scene.find(png), std::string::npos);
    scene.replace(scene.find(png), png.size(), "../sprites/cave-drawn.gif");
    edit("scenes/gif-cave.json", scene);
    fs::copy_file(images + "sprite.gif", mod_ / "sprites/cave-drawn.gif");
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game::Config config;
    config.reader = reload.reader();
    config.seed = 7;
    config.scene = "scenes/gif-cave.json";
    Result<Game> game = Game::create(config);
    ASSERT_TRUE(game.ok()) << game.error().message();
    std::vector<std::string> sprites = game->spritePaths();
    ASSERT_NE(std::find(sprites.begin(), sprites.end(), "sprites/cave-drawn.gif"), sprites.end());
    reload.update({&*game});
    fs::copy_file(images + "gif-named.png", mod_ / "sprites/cave-drawn.gif",
                  fs::copy_options::overwrite_existing);
    fs::last_write_time(mod_ / "sprites/cave-drawn.gif",
                        fs::file_time_type::clock::now() + std::chrono::seconds(99));
    HotReload::Report report = reload.update({&*game}, true);
    EXPECT_NE(std::find(report.spritesChanged.begin(), report.spritesChanged.end(), "sprites/cave-drawn.gif"),
              report.spritesChanged.end());
}

TEST_F(HotReloadTest, ABrokenSceneEditIsReportedAndNewGamesUseTheLastGoodOne) {
    fs::create_directories(mod_ / "scenes");
    fs::copy_file(fs::path(POLAR_ASSET_DIR) / "scenes/cave.json", mod_ / "scenes/cave.json");
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    edit("scenes/cave.json", "{\"format\": 1, \"objects\": [{\"name\": \"ship\", \"speed\": 3}]}");
    HotReload::Report report = reload.update({&game}, true);
    ASSERT_EQ(report.errors.size(), 1u);
    EXPECT_EQ(report.errors[0].file, (mod_ / "scenes/cave.json").generic_string());
    EXPECT_GT(report.errors[0].line, 0);
    Game later = newGame(reload.reader());  // from the last good scene: a cave and a ship
    EXPECT_NE(later.shipId(), 0u);
}

TEST_F(HotReloadTest, OffWhileRecordingOrReplaying) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    reload.disable("a replay is being recorded or played");
    Game game = newGame(reload.reader());
    reload.update({&game});
    fireOne(game);
    edit("sprites/bullet.bounds.json", circleBounds(4));
    HotReload::Report report = reload.update({&game}, true);
    EXPECT_FALSE(report.looked);
    for (double r : bulletRadii(game)) EXPECT_EQ(r, 2);
    EXPECT_FALSE(game.modified());
    EXPECT_NE(reload.notice().find("hot reload is off"), std::string::npos) << "F5 says why nothing happens";
}

TEST_F(HotReloadTest, TheHudShowsTheErrorInTheBitmapFont) {
    AssetFs assets(POLAR_ASSET_DIR, {mod_.string()});
    HotReload reload(assets, 30);
    Game game = newGame(reload.reader());
    reload.update({&game});
    render::Canvas clean(640, 360), shown(640, 360);
    OverlayLayout cleanLayout(640, 360), shownLayout(640, 360);
    drawHotReloadStatus(clean, cleanLayout, reload);
    EXPECT_TRUE(cleanLayout.boxes().empty());
    for (int y = 0; y < 360; ++y)
        for (int x = 0; x < 640; ++x)
            ASSERT_EQ(clean.pixel(x, y), render::kBlack) << "nothing to say, nothing drawn";

    edit("sprites/bullet.bounds.json", "{\"format\": 1, \"radii\": [{\"samples\": []}]}");
    reload.update({&game}, true);
    ASSERT_EQ(reload.problems().size(), 1u);
    drawHotReloadStatus(shown, shownLayout, reload);
    EXPECT_EQ(shownLayout.boxes().size(), 1u) << "the problem claimed one box of the overlay layout";
    // A dark red box near the bottom with light text in it.
    int boxPixels = 0, textPixels = 0;
    for (int y = 200; y < 360; ++y)
        for (int x = 0; x < 640; ++x) {
            render::Color c = shown.pixel(x, y);
            boxPixels += c.r > 40 && c.g < 20 && c.b < 20;
            textPixels += c.r > 200 && c.g > 120;
        }
    EXPECT_GT(boxPixels, 5000);
    EXPECT_GT(textPixels, 300);
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 640; ++x)
            ASSERT_EQ(shown.pixel(x, y), render::kBlack) << "the top of the screen stays clear";
}

TEST(WrapText, CutsAtSpacesWithinTheWidth) {
    std::vector<std::string> lines =
        wrapText("sprites/ship.bounds.json:3:14: radius -3 is not positive; expected a radius > 0", 30);
    ASSERT_GE(lines.size(), 3u);
    std::string joined;
    for (const std::string& line : lines) {
        EXPECT_LE(line.size(), 30u);
        joined += (joined.empty() ? "" : " ") + line;
    }
    EXPECT_EQ(joined, "sprites/ship.bounds.json:3:14: radius -3 is not positive; expected a radius > 0");
    EXPECT_EQ(wrapText(std::string(70, 'x'), 30).size(), 3u) << "a word longer than a line is cut";
}

}  // namespace
}  // namespace polar::game
