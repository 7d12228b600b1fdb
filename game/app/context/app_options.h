#pragma once
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/input/input.h"

namespace polar::game {

struct FrameView;  // run/frame_view.h: what a windowed frame shows

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
    std::string
        script;  // --script FILE: the screens driven by the script's events (app/run/script.h), no window
    std::int64_t seek = -1;        // with --replay: start at this tick (-1: at the start)
    bool verify = false;           // with --replay: stop at the first checkpoint that differs
    bool allowIncomplete = false;  // with --verify: a replay without its end line passes (else exit 1)
    std::string data;  // --data DIR: the data folder (high scores, replays); headless then records there
    std::uint32_t threads = 0;                      // --threads N: the world step's threads (0: every core)
    std::optional<bool> fullscreen;                 // --fullscreen / --windowed: this run only, not saved
    std::optional<bool> integerScaling;             // --scale-mode integer|fit: this run only
    std::function<void(const FrameView&)> onFrame;  // called after each windowed frame is drawn
    // Asked before each windowed frame: a replay file to open in the theatre now (the web page's
    // file picker and drag and drop), or nothing.
    std::function<std::optional<std::string>()> replayToOpen;
    // Asked before each frame: the device the page sees in use (a touch screen's controls send
    // keys, so only the page can tell), or nothing. Once told, the hints follow the page alone.
    std::function<std::optional<Device>()> deviceOfPage;
};

}  // namespace polar::game
