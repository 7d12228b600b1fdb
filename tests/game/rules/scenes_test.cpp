#include <gtest/gtest.h>

#include <filesystem>
#include <set>

#include "files/assets.h"
#include "polar/step_stats.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

// Every scene the game ships, as logical paths, sorted.
std::vector<std::string> builtInScenes() {
    std::vector<std::string> scenes;
    for (const fs::directory_entry& entry : fs::directory_iterator(fs::path(POLAR_ASSET_DIR) / "scenes"))
        if (entry.path().extension() == ".json")
            scenes.push_back("scenes/" + entry.path().filename().string());
    std::sort(scenes.begin(), scenes.end());
    return scenes;
}

Result<Game> sceneGame(const std::string& scene, const AssetFs& assets, std::uint64_t seed = 5) {
    Game::Config config;
    config.scene = scene;
    config.reader = assets.reader();
    config.seed = seed;
    return Game::create(config);
}

// A game of `scene` played by the demo pilot for `ticks` ticks, with time per effect measured.
Game played(const std::string& scene, const AssetFs& assets, int ticks) {
    Result<Game> game = sceneGame(scene, assets);
    EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
    game->world().setTiming(true);
    Bot bot(11);
    for (int t = 0; t < ticks && !game->over(); ++t) game->tick(bot.decide(*game));
    return std::move(*game);
}

class ScenesTest : public ::testing::Test {
  protected:
    AssetFs assets_{POLAR_ASSET_DIR};
};

TEST_F(ScenesTest, AtLeastFourScenesEachWithItsOwnEffects) {
    std::vector<std::string> scenes = builtInScenes();
    ASSERT_GE(scenes.size(), 4u);
    std::set<Effects> sets;
    for (const std::string& scene : scenes) {
        Result<Game> game = sceneGame(scene, assets_);
        ASSERT_TRUE(game.ok()) << scene << ": " << game.error().message();
        EXPECT_TRUE(sets.insert(game->world().def().effects).second)
            << scene << " repeats another scene's effects";
    }
}

// The mission's promise, scene by scene: an effect a scene does not call for makes no pass, visits
// nothing, holds nothing and takes no time, over a few thousand ticks of play; the ones it calls
// for do run.
TEST_F(ScenesTest, AnAbsentEffectCostsNothingInEveryScene) {
    for (const std::string& scene : builtInScenes()) {
        Game game = played(scene, assets_, 2400);
        const StepStats& total = game.world().totalStats();
        for (Effect effect : kAllEffects) {
            const EffectStats& stats = total[effect];
            if (game.world().runs(effect)) {
                EXPECT_GT(stats.calls, 0u) << scene << ": " << effectName(effect) << " never ran";
            } else {
                EXPECT_TRUE(stats.idle()) << scene << ": absent " << effectName(effect) << " made "
                                          << stats.calls << " calls in " << stats.nanoseconds << " ns";
                EXPECT_EQ(stats.nanoseconds, 0u);
            }
        }
    }
}

TEST_F(ScenesTest, EverySceneIsPlayableAndScores) {
    for (const std::string& scene : builtInScenes()) {
        Game game = played(scene, assets_, 3600);
        EXPECT_GT(game.score(), 0) << scene;
        EXPECT_GE(game.wave(), 1) << scene;
    }
}

// In a scene whose edges wrap, nothing the game wraps is ever more than its own size past the field.
TEST_F(ScenesTest, WrapEdgesKeepThingsNearTheField) {
    for (const char* scene : {"scenes/field.json", "scenes/ghosts.json", "scenes/storm.json"}) {
        Result<Game> game = sceneGame(scene, assets_);
        ASSERT_TRUE(game.ok());
        ASSERT_EQ(game->rules().edges, SceneRules::Edges::Wrap);
        Vec2 field = game->rules().field;
        Bot bot(3);
        bool wrapped = false;
        for (int t = 0; t < 3000 && !game->over(); ++t) {
            game->tick(bot.decide(*game) | kThrust);
            for (const GameObject& o : game->world().objects()) {
                if (game->kindOf(o.id) == Kind::Comet) continue;
                double m = (o.boundsOrEmpty().empty() ? 4 : o.boundsOrEmpty().front().maxRadius()) + 1e-9;
                Vec2 p = o.transform.position();
                ASSERT_TRUE(p.x() >= -m && p.y() >= -m && p.x() <= field.x() + m && p.y() <= field.y() + m)
                    << scene << " tick " << t << ": " << o.name << " at " << p.transpose();
                wrapped = wrapped || p.x() < 0 || p.y() < 0 || p.x() > field.x() || p.y() > field.y();
            }
        }
        EXPECT_TRUE(wrapped) << scene << ": nothing ever went past an edge";
    }
}

TEST_F(ScenesTest, StormBulletsAreFastAndSweptByCcd) {
    Result<Game> game = sceneGame("scenes/storm.json", assets_);
    ASSERT_TRUE(game.ok());
    ASSERT_TRUE(game->rules().fastBullets);
    // Per tick a bullet moves farther than a small rock is wide: only a swept test can hit it.
    EXPECT_GT(game->bulletSpeed() / game->tuning().tickRate, 20.0);
    for (int t = 0; t < 20; ++t) game->tick(kFire);
    int bullets = 0;
    for (const GameObject& o : game->world().objects()) {
        if (game->kindOf(o.id) != Kind::Bullet) continue;
        ++bullets;
        EXPECT_TRUE(o.has(kFast));
    }
    EXPECT_GT(bullets, 0);
}

TEST_F(ScenesTest, TheCavePlaysByItsContainer) {
    Result<Game> game = sceneGame("scenes/cave.json", assets_);
    ASSERT_TRUE(game.ok());
    EXPECT_EQ(game->rules().edges, SceneRules::Edges::Container);
    EXPECT_FALSE(game->rules().fastBullets);
    EXPECT_EQ(game->bulletSpeed(), game->tuning().bulletSpeed);
}

SourceFile sceneText(const std::string& game) {
    return {"bad.json", "{\n  \"format\": 1,\n  \"game\": " + game + "\n}\n"};
}

TEST(SceneRulesTest, ABadGameBlockIsOneClearErrorWithItsPlace) {
    struct Case {
        const char* game;
        const char* what;
        const char* expected;
    };
    for (const Case& c : std::initializer_list<Case>{
             {"{\"edge\": \"wrap\"}", "unknown key \"edge\"", "edges"},
             {"{\"edges\": \"loop\"}", "unknown edges \"loop\"", "\"container\" or \"wrap\""},
             {"{\"bullets\": 3}", "", "\"plain\" or \"fast\""},
             {"{\"field\": [10, 360]}", "out of range", "from 64 to 4096"},
             {"{\"bullet_speed\": -1}", "out of range", "at most 5000"},
             {"{\"backdrop\": \"nebula\"}", "unknown backdrop \"nebula\"", "\"starfield\", \"fog\""},
             {"{\"backdrop\": 2}", "", "a backdrop: \"plain\""},
             {"[1]", "\"game\" is an array", "an object"}}) {
        Result<SceneRules> rules = parseSceneRules(sceneText(c.game));
        ASSERT_FALSE(rules.ok()) << c.game;
        std::string message = rules.error().message();
        EXPECT_EQ(message.rfind("bad.json:3:", 0), 0u) << message;
        EXPECT_NE(message.find(c.what), std::string::npos) << message;
        EXPECT_NE(message.find(c.expected), std::string::npos) << message;
    }
    Result<SceneRules> good = parseSceneRules(sceneText("{\"edges\": \"wrap\", \"bullets\": \"fast\"}"));
    ASSERT_TRUE(good.ok()) << good.error().message();
    EXPECT_EQ(good->edges, SceneRules::Edges::Wrap);
    EXPECT_TRUE(good->fastBullets);
    EXPECT_FALSE(good->backdrop);  // a file without the key (every file before it) still loads
    for (const char* name : {"plain", "starfield", "fog", "storm", "cavern"}) {
        Result<SceneRules> chosen =
            parseSceneRules(sceneText(std::string("{\"backdrop\": \"") + name + "\"}"));
        ASSERT_TRUE(chosen.ok()) << chosen.error().message();
        ASSERT_TRUE(chosen->backdrop);
        EXPECT_STREQ(backdropName(*chosen->backdrop), name);
    }
}

}  // namespace
}  // namespace polar::game
