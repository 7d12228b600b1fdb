#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "app/input/settings.h"
#include "polar/platform/window.h"

namespace polar::game {

class Audio;
class Input;

// The command line's say over the settings, for one run only (never saved).
struct SettingsOverrides {
    bool mute = false;                   // --mute
    std::optional<bool> fullscreen;      // --fullscreen / --windowed
    std::optional<ScaleMode> scaleMode;  // --scale-mode integer|fit
};

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
    // Why settings.json could not be used, once (then nothing): the player is told.
    std::optional<std::string> takeProblem() { return file_.takeProblem(); }
    // Keeps `settings` as the saved ones, applies them, and writes settings.json if they changed.
    void change(const Settings& settings, Audio& audio, Input& input, platform::Window& window);
    // Notes the window's windowed size and position and whether it is fullscreen (unless a flag set
    // that), and saves: called when the app leaves.
    void rememberWindow(const platform::Window& window);

  private:
    void save(const Settings& settings);

    SettingsFile file_;
    SettingsOverrides overrides_;
};

}  // namespace polar::game
