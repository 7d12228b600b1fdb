#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "app/settings.h"
#include "polar/platform/window.h"
#include "polar/render/canvas.h"

namespace polar::game {

class Audio;
class Input;
class Session;

// The command line's say over the settings, for one run only (never saved).
struct SettingsOverrides {
    bool mute = false;                   // --mute
    std::optional<bool> fullscreen;      // --fullscreen / --windowed
    std::optional<ScaleMode> scaleMode;  // --scale-mode integer|fit
};

struct AppOptions;
// The overrides the command line asked for.
SettingsOverrides settingsOverrides(const AppOptions& options);

// The settings as the running app uses them: settings.json from the data folder, the flags laid
// over it, applied to the window, the audio and the input, and saved when the player changes them.
//
// Why two copies? `saved()` is what the file holds and the options screen edits; `effective()` is
// that plus this run's flags. A flag never reaches the file, and a change made on screen is kept
// even while a flag overrides it for this run.
class AppSettings {
  public:
    // `dataFolder` empty: nothing is read or written (no data folder).
    AppSettings(const std::string& dataFolder, const SettingsOverrides& overrides);

    const Settings& saved() const { return file_.settings(); }
    Settings effective() const;
    // How to open the window: size, position, fullscreen and scaling from the settings.
    platform::WindowSettings windowSettings(const std::string& title, int canvasWidth,
                                            int canvasHeight) const;
    // Sets the volumes and the key map.
    void apply(Audio& audio, Input& input) const;
    // Applies the settings to the session's audio and input, starts its scene's music, and gives
    // the session (its Options screen) these settings.
    void attach(Session& session);
    // Keeps `settings` as the saved ones, applies them, and writes settings.json if they changed.
    void change(const Settings& settings, Audio& audio, Input& input, platform::Window& window);
    // Notes the window's windowed size and position and whether it is fullscreen (unless a flag set
    // that), and saves: called when the app leaves.
    void rememberWindow(const platform::Window& window);

    // Draws, for the first seconds of the run, why settings.json could not be used (and prints it to
    // stderr on the first call). Draws nothing when the file was fine.
    void drawProblem(render::Canvas& canvas);

  private:
    void save(const Settings& settings);

    SettingsFile file_;
    SettingsOverrides overrides_;
    std::optional<std::string> problem_;  // the message, while it is on screen
    std::uint64_t problemFrames_ = 0;
};

}  // namespace polar::game
