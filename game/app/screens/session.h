#pragma once
#include "app/context/app_context.h"
#include "app/hud/game_drawing.h"
#include "app/hud/notice.h"
#include "app/input/audio.h"
#include "app/input/input.h"
#include "app/input/settings.h"
#include "app/screens/games.h"
#include "app/theatre/seek_timing.h"
#include "files/high_scores.h"
#include "polar/render/canvas.h"
#include "replay/replay_recorder.h"
#include "rules/game.h"

namespace polar::platform {
class Window;
}

namespace polar::game {

class AppSettings;

// What the screens share while the game runs in a window (or under a script): the run's context,
// the player's high scores and recorder, the devices, the games, the notice and the view's flags.
// Each is named once: what the context holds (the options, the files, the threads, the sprites)
// is reached through `context`, never through a second name.
//
// Why one object? A screen is a small room; what outlives a room (the high scores, the recorder,
// the game a pause menu pauses) is kept here, so that opening or closing a screen never loses it.
class Session {
  public:
    // What a session runs on; everything outlives it.
    struct Parts {
        AppContext& context;
        HighScores& scores;
        GameRecorder& recorder;
        Audio& audio;
        Input& input;
        platform::Window* window = nullptr;  // null when a script drives the game
    };
    Session(Parts parts, std::string scenePath);

    AppContext& context;  // the options, the files, the threads, the sprites, the canvas
    HighScores& scores;
    GameRecorder& recorder;
    Audio& audio;
    Input& input;
    platform::Window* window;
    AppSettings* settings = nullptr;  // the player's settings (windowed runs; null under a script)

    Notice notice;  // the line in the notice corner
    Games games;    // the attract demo and the player's game

    bool debug = false;          // the debug overlay (F1)
    double fps = 60;             // frames a second, smoothed
    Settings preferences;        // the settings in force, as the Options screen last applied them
    bool showFrameTime = false;  // the frame-time line in the top right corner (Options)
    EffectLevels effects;        // the screen's shake and the flashes (Options)
    bool holdFire = false;       // fire pressed once fires until pressed again (Options)
    SeekTiming lastSeek;         // the theatre's last seek (FrameView reports it)

    // Takes the player's settings that the session applies itself: the frame time, the effects'
    // levels, hold fire and the next game's speed (the devices' are AppSettings' business).
    void follow(const Settings& settings);
    // Draws `game` with the games' particles and, with `hud`, its score line (the whole canvas).
    // It writes nothing back: the screen says which game it shows (Screen::shownGame).
    void drawWorld(render::Canvas& canvas, const Game& game, double alpha, bool hud);
};

}  // namespace polar::game
