// The scenes' backdrops: each built-in scene looks like no other, a backdrop never feeds the rules,
// the storm's lightning follows the player's flashes, and a scene file may choose its backdrop.
#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>

#include "app/hud/backdrop.h"
#include "app/hud/game_drawing.h"
#include "app/input/audio.h"
#include "files/assets.h"
#include "rules/bot.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

const std::array<const char*, 4> kScenes = {"scenes/cave.json", "scenes/field.json", "scenes/ghosts.json",
                                            "scenes/storm.json"};

Game::Config configFor(const std::string& scene, const FileReader& reader) {
    Game::Config config;
    config.scene = scene;
    config.reader = reader;
    config.seed = 5;
    return config;
}

// A game of `scene` played by the demo pilot, with its effects, drawn after every tick.
struct Played {
    Game game;
    Particles particles;
    Bot bot{11};

    void tick() {
        game.tick(bot.decide(game));
        particles.spawnFor(game.events(), game.tickCount());
        particles.tick(1.0 / 60.0);
    }
};

Played start(const std::string& scene, const AssetFs& assets) {
    Result<Game> game = Game::create(configFor(scene, assets.reader()));
    EXPECT_TRUE(game.ok()) << (game.ok() ? "" : game.error().message());
    return Played{std::move(*game), {}, Bot(11)};
}

// The frame as a 16 × 9 grid of 40 × 40 blocks, each the mean of its pixels' channels: what two
// screenshots "look like" from across the room.
using Blocks = std::array<double, 16 * 9 * 3>;
Blocks blocksOf(const render::Canvas& canvas) {
    Blocks blocks{};
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) {
            const render::Color c = canvas.pixel(x, y);
            const std::size_t b = (static_cast<std::size_t>(y / 40) * 16 + x / 40) * 3;
            blocks[b] += c.r / 1600.0, blocks[b + 1] += c.g / 1600.0, blocks[b + 2] += c.b / 1600.0;
        }
    return blocks;
}
// The mean absolute difference of two frames' blocks, in channel levels (0 … 255).
double apart(const Blocks& a, const Blocks& b) {
    double sum = 0;
    for (std::size_t i = 0; i < a.size(); ++i) sum += std::abs(a[i] - b[i]);
    return sum / a.size();
}

class Backdrops : public ::testing::Test {
  protected:
    AssetFs assets_{POLAR_ASSET_DIR};
    SpriteCache sprites_{assets_};
};

// Every built-in scene's frame at the same tick of the same wave, drawn with every effect as the
// game draws it, is a clear margin apart from every other's. With the backdrops off, field, ghosts
// and storm are the same dark void, and the same measure finds two of them within the margin: it
// is the backdrops that tell the scenes apart.
TEST_F(Backdrops, NoTwoScenesLookAlikeInTheSameWave) {
    constexpr double kMargin = 8;  // channel levels, on average over the screen
    std::vector<Blocks> with, without;
    for (const char* scene : kScenes) {
        Played played = start(scene, assets_);
        for (int t = 0; t < 300; ++t) played.tick();
        ASSERT_EQ(played.game.wave(), 1) << scene;
        render::Canvas canvas(kScreenWidth, kScreenHeight);
        DrawOptions options;
        drawGame(canvas, played.game, sprites_, Interpolation{}, played.particles, 1.0, options);
        with.push_back(blocksOf(canvas));
        options.backdrop = false;
        drawGame(canvas, played.game, sprites_, Interpolation{}, played.particles, 1.0, options);
        without.push_back(blocksOf(canvas));
    }
    double closestWithout = 1e9, closestWith = 1e9;
    for (std::size_t i = 0; i < kScenes.size(); ++i)
        for (std::size_t j = i + 1; j < kScenes.size(); ++j) {
            closestWith = std::min(closestWith, apart(with[i], with[j]));
            EXPECT_GT(apart(with[i], with[j]), kMargin)
                << kScenes[i] << " and " << kScenes[j] << " look alike (" << apart(with[i], with[j]) << ")";
            closestWithout = std::min(closestWithout, apart(without[i], without[j]));
        }
    std::printf("closest two scenes: %.1f channel levels apart with backdrops, %.1f without (margin %.0f)\n",
                closestWith, closestWithout, kMargin);
    EXPECT_LT(closestWithout, kMargin) << "the measure tells plain scenes apart too, so it proves nothing";
}

// Presentation never feeds the rules: two games of each scene, one drawn with its backdrop after
// every tick and one without, hash the same tick for tick, while their pictures differ.
TEST_F(Backdrops, TheStateHashIsTheSameWithBackdropsOnOrOff) {
    for (const char* scene : kScenes) {
        Played on = start(scene, assets_), off = start(scene, assets_);
        render::Canvas a(kScreenWidth, kScreenHeight), b(kScreenWidth, kScreenHeight);
        int differing = 0;
        for (int t = 0; t < 600; ++t) {
            on.tick();
            off.tick();
            DrawOptions options;
            drawGame(a, on.game, sprites_, Interpolation{}, on.particles, 0.5, options);
            options.backdrop = false;
            drawGame(b, off.game, sprites_, Interpolation{}, off.particles, 0.5, options);
            ASSERT_EQ(on.game.hash(), off.game.hash()) << scene << ", tick " << t;
            differing += a.pixel(320, 180) != b.pixel(320, 180) || a.pixel(17, 300) != b.pixel(17, 300);
        }
        EXPECT_GT(differing, 300) << scene << ": the backdrop was not drawn";
    }
}

// The same for rules 3's foe scenes, with every effect: one game drawn with its backdrop, particles,
// shake and flashes and heard through the mixer after every tick, one only ticked, hash the same.
TEST_F(Backdrops, TheStateHashIsTheSameWithEveryEffectOnOrOffAmongFoes) {
    for (const char* scene : {"scenes/minefield.json", "scenes/saucers.json"}) {
        Played on = start(scene, assets_);
        Result<Game> off = Game::create(configFor(scene, assets_.reader()));
        ASSERT_TRUE(off.ok());
        Bot offBot(11);
        std::unique_ptr<Audio> audio = Audio::offline(8000);
        render::Canvas canvas(kScreenWidth, kScreenHeight);
        int foes = 0;
        for (int t = 0; t < 1500; ++t) {
            on.tick();
            audio->play(on.game.events());
            drawGame(canvas, on.game, sprites_, Interpolation{}, on.particles, 0.5, DrawOptions{});
            off->tick(offBot.decide(*off));
            for (const GameEvent& e : on.game.events()) foes += e.type == GameEvent::FoeIn;
            ASSERT_EQ(on.game.hash(), off->hash()) << scene << ", tick " << t;
        }
        EXPECT_GT(foes, 0) << scene;
    }
}

// Each built-in scene has its own backdrop and HUD accent, chosen by its name; a scene file's
// "backdrop" key chooses for itself, and any other scene keeps the plain look.
TEST_F(Backdrops, ASceneChoosesItsBackdropByItsKeyOrItsName) {
    std::vector<Backdrop> seen;
    for (const char* scene : kScenes) {
        Result<Game> game = Game::create(configFor(scene, assets_.reader()));
        ASSERT_TRUE(game.ok()) << game.error().message();
        const Backdrop backdrop = backdropOf(*game);
        EXPECT_NE(backdrop, Backdrop::Plain) << scene;
        for (Backdrop other : seen) {
            EXPECT_NE(backdrop, other) << scene;
            EXPECT_NE(lookFor(backdrop).accent, lookFor(other).accent) << scene;
        }
        seen.push_back(backdrop);
    }
    const FileReader base = assets_.reader();
    auto withScene = [&](const std::string& game) -> FileReader {
        return [base, game](const std::string& path) -> std::optional<SourceFile> {
            if (path != "scenes/mine.json") return base(path);
            std::optional<SourceFile> field = base("scenes/field.json");
            std::string text = field->text;
            const std::string block = "\"game\": {";
            text.replace(text.find(block), block.size(), block + game);
            return SourceFile{path, text};
        };
    };
    Result<Game> fog = Game::create(configFor("scenes/mine.json", withScene("\"backdrop\": \"fog\", ")));
    ASSERT_TRUE(fog.ok()) << fog.error().message();
    EXPECT_EQ(backdropOf(*fog), Backdrop::Fog);
    Result<Game> plain = Game::create(configFor("scenes/mine.json", withScene("")));
    ASSERT_TRUE(plain.ok()) << plain.error().message();
    EXPECT_EQ(backdropOf(*plain), Backdrop::Plain);
    Result<Game> bad = Game::create(configFor("scenes/mine.json", withScene("\"backdrop\": \"lava\", ")));
    ASSERT_FALSE(bad.ok());
    EXPECT_NE(bad.error().message().find("unknown backdrop \"lava\""), std::string::npos)
        << bad.error().message();
}

double brightness(const render::Canvas& canvas) {
    double sum = 0;
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) {
            const render::Color c = canvas.pixel(x, y);
            sum += c.r + c.g + c.b;
        }
    return sum;
}

render::Canvas stormAt(std::uint64_t seed, std::uint64_t tick, int flashes) {
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    render::DrawList list;
    drawBackdrop(list, canvas.width(), canvas.height(), Backdrop::Storm, seed, tick, 0,
                 EffectLevels{100, flashes});
    list.draw(canvas);
    return canvas;
}

// The storm strikes every few seconds; its lightning is as bright as the player's flashes allow,
// and with flashes off the sky is exactly the unlit one (the rain and clouds go on).
TEST(BackdropLightning, StrikesEveryFewSecondsAndFollowsTheFlashesOption) {
    int strikes = 0;
    std::uint64_t lit = 0;
    bool wasDark = true;
    for (std::uint64_t t = 0; t < 60 * 60; ++t) {
        const double light = lightningAt(5, t, 0);
        ASSERT_GE(light, 0);
        ASSERT_LE(light, 1);
        if (light > 0 && wasDark) ++strikes;
        if (light >= 0.99 && lit == 0) lit = t;
        wasDark = light == 0;
    }
    EXPECT_GE(strikes, 6);
    EXPECT_LE(strikes, 20);
    ASSERT_NE(lit, 0u);
    std::uint64_t darkSeed = 6;
    while (lightningAt(darkSeed, lit, 0) > 0) ++darkSeed;

    const double full = brightness(stormAt(5, lit, 100));
    const double reduced = brightness(stormAt(5, lit, 40));
    const double off = brightness(stormAt(5, lit, 0));
    EXPECT_GT(full, reduced * 1.05);
    EXPECT_GT(reduced, off * 1.05);
    const render::Canvas offPicture = stormAt(5, lit, 0), unlit = stormAt(darkSeed, lit, 100);
    for (int y = 0; y < unlit.height(); ++y)
        for (int x = 0; x < unlit.width(); ++x)
            ASSERT_EQ(offPicture.pixel(x, y), unlit.pixel(x, y)) << x << ", " << y;
}

}  // namespace
}  // namespace polar::game
