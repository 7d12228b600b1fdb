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

// Six scenes or more: those without foes each with its own effects; those with foes (rules 3) each
// calling for its own foes or power-ups.
TEST_F(ScenesTest, AtLeastSixScenesEachWithItsOwnEffectsOrFoes) {
    std::vector<std::string> scenes = builtInScenes();
    ASSERT_GE(scenes.size(), 6u);
    std::set<Effects> sets;
    std::set<std::pair<int, int>> calls;
    int withFoes = 0;
    for (const std::string& scene : scenes) {
        Result<Game> game = sceneGame(scene, assets_);
        ASSERT_TRUE(game.ok()) << scene << ": " << game.error().message();
        if (game->arcade()) {
            ++withFoes;
            EXPECT_TRUE(calls.insert({game->rules().foes, game->rules().powerUps}).second)
                << scene << " calls for another scene's foes and power-ups";
        } else {
            EXPECT_TRUE(sets.insert(game->world().def().effects).second)
                << scene << " repeats another scene's effects";
        }
    }
    EXPECT_GE(withFoes, 2);
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

// Rules 3's keys: "foes", "powerups" (lists of known names, each once, kept in file order) and
// "accent" (three levels 0 to 255); anything else is refused at its place.
TEST(SceneRulesTest, FoesPowerUpsAndAccentAreReadOrRefusedAtTheirPlace) {
    Result<SceneRules> good = parseSceneRules(sceneText(
        R"({"foes": ["hunter", "saucer"], "powerups": ["barrier", "spread"], "accent": [0, 128, 255]})"));
    ASSERT_TRUE(good.ok()) << good.error().message();
    EXPECT_TRUE(good->callsFor(Foe::Hunter));
    EXPECT_TRUE(good->callsFor(Foe::Saucer));
    EXPECT_FALSE(good->callsFor(Foe::Mine));
    EXPECT_EQ(good->foeOrder, (std::vector<Foe>{Foe::Hunter, Foe::Saucer}));
    EXPECT_TRUE(good->callsFor(PowerUp::Barrier));
    EXPECT_TRUE(good->callsFor(PowerUp::Spread));
    EXPECT_FALSE(good->callsFor(PowerUp::Rapid));
    ASSERT_TRUE(good->accent);
    EXPECT_EQ((*good->accent)[2], 255);
    Result<SceneRules> none = parseSceneRules(sceneText("{}"));
    ASSERT_TRUE(none.ok());
    EXPECT_EQ(none->foes, 0);
    EXPECT_EQ(none->powerUps, 0);
    EXPECT_FALSE(none->accent);
    struct Case {
        const char* game;
        const char* at;
        const char* what;
    };
    for (const Case& c : std::initializer_list<Case>{
             {R"({"foes": ["saucer", "ufo"]})", "bad.json:3:31:",
              R"(unknown foes "ufo"; expected a list of foes: "saucer", "mine" or "hunter")"},
             {R"({"foes": "saucer"})", "bad.json:3:20:", "expected a list of foes"},
             {R"({"foes": ["mine", "mine"]})", "bad.json:3:29:", R"("mine" is listed twice)"},
             {R"({"powerups": ["bomb"]})", "bad.json:3:25:",
              R"(unknown powerups "bomb"; expected a list of powerups: "spread", "rapid" or "barrier")"},
             {R"({"accent": [1, 2]})", "bad.json:3:22:", "2 numbers"},
             {R"({"accent": [1, 2, 256]})", "bad.json:3:29:", "not a colour level"},
             {R"({"accent": [1, 2.5, 3]})", "bad.json:3:26:", "not a colour level"}}) {
        Result<SceneRules> rules = parseSceneRules(sceneText(c.game));
        ASSERT_FALSE(rules.ok()) << c.game;
        const std::string message = rules.error().message();
        EXPECT_EQ(message.rfind(c.at, 0), 0u) << message;
        EXPECT_NE(message.find(c.what), std::string::npos) << message;
    }
}

// The game block's ranges (assets/README.md, "Scenes"): a field side from 64 to 4096, a bullet
// speed above 0 up to 5000, a bullet life above 0 up to 10; each end is accepted, one step past it
// refused at the value.
TEST(SceneRulesTest, RangesHoldAtBothEnds) {
    for (const char* good :
         {R"({"edges": "wrap", "field": [64, 4096]})", R"({"field": [4096, 64]})",
          R"({"bullet_speed": 5000, "bullet_life": 10})", R"({"bullet_speed": 1e-9, "bullet_life": 1e-9})",
          R"({"edges": "container"})", R"({"bullets": "plain"})"}) {
        Result<SceneRules> rules = parseSceneRules(sceneText(good));
        EXPECT_TRUE(rules.ok()) << good << ": " << rules.error().message();
    }
    Result<SceneRules> edges = parseSceneRules(sceneText(R"({"field": [64, 4096], "bullet_speed": 5000})"));
    ASSERT_TRUE(edges.ok());
    EXPECT_EQ(edges->field, Vec2(64, 4096));
    EXPECT_EQ(edges->bulletSpeed, 5000.0);
    for (const char* bad :
         {R"({"field": [63.9, 360]})", R"({"field": [640, 63.9]})", R"({"field": [4096.5, 360]})",
          R"({"field": [640, 4096.5]})", R"({"bullet_speed": 0})", R"({"bullet_speed": 5000.5})",
          R"({"bullet_life": 0})", R"({"bullet_life": 10.001})"}) {
        Result<SceneRules> rules = parseSceneRules(sceneText(bad));
        ASSERT_FALSE(rules.ok()) << bad;
        EXPECT_EQ(rules.error().message().rfind("bad.json:3:", 0), 0u) << rules.error().message();
        EXPECT_NE(rules.error().message().find("out of range"), std::string::npos) << rules.error().message();
    }
}

// What the game needs of a scene (assets/README.md, "Scenes"): an object named "ship"; unless the
// edges wrap, a container, the first of which is the arena; fast bullets only with "ccd".
class SceneNeedsTest : public ::testing::Test {
  protected:
    Result<Game> withScene(const std::string& effects, const std::string& game, const std::string& objects) {
        const std::string text = "{\"format\": 1, \"effects\": [" + effects + "]" +
                                 (game.empty() ? "" : ", \"game\": " + game) + ", \"objects\": [" + objects +
                                 "]}";
        Game::Config config;
        config.scene = "scenes/made.json";
        config.reader = [&, text](const std::string& path) -> std::optional<SourceFile> {
            if (path == "scenes/made.json") return SourceFile{path, text};
            return assets_.reader()(path);
        };
        return Game::create(config);
    }
    static std::string object(const std::string& name, const std::string& flags, int x = 320) {
        return "{\"name\": \"" + name +
               "\", \"bounds\": {\"radii\": [{\"samples\": [[0, 150]]}]}, \"position\": [" +
               std::to_string(x) + ", 180], \"flags\": [" + flags + "]}";
    }
    static std::string ship() {
        return "{\"name\": \"ship\", \"bounds\": \"../sprites/ship.bounds.json\", \"position\": [320, 180], "
               "\"flags\": [\"physics\", \"collisions\"]}";
    }
    AssetFs assets_{POLAR_ASSET_DIR};
};

TEST_F(SceneNeedsTest, AShipAndAnArenaUnlessTheEdgesWrap) {
    const std::string effects = R"("physics", "collisions", "response", "containers")";
    Result<Game> noShip = withScene(effects, "", object("cave", R"("collisions", "container")"));
    ASSERT_FALSE(noShip.ok());
    EXPECT_EQ(noShip.error().message(),
              "scenes/made.json: the scene has no object named \"ship\"; expected an object named \"ship\"");
    Result<Game> noArena = withScene(effects, "", ship());
    ASSERT_FALSE(noArena.ok());
    EXPECT_EQ(noArena.error().message().rfind("scenes/made.json: the scene has no container object", 0), 0u)
        << noArena.error().message();
    EXPECT_TRUE(withScene(R"("physics", "collisions")", R"({"edges": "wrap"})", ship()).ok())
        << "an open field needs no arena";

    // Two containers: the first in the file is the arena, the second is scenery.
    Result<Game> two = withScene(effects, "",
                                 object("outer", R"("collisions", "container")", 300) + ", " +
                                     object("inner", R"("collisions", "container")", 340) + ", " + ship());
    ASSERT_TRUE(two.ok()) << two.error().message();
    const GameObject* outer = two->world().findByName("outer");
    const GameObject* inner = two->world().findByName("inner");
    ASSERT_TRUE(outer && inner);
    EXPECT_EQ(two->kindOf(outer->id), Kind::Arena);
    EXPECT_EQ(two->kindOf(inner->id), Kind::Scenery);
    EXPECT_EQ(two->kindOf(two->world().findByName("ship")->id), Kind::Ship);
}

TEST_F(SceneNeedsTest, FastBulletsNeedCcd) {
    const std::string objects = object("cave", R"("collisions", "container")") + ", " + ship();
    Result<Game> plain =
        withScene(R"("physics", "collisions", "containers")", R"({"bullets": "fast"})", objects);
    ASSERT_FALSE(plain.ok());
    EXPECT_EQ(
        plain.error().message(),
        "scenes/made.json: the game's \"bullets\": \"fast\" needs the effect \"ccd\"; expected \"ccd\" in "
        "\"effects\", or plain bullets");
    Result<Game> swept =
        withScene(R"("physics", "collisions", "containers", "ccd")", R"({"bullets": "fast"})", objects);
    ASSERT_TRUE(swept.ok()) << swept.error().message();
    EXPECT_TRUE(swept->rules().fastBullets);
}

}  // namespace
}  // namespace polar::game
