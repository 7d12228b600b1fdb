#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace polar::game {

class Game;
class HighScores;

// What a windowed frame shows, for an observer (the web page's test hooks).
// How the theatre's last seek went, for observers (the browser test measures seeks in the page).
struct SeekTiming {
    std::uint64_t seeks = 0;                              // seeks so far; the figures are the last one's
    std::uint64_t ticks = 0;                              // ticks stepped after the restore
    double restoreMs = 0, steppingMs = 0, drawingMs = 0;  // drawing: the first frame after it
};

struct FrameView {
    const Game& game;    // the game on screen: the attract demo under the title, else the player's
    const char* screen;  // the screen on top: "title", "playing", "paused", "game-over", "name-entry", …
    const HighScores& scores;
    const SeekTiming& seek;
};

// Everything the command line can ask of the game.
struct AppOptions {
    bool headless = false;
    std::int64_t ticks = -1;  // headless: how many ticks to run (-1: the default for the mode)
    std::vector<std::pair<std::uint64_t, std::string>> screenshots;  // after tick N, save FILE
    std::string scene = "cave";
    std::optional<std::uint64_t> seed;
    std::optional<int> lives;  // --lives N: the ship's lives at the start instead of the default
    std::vector<std::string> mods;
    bool stats = false;
    bool showBounds = false;  // start with the debug overlay (F1) on; headless screenshots show it too
    bool mute = false;
    std::string record;  // --record FILE
    std::string replay;  // --replay FILE
    std::string script;  // --script FILE: the screens driven by the script's events (app/script.h), no window
    std::int64_t seek = -1;  // with --replay: start at this tick (-1: at the start)
    bool verify = false;     // with --replay: stop at the first checkpoint that differs
    std::string data;  // --data DIR: the data folder (high scores, replays); headless then records there
    std::uint32_t threads = 0;                      // --threads N: the world step's threads (0: every core)
    std::optional<bool> fullscreen;                 // --fullscreen / --windowed: this run only, not saved
    std::optional<bool> integerScaling;             // --scale-mode integer|fit: this run only
    std::function<void(const FrameView&)> onFrame;  // called after each windowed frame is drawn
    // Asked before each windowed frame: a replay file to open in the theatre now (the web page's
    // file picker and drag and drop), or nothing.
    std::function<std::optional<std::string>()> replayToOpen;
};

// The environment variable that names the data folder instead of the platform's per-user folder.
inline constexpr const char* kDataFolderVariable = "POLARCADE_DATA";

// The exit code of a headless run stopped by SIGINT or SIGTERM (128 + SIGINT, as shells report it)
// after it finished its recording.
inline constexpr int kInterruptedExitCode = 130;

// Runs the game as the options say; returns the process exit code.
int runApp(AppOptions options);

}  // namespace polar::game
