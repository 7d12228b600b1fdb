#pragma once
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "app/app.h"
#include "app/app_context.h"
#include "app/audio.h"
#include "app/data_folder.h"
#include "app/draw.h"
#include "app/input.h"
#include "files/assets.h"
#include "files/high_scores.h"
#include "files/hot_reload.h"
#include "polar/render/canvas.h"
#include "replay/replay_recorder.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::platform {
class Window;
}

namespace polar::game {

class AppSettings;

// What the screens share while the game runs in a window (or under a script): the files, the
// player's data, the devices, the attract demo behind the title and the player's game.
//
// Why one object? A screen is a small room; what outlives a room (the high scores, the recorder,
// the game a pause menu pauses) is kept here, so that opening or closing a screen never loses it.
// The Session also holds the few verbs several screens need, so each is written once: start a
// game, end it, step a game, draw a game.
class Session {
  public:
    // What a session runs on; everything outlives it.
    struct Parts {
        AppContext& context;
        const DataFolder& data;
        HighScores& scores;
        GameRecorder& recorder;
        Audio& audio;
        Input& input;
        platform::Window* window = nullptr;  // null when a script drives the game
    };
    Session(Parts parts, std::string scenePath);

    AppContext& context;
    const AppOptions& options;
    AssetFs& assets;
    SpriteCache& sprites;
    TaskSystem& tasks;
    HotReload& hotReload;
    const DataFolder& data;
    HighScores& scores;
    GameRecorder& recorder;
    Audio& audio;
    Input& input;
    platform::Window* window;
    AppSettings* settings = nullptr;  // the player's settings (windowed runs; null under a script)

    std::string scenePath;        // the scene the next game plays (--scene, or the Scenes screen)
    std::optional<Game> attract;  // the demo under the title, played by `bot`
    std::optional<Game> game;     // the player's game, from Play until the title
    Bot bot{7};
    Interpolation interpolation;
    Particles particles;
    bool debug = false;          // the debug overlay (F1)
    double fps = 60;             // frames a second, smoothed
    bool showFrameTime = false;  // the frame-time line in the top right corner (Options)
    SeekTiming lastSeek;         // the theatre's last seek (FrameView reports it)

    // A game of `scene` (default: scenePath) with `seed` on the session's threads, or the loader's error.
    Result<Game> newGame(std::uint64_t seed, const std::string& scene = {}) const;
    // The seed of a new game: --seed, else one from the clock (a script's runs: 1, so they repeat).
    std::uint64_t freshSeed() const;
    // Starts the player's game on scenePath and records it; false (with the reason on stderr and
    // on screen) when the scene cannot be loaded.
    bool startGame();
    // Ends the player's game, finishing its recordings with `reason` ("quit", "restart").
    void endGame(std::string_view reason);
    // A new attract demo when there is none or the last one is over.
    void renewAttract();
    // One tick of the attract demo with its pilot (the screens over it call this from tick()).
    void tickAttract();
    // Ticks `game` with `actions`, keeping the interpolation, the statistics and the particles.
    void advance(Game& game, Actions actions);
    // Draws `game` with the particles and, with `hud`, its score line (the whole canvas); it is
    // then the game shown.
    void drawWorld(render::Canvas& canvas, const Game& game, double alpha, bool hud);
    // The game the frame shows (the debug panel describes it; FrameView reports it): the last one
    // drawn, or null.
    const Game* shown = nullptr;

    // A line for the player, shown for a few seconds in the notice corner (overlay_layout.h) and
    // printed on stderr: a scene that did not load, a recording that stopped.
    void tell(std::string message);
    const std::string& notice() const { return notice_; }
    // True while the notice is shown (for kNoticeTicks after it was told).
    bool noticeFresh() const;
    static constexpr std::uint64_t kNoticeTicks = 300;  // 5 s
    // Counts the loop's ticks (the notice clock).
    void countTick() { ++ticks_; }

  private:
    std::string notice_;
    std::uint64_t ticks_ = 0, noticeAt_ = 0;
};

}  // namespace polar::game
