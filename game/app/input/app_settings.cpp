#include "app/input/app_settings.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/input/audio.h"
#include "app/input/input.h"

namespace polar::game {
AppSettings::AppSettings(const std::string& dataFolder, const SettingsOverrides& overrides)
    : file_(dataFolder.empty() ? SettingsFile{} : SettingsFile::load(dataFolder + "settings.json")),
      overrides_(overrides) {}

Settings AppSettings::effective() const {
    Settings s = file_.settings();
    if (overrides_.mute) s.mute = true;
    if (overrides_.fullscreen) s.fullscreen = *overrides_.fullscreen;
    if (overrides_.scaleMode) s.scaleMode = *overrides_.scaleMode;
    return s;
}

platform::WindowSettings AppSettings::windowSettings(const std::string& title, int canvasWidth,
                                                     int canvasHeight) const {
    const Settings s = effective();
    platform::WindowSettings w;
    w.title = title;
    w.canvasWidth = canvasWidth;
    w.canvasHeight = canvasHeight;
    w.width = s.windowWidth;
    w.height = s.windowHeight;
    w.x = s.windowX;
    w.y = s.windowY;
    w.fullscreen = s.fullscreen;
    w.integerScaling = s.scaleMode == ScaleMode::Integer;
    return w;
}

void AppSettings::apply(Audio& audio, Input& input) const {
    const Settings s = effective();
    audio.setVolumes({s.masterVolume, s.effectsVolume, s.musicVolume, s.mute});
    input.setBindings(s.bindings);
}

void AppSettings::change(const Settings& settings, Audio& audio, Input& input, platform::Window& window) {
    const bool wasFullscreen = effective().fullscreen;
    save(settings);
    apply(audio, input);
    const Settings s = effective();
    window.setIntegerScaling(s.scaleMode == ScaleMode::Integer);
    if (s.fullscreen != wasFullscreen && window.fullscreen() != s.fullscreen) window.toggleFullscreen();
}

void AppSettings::rememberWindow(const platform::Window& window) {
    Settings s = file_.settings();
    const platform::Window::Bounds b = window.windowedBounds();
    if (b.width >= Settings::kMinWindowSide && b.height >= Settings::kMinWindowSide) {
        s.windowWidth = std::min(b.width, Settings::kMaxWindowSide);
        s.windowHeight = std::min(b.height, Settings::kMaxWindowSide);
        s.windowX = std::clamp(b.x, -Settings::kMaxWindowOffset, Settings::kMaxWindowOffset);
        s.windowY = std::clamp(b.y, -Settings::kMaxWindowOffset, Settings::kMaxWindowOffset);
    }
    if (!overrides_.fullscreen) s.fullscreen = window.fullscreen();
    save(s);
}

void AppSettings::save(const Settings& settings) {
    if (file_.path().empty()) return;
    if (std::optional<Error> error = file_.save(settings))
        std::fprintf(stderr, "%s (the settings are kept for this run)\n", error->message().c_str());
}

}  // namespace polar::game
