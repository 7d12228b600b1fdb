// polarcade in a web page: the same game as the desktop's, its arguments from the page's URL
// (?lives=1&seed=5 → --lives 1 --seed 5), plus two hooks the browser test calls.
#include <emscripten.h>

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/hud/game_drawing.h"
#include "app/run/app.h"
#include "files/assets.h"
#include "files/high_scores.h"
#include "plain_flags.h"
#include "polar/platform/window.h"
#include "replay/replay.h"
#include "rules/game.h"

namespace {

std::string probe = "{}";                       // the last frame, as polar_web_probe returns it
std::optional<std::string> replayToOpen;        // polar_web_open_replay's file, until the next frame
std::optional<polar::game::Device> pageDevice;  // polar_web_device's, from the page's first word

void escapeInto(std::string& out, const std::string& text) {
    for (char c : text) {
        if (c == '"' || c == '\\') out += '\\';
        if (static_cast<unsigned char>(c) >= 0x20) out += c;
    }
}

// The frame in a few numbers: the screen, the shown game's tick, score and lives, the ship's
// position (null while it waits to respawn) and heading in radians, the number of bullets in flight, the high
// scores, and the theatre's last seek (its parts in milliseconds).
void observe(const polar::game::FrameView& view) {
    using polar::game::Kind;
    const polar::game::Game& game = view.game;
    std::string out = "{\"screen\":\"" + std::string(view.screen) +
                      "\",\"tick\":" + std::to_string(game.tickCount()) +
                      ",\"score\":" + std::to_string(game.score()) +
                      ",\"lives\":" + std::to_string(game.lives()) + ",\"ship\":";
    const polar::GameObject* ship = game.shipId() ? game.world().find(game.shipId()) : nullptr;
    if (ship) {
        char xy[120];
        std::snprintf(xy, sizeof xy, "[%.17g,%.17g],\"heading\":%.17g", ship->transform.position().x(),
                      ship->transform.position().y(), ship->transform.rotation());
        out += xy;
    } else {
        out += "null";
    }
    int bullets = 0;
    for (const polar::GameObject& object : game.world().objects())
        if (game.kindOf(object.id) == Kind::Bullet) ++bullets;
    out += ",\"bullets\":" + std::to_string(bullets) + ",\"highScores\":[";
    bool first = true;
    for (const polar::game::HighScores::Entry& e : view.scores.entries()) {
        out += first ? "{\"name\":\"" : ",{\"name\":\"";
        escapeInto(out, e.name);
        out += "\",\"score\":" + std::to_string(e.score) + "}";
        first = false;
    }
    char seek[200];
    std::snprintf(seek, sizeof seek,
                  "],\"seek\":{\"seeks\":%llu,\"ticks\":%llu,\"restoreMs\":%.4f,\"steppingMs\":%.4f,"
                  "\"drawingMs\":%.4f}",
                  static_cast<unsigned long long>(view.seek.seeks),
                  static_cast<unsigned long long>(view.seek.ticks), view.seek.restoreMs, view.seek.steppingMs,
                  view.seek.drawingMs);
    probe = out + seek + "}";
}

}  // namespace

extern "C" {

// The last frame's numbers as JSON (see observe).
EMSCRIPTEN_KEEPALIVE const char* polar_web_probe() {
    return probe.c_str();
}

// The device the page sees in use: 0 a keyboard, 1 a game controller, 2 a touch screen. The game's
// hints name its controls from then on.
EMSCRIPTEN_KEEPALIVE void polar_web_device(int device) {
    using polar::game::Device;
    pageDevice = device == 2 ? Device::Touch : device == 1 ? Device::Gamepad : Device::Keyboard;
}

// Opens the replay file at `path` (in the page's file system: web_runtime.js writes a file the
// player picked or dropped there) in the theatre, at the next frame.
EMSCRIPTEN_KEEPALIVE void polar_web_open_replay(const char* path) {
    replayToOpen = path;
}

// Stops the game's frames, plays the replay at `path` to tick `tick` and shows that frame on the
// canvas, drawn as the replay verifier draws its screenshots (alpha 1, no overlay). Returns 0, or
// 1 with the error on stderr (the console).
EMSCRIPTEN_KEEPALIVE int polar_web_show_replay(const char* path, int tick) {
    using namespace polar::game;
    emscripten_pause_main_loop();
    polar::Result<Replay> replay = readReplay(path);
    if (!replay) {
        std::fprintf(stderr, "%s\n", replay.error().message().c_str());
        return 1;
    }
    polar::Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "%s\n", root.error().message().c_str());
        return 1;
    }
    AssetFs assets(*root, {});
    polar::Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
    if (!player) {
        std::fprintf(stderr, "%s\n", player.error().message().c_str());
        return 1;
    }
    SpriteCache sprites(assets);
    Particles particles;
    while (!player->done() && player->game().tickCount() < static_cast<std::uint64_t>(tick)) {
        if (std::optional<Desync> desync = player->step()) {
            std::fprintf(stderr, "%s\n", describe(*desync, path).c_str());
            return 1;
        }
        particles.spawnFor(player->game().events(), player->game().tickCount());
        particles.tick(1.0 / replay->header.tuning.tickRate);
    }
    polar::render::Canvas canvas(kScreenWidth, kScreenHeight);
    drawGame(canvas, player->game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
    auto window = polar::platform::Window::open({"Polarcade", kScreenWidth, kScreenHeight, 1, false});
    if (!window) return 1;
    (*window)->present(canvas);
    return 0;
}
}

int main(int argc, char** argv) {
    polar::game::AppOptions options;
    // The page's address gives the arguments (web_runtime.js: ?lives=1&seed=5&mute). Read without
    // CLI11, which would be a seventh of the page's code (plain_flags.h).
    polar::cli::PlainFlags flags;
    bool seedGiven = false, livesGiven = false;
    std::uint64_t seed = 0;
    int lives = 0;
    flags.text("--scene", options.scene);
    flags.number("--seed", seed, {}, &seedGiven);
    flags.number("--lives", lives, {1, 99}, &livesGiven);
    flags.flag("--mute", options.mute);
    flags.flag("--show-bounds", options.showBounds);
    if (std::optional<std::string> problem = flags.parse(std::vector<std::string>(argv + 1, argv + argc))) {
        std::fprintf(stderr, "polarcade: %s\n", problem->c_str());
        return 2;
    }
    if (seedGiven) options.seed = seed;
    if (livesGiven) options.lives = lives;
    options.onFrame = observe;
    options.replayToOpen = [] { return std::exchange(replayToOpen, std::nullopt); };
    options.deviceOfPage = [] { return pageDevice; };
    return polar::game::runApp(std::move(options));
}
