#include "app/app_settings.h"

#include "app/app.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/audio.h"
#include "app/hot_reload_hud.h"
#include "app/input.h"
#include "app/session.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"

namespace polar::game {
namespace {

constexpr std::uint64_t kProblemFrames = 600;  // about ten seconds on screen
constexpr render::Color kBox{70, 8, 14, 225};
constexpr render::Color kTitle{255, 200, 120, 255};
constexpr render::Color kText{255, 170, 170, 255};

}  // namespace

SettingsOverrides settingsOverrides(const AppOptions& options) {
    SettingsOverrides o;
    o.mute = options.mute;
    o.fullscreen = options.fullscreen;
    if (options.integerScaling) o.scaleMode = *options.integerScaling ? ScaleMode::Integer : ScaleMode::Fit;
    return o;
}

AppSettings::AppSettings(const std::string& dataFolder, const SettingsOverrides& overrides)
    : file_(dataFolder.empty() ? SettingsFile{} : SettingsFile::load(dataFolder + "settings.json")),
      overrides_(overrides) {
    problem_ = file_.takeProblem();
    if (problem_) std::fprintf(stderr, "%s\n", problem_->c_str());
}

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

void AppSettings::attach(Session& session) {
    session.settings = this;
    apply(session.audio, session.input);
    session.audio.setMusic(std::filesystem::path(session.scenePath).stem().string());
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

void AppSettings::drawProblem(render::Canvas& canvas) {
    if (!problem_) return;
    if (++problemFrames_ > kProblemFrames) {
        problem_.reset();
        return;
    }
    const int margin = 6;
    const std::size_t columns =
        static_cast<std::size_t>((canvas.width() - 2 * margin - 4) / render::kCharAdvance);
    std::vector<std::string> lines{"SETTINGS NOT USED - THE DEFAULTS ARE:"};
    for (std::string& line : wrapText(*problem_, columns)) lines.push_back(std::move(line));
    if (lines.size() > 6) lines.resize(6);
    const int height = static_cast<int>(lines.size()) * render::kLineHeight + 6;
    render::fillRect(canvas, margin - 2, margin, canvas.width() - 2 * (margin - 2), height, kBox);
    for (std::size_t i = 0; i < lines.size(); ++i)
        render::drawText(canvas, lines[i], margin + 2, margin + 3 + static_cast<int>(i) * render::kLineHeight,
                         1, i == 0 ? kTitle : kText);
}

}  // namespace polar::game
