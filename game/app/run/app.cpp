#include "app/run/app.h"

#include <chrono>
#include <cstdio>
#include <filesystem>

#include "app/context/app_context.h"
#include "app/input/app_settings.h"
#include "app/run/headless_run.h"
#include "app/run/replay_headless.h"
#include "app/run/screen_loop.h"
#include "app/run/script.h"
#include "app/screens/replay_list_screen.h"
#include "app/screens/theatre_screen.h"
#include "app/screens/title_screen.h"
#include "app/theatre/replay_playback.h"
#include "files/scene_list.h"
#include "polar/platform/image_file.h"
#include "polar/platform/main_loop.h"
#include "polar/platform/window.h"

namespace polar::game {
namespace {

namespace fs = std::filesystem;

constexpr std::int64_t kNoDisplayTicks = 300;
constexpr std::int64_t kHeadlessTicks = 600;  // --headless without --ticks
constexpr double kTickSeconds = 1.0 / 60.0;

// Applies the settings to the session's audio and input, starts its scene's music, gives the
// session (its Options screen) these settings, and tells the player, once, why settings.json could
// not be used.
void attachSettings(AppSettings& settings, Session& session) {
    session.settings = &settings;
    // Once, in the notice corner and on stderr.
    if (std::optional<std::string> problem = settings.takeProblem()) session.notice.tell(*problem);
    settings.apply(session.audio, session.input);
    session.follow(settings.effective());
    session.audio.setMusic(fs::path(session.games.scenePath).stem().string());
}

// The overrides the command line asked for: this run only, never saved.
SettingsOverrides settingsOverrides(const AppOptions& options) {
    SettingsOverrides o;
    o.mute = options.mute;
    o.fullscreen = options.fullscreen;
    if (options.integerScaling) o.scaleMode = *options.integerScaling ? ScaleMode::Integer : ScaleMode::Fit;
    return o;
}

// Chooses how the game runs (a replay, headless, a script, a window) and runs it.
class App {
  public:
    App(AppOptions options, std::string assetRoot) : context_(std::move(options), std::move(assetRoot)) {
        // A replay must reproduce its game exactly; an edit in the middle would break that.
        if (!context_.options.record.empty() || !context_.options.replay.empty())
            context_.hotReload.disable("a replay is being recorded or played");
    }

    int run() {
        const AppOptions& options = context_.options;
        for (const AssetFs::ModSummary& mod : context_.assets.summarise())
            std::printf("mod: %s (replaces %zu files, adds %zu)\n", mod.folder.c_str(), mod.replaces.size(),
                        mod.adds.size());
        std::error_code ec;
        const bool replayFolder = !options.replay.empty() && fs::is_directory(options.replay, ec);
        if (!options.replay.empty() && !replayFolder) return runReplay();
        Result<std::string> scene = resolveScene(context_.assets, options.scene);
        if (!scene) return context_.fail(scene.error());
        scenePath_ = *scene;
        // --replay DIR: the replay list of that folder is the first screen.
        std::function<std::unique_ptr<Screen>(Session&)> root = [](Session&) { return makeTitleScreen(); };
        if (replayFolder) root = [&options](Session&) { return makeReplayListScreen(options.replay, true); };
        if (!options.script.empty()) return runScript(root);
        if (replayFolder) {
            if (options.headless || platform::Window::displayProblem())
                return context_.fail(Error{options.replay, 0, 0,
                                           "is a folder: its replays are listed in a window",
                                           "a replay file, or polarcade-replay " + options.replay +
                                               " to verify every replay in it"});
            return runWindowed("Polarcade replays", root);
        }
        if (options.headless) {
            const std::int64_t ticks = options.ticks < 0 ? kHeadlessTicks : options.ticks;
            const std::string limit = options.ticks < 0
                                          ? "the run is " + std::to_string(ticks) + " ticks by default"
                                          : "--ticks " + std::to_string(ticks);
            if (std::optional<Error> error =
                    screenshotNotReached(options, 1, static_cast<std::uint64_t>(ticks), limit))
                return context_.fail(*error);
            return runHeadless(context_, scenePath_, ticks, true, !options.data.empty());
        }
        if (std::optional<Error> noDisplay = platform::Window::displayProblem()) {
            std::printf(
                "polarcade: no display found (%s); running the attract demo headless for %lld ticks "
                "instead\n",
                noDisplay->what.c_str(), static_cast<long long>(kNoDisplayTicks));
            std::fflush(stdout);
            const DataFolder& data = context_.dataFolder();
            std::string shot = data.path + "attract.png";
            if (data.writable()) context_.options.screenshots.emplace_back(kNoDisplayTicks, shot);
            int code = runHeadless(context_, scenePath_, kNoDisplayTicks, false, false);
            if (code == 0 && data.writable())
                std::printf("polarcade: saved a screenshot of the attract demo to %s\n", shot.c_str());
            return code;
        }
        return runWindowed("Polarcade", [](Session&) { return makeTitleScreen(); });
    }

  private:
    // --replay FILE: off-screen with --headless (or with no display), else in the replay screen.
    int runReplay() {
        const AppOptions& options = context_.options;
        if (options.headless)
            return playReplayHeadless(options, context_.assets, context_.sprites, context_.canvas,
                                      context_.pool);
        if (std::optional<Error> noDisplay = platform::Window::displayProblem()) {
            // A replay that cannot be read says so before anything about the display.
            Result<std::unique_ptr<Playback>> check =
                Playback::open(options.replay, context_.assets, context_.pool);
            if (!check) return context_.fail(check.error());
            std::printf("polarcade: no display found (%s); playing the replay headless instead\n",
                        noDisplay->what.c_str());
            return playReplayHeadless(options, context_.assets, context_.sprites, context_.canvas,
                                      context_.pool);
        }
        return runWindowed("Polarcade replay", [&options](Session& session) {
            return makeTheatreScreen(session, options.replay, true);
        });
    }

    // --script FILE: the screens driven by the script's events, one tick a frame, no window.
    int runScript(const std::function<std::unique_ptr<Screen>(Session&)>& root) {
        const std::string& path = context_.options.script;
        std::optional<SourceFile> file = diskReader()(path);
        if (!file) return context_.fail(Error{path, 0, 0, "cannot read the script", "a readable text file"});
        Result<std::vector<ScriptStep>> steps = parseScript(*file);
        if (!steps) return context_.fail(steps.error());
        ScreenLoop loop(context_, nullptr, scenePath_, root);
        if (!loop.ready()) return 2;
        const fs::path folder = fs::path(path).parent_path();
        auto runFrame = [&](const std::vector<platform::Event>& events) {
            return loop.frame(events, kTickSeconds);
        };
        if (std::optional<int> code = runFrame({})) return *code;  // the first frame, before any event
        for (const ScriptStep& step : *steps) {
            std::optional<int> code;
            switch (step.kind) {
                case ScriptStep::Kind::Events:
                    code = runFrame(step.events);
                    break;
                case ScriptStep::Kind::Wait:
                    for (int i = 0; i < step.frames && !code; ++i) code = runFrame({});
                    break;
                case ScriptStep::Kind::Screenshot: {
                    const std::string shot = (folder / step.text).generic_string();
                    if (auto error = render::savePng(context_.canvas, shot)) return context_.fail(*error);
                    break;
                }
                case ScriptStep::Kind::Expect:
                    if (step.text != loop.stack().top().name()) {
                        return context_.fail(
                            Error{path, step.line, 1,
                                  std::string("the screen on top is \"") + loop.stack().top().name() + "\"",
                                  "\"" + step.text + "\""});
                    }
                    break;
                case ScriptStep::Kind::ExpectTick: {
                    const std::optional<FrameView> view = loop.view();
                    const long long at = view ? static_cast<long long>(view->game.tickCount()) : -1;
                    if (at != step.frames)
                        return context_.fail(Error{path, step.line, 1,
                                                   view
                                                       ? "the game on screen is at tick " + std::to_string(at)
                                                       : std::string("no game is on screen"),
                                                   "tick " + std::to_string(step.frames)});
                    break;
                }
            }
            if (code) return *code;
        }
        return loop.frame({platform::QuitRequested{}}, kTickSeconds).value_or(0);
    }

    // Opens the window and runs the screens in it, from `root`, until the player quits. What the
    // frames use is kept on the heap: a browser's frame loop outlives the call that starts it.
    int runWindowed(const char* title, std::function<std::unique_ptr<Screen>(Session&)> root) {
        const DataFolder& data = context_.dataFolder();
        settings_.emplace(data.writable() ? data.path : "", settingsOverrides(context_.options));
        Result<std::unique_ptr<platform::Window>> opened =
            platform::Window::open(settings_->windowSettings(title, kScreenWidth, kScreenHeight));
        if (!opened) return context_.fail(opened.error());
        window_ = std::move(*opened);
        loop_ = std::make_unique<ScreenLoop>(context_, window_.get(), scenePath_, root);
        if (!loop_->ready()) return 2;
        attachSettings(*settings_, loop_->session());
        last_ = std::chrono::steady_clock::now();
        const int code = platform::runFrames([this] { return windowedFrame(); });
        settings_->rememberWindow(*window_);
        return code;
    }

    // One frame in the window: its events in, the picture out.
    platform::FrameResult windowedFrame() {
        std::vector<platform::Event> events;
        while (std::optional<platform::Event> event = window_->pollEvent())
            events.push_back(std::move(*event));
        const auto now = std::chrono::steady_clock::now();
        const double seconds = std::chrono::duration<double>(now - last_).count();
        last_ = now;
        if (context_.options.replayToOpen)
            if (std::optional<std::string> replay = context_.options.replayToOpen())
                loop_->openReplay(*replay);
        if (std::optional<int> code = loop_->frame(events, seconds)) return {code};
        window_->present(context_.canvas);
        if (context_.options.onFrame)
            if (std::optional<FrameView> view = loop_->view()) context_.options.onFrame(*view);
        // No vsync on a window surface: rest until the next tick is nearly due.
        return {std::nullopt, loop_->idleSeconds()};
    }

    AppContext context_;
    std::string scenePath_;
    std::optional<AppSettings> settings_;  // windowed runs: settings.json
    std::unique_ptr<platform::Window> window_;
    std::unique_ptr<ScreenLoop> loop_;  // after the window: closed before it
    std::chrono::steady_clock::time_point last_;
};

}  // namespace

int runApp(AppOptions options) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "polarcade: %s\n", root.error().message().c_str());
        return 2;
    }
    // On the heap, and left there while a browser runs its frames: on the web, run() hands the
    // frame loop to the page and never comes back here (platform/main_loop.h).
    auto* app = new App(std::move(options), std::move(*root));
    const int code = app->run();
    delete app;
    return code;
}

}  // namespace polar::game
