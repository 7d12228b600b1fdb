#pragma once
#include <optional>
#include <string>

#include "app/input/bindings.h"
#include "polar/atomic_file.h"
#include "polar/error.h"

namespace polar::game {

// How the canvas is scaled into the window: by whole pixels only (borders where the window is not a
// multiple of the canvas), or as large as fits (Window::fit's rule: whole pixels when they fill most
// of the window, else any factor).
enum class ScaleMode : std::uint8_t { Integer, Fit };

// Everything the player can set, with its defaults: one struct, kept as settings.json in the data
// folder.
//
// Why a struct of plain values? The options screen edits one of these, the app applies it, and the
// file is its mirror: {"format": 1, "master_volume": 80, …, "screen_shake": 100, "flashes": 100,
// "hold_fire": false, "game_speed": 100, "keys": {"fire": ["space"]}, "pad": {"fire": ["a"]}}. Volumes are
// whole percents 0–100; a window position that is absent lets the desktop place the window. Command-line
// flags change a copy for one run and never reach the file.
struct Settings {
    int masterVolume = 80;
    int effectsVolume = 100;
    int musicVolume = 60;
    bool mute = false;
    bool fullscreen = false;
    int windowWidth = 1280;  // the windowed size in pixels
    int windowHeight = 720;
    std::optional<int> windowX, windowY;  // the windowed position; nothing: wherever the desktop puts it
    ScaleMode scaleMode = ScaleMode::Fit;
    bool showFrameTime = false;
    // Less motion, fewer flashes: the screen's shake and the flashes, in percent of full (0, 50, 100).
    int screenShake = 100;
    int flashes = 100;
    // Fire pressed once keeps firing until pressed again (for a player who cannot hold a key).
    bool holdFire = false;
    // The game-speed assist for the next games, in percent (50 … 100): a replay records it and the
    // high scores keep its games in a table of their own.
    int gameSpeed = 100;
    Bindings bindings = Bindings::defaults();

    static constexpr int kMinWindowSide = 160;
    static constexpr int kMaxWindowSide = 16384;
    static constexpr int kMaxWindowOffset = 65536;  // |x|, |y| at most this

    bool operator==(const Settings&) const = default;
};

// The file's text for `settings` (formatted JSON, one key a line, keys in a fixed order).
std::string settingsToJson(const Settings& settings);
// Parses settings.json text. Every key is checked: a wrong type, an unknown key, a value out of
// range, a duplicate key or a key bound twice is an Error at its file:line:column.
Result<Settings> parseSettings(const SourceFile& file);

// The settings file in the data folder and what became of it at start-up.
//
// A missing file gives the defaults. A file that cannot be read or parsed gives the defaults and a
// problem (its file:line:column message, shown once on screen and on stderr), and the file is
// renamed to settings.json.bad (.bad-2, … when that is taken) before anything is written, so a
// hand edit is never overwritten. If it cannot even be renamed, nothing is saved this run.
class SettingsFile {
  public:
    static SettingsFile load(const std::string& path);

    const Settings& settings() const { return settings_; }
    // The message for a file that could not be used, once: the second call returns nothing.
    std::optional<std::string> takeProblem();
    const std::optional<Error>& problem() const { return problem_; }
    // Where the unusable file was kept ("…/settings.json.bad"), if it was.
    const std::string& setAside() const { return setAside_; }

    // Keeps `settings` and writes them atomically when they differ from what was written last.
    std::optional<Error> save(const Settings& settings, const AtomicWriteFault& fault = {});
    const std::string& path() const { return path_; }

  private:
    std::string path_;
    Settings settings_;
    std::optional<Error> problem_;
    bool problemTaken_ = false;
    bool saveBlocked_ = false;
    std::string setAside_;
    std::optional<std::string> written_;  // the text on disk, once known
};

}  // namespace polar::game
