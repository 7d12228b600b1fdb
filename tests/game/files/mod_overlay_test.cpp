// Mod folders laid over assets/: a later mod wins over an earlier one and both over assets/; a mod can
// replace files and add new sprites, bounds and scenes; the game and the executable see the overlay.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "files/assets.h"
#include "polar/platform/png_io.h"
#include "rules/game.h"
#include "run_command.h"
#include "scratch_folder.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

using polar::testing::readFile;
using polar::testing::writeFile;

// A w × h PNG of one opaque colour.
void writeSolidPng(const fs::path& p, int w, int h, std::uint32_t argb) {
    fs::create_directories(p.parent_path());
    RgbaImage image{w, h, std::vector<std::uint32_t>(static_cast<std::size_t>(w * h), argb)};
    ASSERT_FALSE(savePng(image, p.string()).has_value());
}

std::string circleBounds(double radius) {
    return "{\"format\": 1, \"radii\": [{\"samples\": [[0, " + std::to_string(radius) + "]]}]}\n";
}

// A scene that keeps the game's cave and ship and adds a beacon: a new sprite with new bounds.
const char* kBeaconScene = R"({
  "format": 1,
  "effects": ["physics", "collisions", "response", "containers"],
  "objects": [
    {"name": "cave", "sprite": "../sprites/cave.png", "bounds": "../sprites/cave.bounds.json",
     "position": [320, 180], "flags": ["collisions", "container", "ghost"]},
    {"name": "ship", "sprite": "../sprites/ship.png", "bounds": "../sprites/ship.bounds.json",
     "position": [320, 180], "rotation": 90, "flags": ["physics", "collisions"]},
    {"name": "beacon", "sprite": "../sprites/beacon.png", "bounds": "../sprites/beacon.bounds.json",
     "position": [560, 300]}
  ]
})";

constexpr std::uint32_t kBeaconColor = 0xff00ff00;   // opaque green
constexpr std::uint32_t kModShipColor = 0xffff00ff;  // opaque magenta

class ModOverlay : public ::testing::Test {
  protected:
    void SetUp() override {
        folder_ = polar::testing::freshTestFolder("polar-mods");
        // Mod A: replaces the ship's bounds, adds the beacon (sprite, bounds) and a scene.
        writeFile(modA() / "sprites/ship.bounds.json", circleBounds(7));
        writeSolidPng(modA() / "sprites/beacon.png", 10, 10, kBeaconColor);
        writeFile(modA() / "sprites/beacon.bounds.json", circleBounds(5));
        writeFile(modA() / "scenes/beacon.json", kBeaconScene);
        // Mod B, after A: replaces the ship's bounds again and the ship's picture.
        writeFile(modB() / "sprites/ship.bounds.json", circleBounds(9));
        writeSolidPng(modB() / "sprites/ship.png", 20, 20, kModShipColor);
    }
    void TearDown() override { fs::remove_all(folder_); }

    fs::path modA() const { return folder_ / "mod-a"; }
    fs::path modB() const { return folder_ / "mod-b"; }
    AssetFs overlay() const { return AssetFs(POLAR_ASSET_DIR, {modA().string(), modB().string()}); }

    struct Outcome {
        int exitCode = -1;
        std::string out, err;
    };
    Outcome runGame(const std::string& args) const {
        std::string command = "cd '" + folder_.string() + "' && '" + std::string(POLARCADE_EXE) + "' " +
                              args + " >out.txt 2>err.txt";
        int status = std::system(command.c_str());
        Outcome r{WIFEXITED(status) ? WEXITSTATUS(status) : -1, readFile(folder_ / "out.txt"),
                  readFile(folder_ / "err.txt")};
        return r;
    }

    fs::path folder_;
};

TEST_F(ModOverlay, LaterModsWinThenAssets) {
    AssetFs assets = overlay();
    EXPECT_EQ(assets.resolve("sprites/ship.bounds.json"),
              (modB() / "sprites/ship.bounds.json").generic_string())
        << "both mods have it: the later one wins";
    EXPECT_EQ(assets.resolve("sprites/beacon.png"), (modA() / "sprites/beacon.png").generic_string())
        << "added by A";
    EXPECT_EQ(assets.resolve("sprites/rock-large-1.png"),
              (fs::path(POLAR_ASSET_DIR) / "sprites/rock-large-1.png").generic_string())
        << "no mod has it: assets/";
    EXPECT_FALSE(assets.resolve("sprites/nothing.png").has_value());
    std::optional<SourceFile> ship = assets.reader()("sprites/ship.bounds.json");
    ASSERT_TRUE(ship.has_value());
    EXPECT_EQ(ship->text, circleBounds(9));

    // Only mod A alone: its own version.
    AssetFs onlyA(POLAR_ASSET_DIR, {modA().string()});
    EXPECT_EQ(onlyA.reader()("sprites/ship.bounds.json")->text, circleBounds(7));
}

TEST_F(ModOverlay, ListsAndSummariesCoverEveryLayer) {
    AssetFs assets = overlay();
    std::vector<std::string> scenes = assets.list("scenes");
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), "scenes/beacon.json"), scenes.end())
        << "added by a mod";
    EXPECT_NE(std::find(scenes.begin(), scenes.end(), "scenes/cave.json"), scenes.end()) << "from assets/";

    std::vector<AssetFs::ModSummary> summary = assets.summarise();
    ASSERT_EQ(summary.size(), 2u);
    EXPECT_EQ(summary[0].replaces, std::vector<std::string>{"sprites/ship.bounds.json"});
    EXPECT_EQ(summary[0].adds, (std::vector<std::string>{"scenes/beacon.json", "sprites/beacon.bounds.json",
                                                         "sprites/beacon.png"}));
    EXPECT_EQ(summary[1].replaces, (std::vector<std::string>{"sprites/ship.bounds.json", "sprites/ship.png"}))
        << "B replaces A's ship bounds and assets/' ship picture";
    EXPECT_TRUE(summary[1].adds.empty());
}

TEST_F(ModOverlay, TheGamePlaysASceneAModAdds) {
    AssetFs assets = overlay();
    Game::Config config;
    config.scene = "scenes/beacon.json";
    config.reader = assets.reader();
    Result<Game> game = Game::create(config);
    ASSERT_TRUE(game.ok()) << game.error().message();
    const GameObject* beacon = nullptr;
    const GameObject* ship = nullptr;
    for (const GameObject& o : game->world().objects()) {
        if (o.name == "beacon") beacon = &o;
        if (o.name == "ship") ship = &o;
    }
    ASSERT_NE(beacon, nullptr);
    ASSERT_NE(ship, nullptr);
    EXPECT_EQ(game->lookOf(*beacon).sprite, "sprites/beacon.png");
    ASSERT_EQ(beacon->boundsOrEmpty().size(), 1u);
    EXPECT_EQ(beacon->boundsOrEmpty()[0].maxRadius(), 5) << "the mod's new bounds";
    EXPECT_EQ(ship->boundsOrEmpty()[0].maxRadius(), 9) << "the last mod's replacement";
    for (int t = 0; t < 120; ++t) game->tick(kFire);
    EXPECT_GT(game->score() + static_cast<int>(game->world().objects().size()), 0);
}

TEST_F(ModOverlay, TheExecutableListsModsAndDrawsTheirSprites) {
    Outcome r =
        runGame("--headless --mod mod-a --mod mod-b --scene beacon --ticks 10 --screenshot 8:shot.png");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.out.find("mod: mod-a (replaces 1 files, adds 3)"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("mod: mod-b (replaces 2 files, adds 0)"), std::string::npos) << r.out;
    EXPECT_LT(r.out.find("mod: mod-a"), r.out.find("mod: mod-b")) << "in command-line order";
    Result<RgbaImage> shot = loadPng((folder_ / "shot.png").string());
    ASSERT_TRUE(shot.ok()) << shot.error().message();
    // World (560, 300) is canvas (560, 60): the beacon a mod added. World (320, 180) is the ship,
    // drawn with the picture mod B put in its place (at tick 8 it is not blinking).
    EXPECT_EQ(shot->at(560, 60), kBeaconColor);
    EXPECT_EQ(shot->at(320, 180), kModShipColor);
}

TEST_F(ModOverlay, AnUnknownSceneNameListsTheScenesOfEveryLayer) {
    Outcome r = runGame("--headless --mod mod-a --scene nosuch --ticks 1");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("nosuch: no such scene file or scene name"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("beacon, cave"), std::string::npos) << r.err;
}

TEST_F(ModOverlay, AnInvalidModFileIsOneClearErrorNotACrash) {
    writeFile(modB() / "sprites/ship.bounds.json",
              "{\"format\": 1, \"radii\": [{\"samples\": [[0, -3]]}]}\n");
    Outcome r = runGame("--headless --mod mod-a --mod mod-b --scene beacon --ticks 1");
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("mod-b/sprites/ship.bounds.json:1:"), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("radius -3 is not positive"), std::string::npos) << r.err;
}

// The guide's example mod (assets/docs/example-mod) does what the guide says: the crystals scene
// plays, with the crystal's bounds on every crystal, and the mod's bullet replaces the game's.
TEST(ExampleMod, TheGuidesExampleModPlays) {
    const std::string mod = std::string(POLAR_ASSET_DIR) + "/docs/example-mod";
    AssetFs assets(POLAR_ASSET_DIR, {mod});
    std::vector<AssetFs::ModSummary> summary = assets.summarise();
    ASSERT_EQ(summary.size(), 1u);
    EXPECT_EQ(summary[0].replaces,
              (std::vector<std::string>{"sprites/bullet.bounds.json", "sprites/bullet.png"}));
    EXPECT_EQ(summary[0].adds,
              (std::vector<std::string>{"scenes/crystals.json", "sprites/crystal.bounds.json",
                                        "sprites/crystal.png"}));
    Game::Config config;
    config.scene = "scenes/crystals.json";
    config.reader = assets.reader();
    Result<Game> game = Game::create(config);
    ASSERT_TRUE(game.ok()) << game.error().message();
    int crystals = 0;
    for (const GameObject& o : game->world().objects()) {
        if (o.name.rfind("crystal-", 0) != 0) continue;
        ++crystals;
        EXPECT_EQ(game->lookOf(o).bounds, "sprites/crystal.bounds.json");
        ASSERT_EQ(o.boundsOrEmpty().size(), 1u);
        EXPECT_TRUE(o.has(kCollisions) && o.has(kGhost));
    }
    EXPECT_EQ(crystals, 3);
    // The mod's bullet is a 7 × 7 diamond: its outline reaches 4 px, the game's 5 × 5 one 2.1.
    bool shot = false;
    for (int t = 0; t < 60 && !shot; ++t) {
        game->tick(kFire);
        for (const GameObject& o : game->world().objects())
            if (game->kindOf(o.id) == Kind::Bullet) {
                EXPECT_GT(o.boundsOrEmpty().at(0).maxRadius(), 3.9);
                shot = true;
            }
    }
    EXPECT_TRUE(shot);
    // Hits with the crystals happen: they are obstacles, not decoration.
    int crystalHits = 0;
    for (int t = 0; t < 3000; ++t) {
        game->tick(t % 2 ? kFire : kTurnLeft);
        for (const PairReport& hit : game->world().hits()) {
            const GameObject& a = game->world().objects()[hit.a];
            const GameObject& b = game->world().objects()[hit.b];
            crystalHits += a.name.rfind("crystal-", 0) == 0 || b.name.rfind("crystal-", 0) == 0;
        }
    }
    EXPECT_GT(crystalHits, 0);
}

}  // namespace
}  // namespace polar::game
