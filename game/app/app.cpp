#include "app/app.h"

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>

#include "app/audio.h"
#include "app/draw.h"
#include "app/hot_reload_hud.h"
#include "app/input.h"
#include "app/replay_playback.h"
#include "files/assets.h"
#include "files/high_scores.h"
#include "files/hot_reload.h"
#include "polar/platform/image_file.h"
#include "polar/platform/main_loop.h"
#include "polar/platform/system.h"
#include "polar/platform/window.h"
#include "polar/render/shapes.h"
#include "polar/render/text.h"
#include "replay/replay.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace polar::game {
namespace {

using render::Color;
namespace fs = std::filesystem;

constexpr double kTickSeconds = 1.0 / 60.0;
constexpr double kMaxFrameSeconds = 0.25;  // a longer frame is clamped: no spiral of death
constexpr std::int64_t kNoDisplayTicks = 300;

// The player's data folder (high scores, replays) and whether anything can be saved there.
struct DataFolder {
    std::string path;              // ends with '/'; empty when there is none at all
    std::optional<Error> problem;  // why nothing can be written there
    bool writable() const { return !path.empty() && !problem; }
};

// --data DIR, else $POLARCADE_DATA, else the platform's per-user folder; created if missing, then
// probed by writing a file, so a read-only or non-folder path is found before a game is lost to it.
DataFolder openDataFolder(const std::string& asked) {
    const char* expected = "a writable folder (choose one with --data DIR or POLARCADE_DATA)";
    DataFolder data;
    std::string chosen = asked;
    if (const char* env = std::getenv(kDataFolderVariable); chosen.empty() && env && *env) chosen = env;
    if (chosen.empty()) {
        Result<std::string> pref = platform::userDataFolder("polarcade", "polarcade");
        if (!pref) {
            data.problem = pref.error();
            data.problem->expected = expected;
            return data;
        }
        chosen = *pref;
    }
    if (chosen.back() != '/') chosen += '/';
    data.path = chosen;
    std::error_code ec;
    const std::string bare =
        chosen.size() > 1 ? chosen.substr(0, chosen.size() - 1) : chosen;  // "x/" is never a file
    if (fs::exists(bare, ec) && !fs::is_directory(bare, ec)) {
        data.problem = Error{chosen, 0, 0, "the data folder is a file, not a folder", expected};
        return data;
    }
    fs::create_directories(chosen, ec);
    if (ec || !fs::is_directory(chosen, ec)) {
        data.problem =
            Error{chosen, 0, 0,
                  "the data folder cannot be created: " + (ec ? ec.message() : std::string("not a folder")),
                  expected};
        return data;
    }
    const std::string probe = chosen + ".polarcade-write-test";
    std::FILE* file = std::fopen(probe.c_str(), "wb");
    if (!file || std::fclose(file) != 0) {
        data.problem =
            Error{chosen, 0, 0, std::string("the data folder cannot be written: ") + std::strerror(errno),
                  expected};
        return data;
    }
    std::remove(probe.c_str());
    return data;
}

// Set by SIGINT or SIGTERM during a headless run; the loop looks at it between ticks. A signal
// handler may only touch a volatile sig_atomic_t, so that is all it does.
volatile std::sig_atomic_t interruptRequested = 0;

void requestInterrupt(int) {
    interruptRequested = 1;
}

// Catches SIGINT and SIGTERM for its lifetime, then puts the previous handlers back.
class InterruptCatcher {
  public:
    InterruptCatcher() {
        interruptRequested = 0;
        previousInt_ = std::signal(SIGINT, requestInterrupt);
        previousTerm_ = std::signal(SIGTERM, requestInterrupt);
    }
    ~InterruptCatcher() {
        std::signal(SIGINT, previousInt_ == SIG_ERR ? SIG_DFL : previousInt_);
        std::signal(SIGTERM, previousTerm_ == SIG_ERR ? SIG_DFL : previousTerm_);
    }
    InterruptCatcher(const InterruptCatcher&) = delete;
    InterruptCatcher& operator=(const InterruptCatcher&) = delete;
    bool interrupted() const { return interruptRequested != 0; }

  private:
    void (*previousInt_)(int) = SIG_DFL;
    void (*previousTerm_)(int) = SIG_DFL;
};

// A scene by name (assets/scenes/NAME.json, through the mods) or by file path.
Result<std::string> resolveScene(const AssetFs& assets, const std::string& scene) {
    std::error_code ec;
    if (fs::is_regular_file(scene, ec)) return fs::absolute(scene).lexically_normal().generic_string();
    std::string logical = "scenes/" + scene + ".json";
    if (assets.resolve(logical)) return logical;
    std::string names;  // from assets/ and every mod
    for (const std::string& file : assets.list("scenes")) {
        fs::path path(file);
        if (path.extension() == ".json" && path.parent_path() == "scenes")
            names += (names.empty() ? "" : ", ") + path.stem().string();
    }
    return Error{scene, 0, 0, "no such scene file or scene name",
                 "a scene name (" + names + ") or the path of a scene .json file"};
}

std::uint64_t seedFromClock() {
    // The seed is the only thing the wall clock ever decides; it is recorded with the game.
    return static_cast<std::uint64_t>(std::chrono::steady_clock::now().time_since_epoch().count()) %
           1000000007ull;
}

class App {
  public:
    App(AppOptions options, std::string assetRoot)
        : options_(std::move(options)),
          pool_(options_.threads > 0 ? options_.threads : hardwareThreads()),
          assets_(std::move(assetRoot), options_.mods),
          sprites_(assets_),
          canvas_(kScreenWidth, kScreenHeight),
          hotReload_(assets_) {
        // A replay must reproduce its game exactly; an edit in the middle would break that.
        if (!options_.record.empty() || !options_.replay.empty())
            hotReload_.disable("a replay is being recorded or played");
    }

    int run() {
        for (const AssetFs::ModSummary& mod : assets_.summarise())
            std::printf("mod: %s (replaces %zu files, adds %zu)\n", mod.folder.c_str(), mod.replaces.size(),
                        mod.adds.size());
        if (!options_.replay.empty()) return playReplay(options_, assets_, sprites_, canvas_, pool_);
        Result<std::string> scene = resolveScene(assets_, options_.scene);
        if (!scene) return fail(scene.error());
        scenePath_ = *scene;
        recordIntoData_ = options_.headless && !options_.data.empty();
        if (options_.headless) return runHeadless(options_.ticks < 0 ? 600 : options_.ticks);
        if (std::optional<Error> noDisplay = platform::Window::displayProblem()) {
            std::printf(
                "polarcade: no display found (%s); running the attract demo headless for %lld ticks "
                "instead\n",
                noDisplay->what.c_str(), static_cast<long long>(kNoDisplayTicks));
            std::fflush(stdout);
            const DataFolder& data = dataFolder();
            std::string shot = data.path + "attract.png";
            if (data.writable()) options_.screenshots.emplace_back(kNoDisplayTicks, shot);
            int code = runHeadless(kNoDisplayTicks, false);
            if (code == 0 && data.writable())
                std::printf("polarcade: saved a screenshot of the attract demo to %s\n", shot.c_str());
            return code;
        }
        return runWindowed();
    }

  private:
    enum class Screen { Title, Playing, Paused, GameOver, NameEntry };

    // What the windowed screens share: the window and the devices, the attract demo behind the
    // title and the player's game, the screen shown and its clock.
    struct Session {
        Session(platform::Window& window, Audio& audio, const DataFolder& data, HighScores& scores,
                GameRecorder& recorder, Game& attract)
            : window(window),
              audio(audio),
              data(data),
              scores(scores),
              recorder(recorder),
              attract(attract) {}

        platform::Window& window;
        Audio& audio;
        const DataFolder& data;
        HighScores& scores;
        GameRecorder& recorder;
        Game& attract;
        std::optional<Game> game;
        Input input;
        Bot bot{7};
        Screen screen = Screen::Title;
        Interpolation interpolation;
        Particles particles;
        bool debug = false;
        std::string nameEntry = "AAA";
        std::size_t nameCursor = 0;
        int screenTicks = 0;  // ticks since the last game over (also the title's blink clock)

        // The game on screen: the attract demo under the title, else the player's.
        Game& shown() { return screen == Screen::Title ? attract : *game; }
    };

    // The data folder, opened at the first use; when nothing can be saved there, that is said once.
    const DataFolder& dataFolder() {
        if (!data_) {
            data_ = openDataFolder(options_.data);
            if (data_->problem)
                std::fprintf(stderr, "polarcade: high scores and replays will not be saved: %s\n",
                             data_->problem->message().c_str());
        }
        return *data_;
    }

    int fail(const Error& error) {
        std::fprintf(stderr, "%s\n", assets_.onDisk(error).message().c_str());
        return 2;
    }

    Result<Game> newGame(std::uint64_t seed) {
        Game::Config config;
        config.scene = scenePath_;
        config.reader = hotReload_.reader();
        config.seed = seed;
        config.threads.tasks = &pool_;
        if (options_.lives) config.tuning.startLives = *options_.lives;
        Result<Game> game = Game::create(config);
        // Timing reads the clock only to report; the simulation never sees it.
        if (game) game->world().setTiming(timing_);
        return game;
    }

    // Adds the step just taken to the --stats totals and the overlay's smoothed time per effect.
    void tallyStep(const Game& game) {
        const StepStats& step = game.world().lastStepStats();
        statsTotal_ += step;
        ++statsSteps_;
        for (std::size_t i = 0; i < kEffectCount; ++i)
            effectMs_[i] = effectMs_[i] * 0.9 + 0.1 * (step.effects[i].nanoseconds * 1e-6);
    }

    void printStats() const {
        if (!options_.stats) return;
        std::printf("per-effect statistics over %llu steps on %u thread%s:\n%s",
                    static_cast<unsigned long long>(statsSteps_), pool_.workerCount(),
                    pool_.workerCount() == 1 ? "" : "s", formatStepStats(statsTotal_, statsSteps_).c_str());
    }

    void reportSpriteProblems() {
        for (std::size_t i = reportedProblems_; i < sprites_.problems().size(); ++i)
            std::fprintf(stderr, "%s\n", sprites_.problems()[i].message().c_str());
        reportedProblems_ = sprites_.problems().size();
    }

    // Applies edited bounds files to the games (hot_reload.h); the output goes to stdout and stderr.
    void reloadBetweenTicks(const std::vector<Game*>& games, bool now) {
        HotReload::Report report = hotReload_.update(games, now);
        auto disk = [this](const std::string& logical) { return assets_.resolve(logical).value_or(logical); };
        for (std::size_t i = 0; i < report.reloaded.size(); ++i)
            std::printf("reloaded %s (%zu object%s)\n", disk(report.reloaded[i]).c_str(), report.objects[i],
                        report.objects[i] == 1 ? "" : "s");
        for (const std::string& scene : report.scenes)
            std::printf("%s changed: it applies to the next game\n", disk(scene).c_str());
        for (const Error& error : report.errors)
            std::fprintf(stderr, "%s (the old version stays)\n", error.message().c_str());
        for (const std::string& file : report.fixed) std::printf("%s is valid again\n", disk(file).c_str());
        for (const std::string& sprite : report.spritesChanged) sprites_.forget(sprite);
        if (!report.reloaded.empty() || !report.scenes.empty() || !report.fixed.empty()) std::fflush(stdout);
    }

    std::optional<Error> screenshot(const std::string& path) { return render::savePng(canvas_, path); }

    // Headless: the attract demo's pilot plays, nothing opens a window or an audio device.
    int runHeadless(std::int64_t ticks, bool announceScreenshots = true) {
        timing_ = options_.stats || options_.showBounds;
        Result<Game> game = newGame(options_.seed.value_or(1));
        if (!game) return fail(game.error());
        Bot bot(game->seed());
        // With --data DIR the game is also kept in DIR/replays/, as a windowed game would be.
        std::string replays;
        if (recordIntoData_ && dataFolder().writable()) replays = dataFolder().path + "replays";
        GameRecorder recorder({options_.record, replays, 20, options_.mods, {}});
        recorder.start(*game, assets_);
        // Every picture is read now, so a missing or corrupt one is reported even when no frame is
        // drawn (it would be drawn as a magenta box).
        for (const std::string& sprite : game->spritePaths()) sprites_.get(sprite);
        reportSpriteProblems();
        // SIGINT or SIGTERM ends the run between two ticks, with the recordings finished.
        InterruptCatcher interrupt;
        Interpolation interpolation;
        Particles particles;
        std::map<std::uint64_t, std::vector<std::string>> shots;
        for (auto& [tick, file] : options_.screenshots) shots[tick].push_back(file);
        for (std::int64_t t = 1; t <= ticks; ++t) {
            if (interrupt.interrupted()) {
                std::fflush(stdout);
                std::fprintf(stderr, "polarcade: interrupted after tick %lld\n",
                             static_cast<long long>(t - 1));
                recorder.finish(*game, "interrupted");
                printStats();
                std::fflush(stdout);
                return kInterruptedExitCode;
            }
            reloadBetweenTicks({&*game}, false);
            Actions actions = bot.decide(*game);
            game->tick(actions);
            tallyStep(*game);
            recorder.record(actions, *game);
            particles.spawnFor(game->events(), game->tickCount());
            particles.tick(kTickSeconds);
            auto due = shots.find(static_cast<std::uint64_t>(t));
            if (due == shots.end()) continue;
            DrawOptions draw;
            draw.tasks = &pool_;
            draw.debugOverlay = options_.showBounds;
            draw.effectMs = effectMs_;
            drawGame(canvas_, *game, sprites_, interpolation, particles, 1.0, draw);
            drawHotReloadStatus(canvas_, hotReload_);
            reportSpriteProblems();
            for (const std::string& file : due->second) {
                if (auto error = screenshot(file)) return fail(*error);
                if (announceScreenshots)
                    std::printf("saved tick %lld to %s\n", static_cast<long long>(t), file.c_str());
            }
        }
        recorder.finish(*game, "ticks");
        printStats();
        return 0;
    }

    // What the windowed screens run on, in the order it is made: kept on the heap for as long as
    // they run, since a browser's frame loop outlives the call that starts it.
    struct Windowed {
        std::unique_ptr<platform::Window> window;
        std::optional<Audio> audio;
        HighScores scores;
        std::optional<GameRecorder> recorder;
        std::optional<Game> attract;
        std::optional<Session> session;
        std::chrono::steady_clock::time_point last = std::chrono::steady_clock::now();
        double accumulator = 0, fps = 60;
    };

    // Opens the window and the devices, then runs the screens until the player quits.
    int runWindowed() {
        timing_ = true;  // the debug overlay can be turned on at any time
        Result<std::unique_ptr<platform::Window>> opened =
            platform::Window::open({"Polarcade", kScreenWidth, kScreenHeight, 2});
        if (!opened) return fail(opened.error());
        windowed_ = std::make_unique<Windowed>();
        Windowed& w = *windowed_;
        w.window = std::move(*opened);
        w.audio.emplace(!options_.mute);
        const DataFolder& data = dataFolder();
        std::optional<Error> scoreProblem;
        // A folder that cannot be written may still be read: its table is shown, never saved.
        w.scores = HighScores::load(data.path.empty() ? "" : data.path + "highscores.json", &scoreProblem);
        if (scoreProblem)
            std::fprintf(stderr, "%s (%s)\n", scoreProblem->message().c_str(),
                         data.writable() ? "kept aside; a new table starts" : "a new table starts");

        w.recorder.emplace(GameRecorder::Options{
            options_.record, data.writable() ? data.path + "replays" : "", 20, options_.mods, {}});
        Result<Game> attract = newGame(seedFromClock());
        if (!attract) return fail(attract.error());
        w.attract.emplace(std::move(*attract));
        w.session.emplace(*w.window, *w.audio, data, w.scores, *w.recorder, *w.attract);
        w.session->debug = options_.showBounds;
        return platform::runFrames([this] { return windowedFrame(*windowed_); });
    }

    // One frame of the fixed-step loop: reads the commands, runs the ticks that are due, then draws.
    platform::FrameResult windowedFrame(Windowed& w) {
        Session& s = *w.session;
        const Input::Commands cmd = s.input.pollEvents(s.window);
        if (cmd.quit) return {finishWindowed(s)};
        if (cmd.debugOverlay) s.debug = !s.debug;
        if (std::optional<int> exitCode = screenCommands(s, cmd)) return {exitCode};
        s.audio.setPaused(s.screen == Screen::Paused);

        auto now = std::chrono::steady_clock::now();
        double frame = std::chrono::duration<double>(now - w.last).count();
        w.last = now;
        w.fps = w.fps * 0.95 + (frame > 0 ? 0.05 / frame : 0);
        w.accumulator += std::min(frame, kMaxFrameSeconds);
        reloadBetweenTicks({&s.attract, s.game ? &*s.game : nullptr}, cmd.reload);
        while (w.accumulator >= kTickSeconds) {
            w.accumulator -= kTickSeconds;
            ++s.screenTicks;
            screenTick(s);
        }
        const double alpha = (s.screen == Screen::Paused) ? 1.0 : w.accumulator / kTickSeconds;
        drawFrame(s, alpha, w.fps);
        s.window.present(canvas_);
        if (options_.onFrame) options_.onFrame(FrameView{s.shown(), screenName(s.screen), s.scores});
        // No vsync on a window surface: rest until the next tick is nearly due.
        return {std::nullopt, kTickSeconds - w.accumulator - 0.002};
    }

    int finishWindowed(Session& s) {
        if (s.game) s.recorder.finish(*s.game, "quit");
        printStats();
        return 0;
    }

    static const char* screenName(Screen screen) {
        switch (screen) {
            case Screen::Title:
                return "title";
            case Screen::Playing:
                return "playing";
            case Screen::Paused:
                return "paused";
            case Screen::GameOver:
                return "game-over";
            case Screen::NameEntry:
                return "name-entry";
        }
        return "?";
    }

    // The frame's menu commands, by screen; an exit code when the player leaves from the title.
    std::optional<int> screenCommands(Session& s, const Input::Commands& cmd) {
        switch (s.screen) {
            case Screen::Title:
                return titleCommands(s, cmd);
            case Screen::Playing:  // the player looking away pauses too
                if (cmd.pause || cmd.focusLost) s.screen = Screen::Paused;
                break;
            case Screen::Paused:
                pausedCommands(s, cmd);
                break;
            case Screen::GameOver:
                gameOverCommands(s, cmd);
                break;
            case Screen::NameEntry:
                nameEntryCommands(s, cmd);
                break;
        }
        return std::nullopt;
    }

    // Title: Esc leaves the game, confirm or a click starts a new one.
    std::optional<int> titleCommands(Session& s, const Input::Commands& cmd) {
        if (cmd.back) {
            printStats();
            return 0;
        }
        if (!cmd.confirm && !cmd.click) return std::nullopt;
        Result<Game> fresh = newGame(options_.seed.value_or(seedFromClock()));
        if (!fresh) {  // a modder's file broke since the start: say so, stay on the title
            std::fprintf(stderr, "%s\n", assets_.onDisk(fresh.error()).message().c_str());
            return std::nullopt;
        }
        s.game.emplace(std::move(*fresh));
        s.recorder.start(*s.game, assets_);
        s.screen = Screen::Playing;
        s.interpolation.capture(s.game->world());
        return std::nullopt;
    }

    // Paused: Esc gives the game up for the title, pause, confirm or a click resumes.
    void pausedCommands(Session& s, const Input::Commands& cmd) {
        if (cmd.back) {
            s.recorder.finish(*s.game, "quit");
            s.screen = Screen::Title;
        } else if (cmd.pause || cmd.confirm || cmd.click) {
            s.screen = Screen::Playing;
        }
    }

    // Game over: after 1.5 s confirm or a click (or after 6 s, anything) moves on, to the name
    // entry when the score earns a place in the table.
    void gameOverCommands(Session& s, const Input::Commands& cmd) {
        if (s.screenTicks <= 90 || !(cmd.confirm || cmd.click || s.screenTicks > 360)) return;
        if (s.scores.qualifies(s.game->score())) {
            s.screen = Screen::NameEntry;
            s.nameEntry = "AAA";
            s.nameCursor = 0;
        } else {
            s.screen = Screen::Title;
        }
    }

    // Name entry: up/down change the letter under the cursor, left/right move it, confirm moves on
    // and after the third letter saves the table.
    void nameEntryCommands(Session& s, const Input::Commands& cmd) {
        char& letter = s.nameEntry[s.nameCursor];
        if (cmd.up) letter = letter == 'Z' ? 'A' : letter + 1;
        if (cmd.down) letter = letter == 'A' ? 'Z' : letter - 1;
        if (cmd.left && s.nameCursor > 0) --s.nameCursor;
        if (cmd.right && s.nameCursor < 2) ++s.nameCursor;
        if (!cmd.confirm) return;
        if (s.nameCursor < 2) {
            ++s.nameCursor;
            return;
        }
        s.scores.insert({s.nameEntry, s.game->score(), s.game->wave()});
        // An unwritable folder was reported once at the start: the table then lives until the
        // game closes.
        std::optional<Error> error = s.data.writable() ? s.scores.save() : std::nullopt;
        if (error) std::fprintf(stderr, "polarcade: high scores not saved: %s\n", error->message().c_str());
        s.screen = Screen::Title;
    }

    // One fixed step under the screen's rules: the title plays the attract demo with the demo
    // pilot (a new demo when it ends), playing runs the player's actions (recorded, with sound),
    // game over lets the game run on untouched; paused and name entry stand still.
    void screenTick(Session& s) {
        switch (s.screen) {
            case Screen::Title: {
                const Actions actions = s.bot.decide(s.attract);
                advance(s, s.attract, actions);
                if (s.attract.over()) {
                    Result<Game> again = newGame(seedFromClock());
                    if (again) s.attract = std::move(*again);
                }
                break;
            }
            case Screen::Playing: {
                const Actions actions = Input::actions(s.window);
                advance(s, *s.game, actions);
                s.recorder.record(actions, *s.game);
                s.audio.play(s.game->events());
                if (s.game->over()) {
                    s.screen = Screen::GameOver;
                    s.screenTicks = 0;
                }
                break;
            }
            case Screen::GameOver:
                advance(s, *s.game, Actions{0});
                s.audio.play(s.game->events());
                break;
            case Screen::Paused:
            case Screen::NameEntry:
                break;
        }
    }

    // Ticks `game` with `actions`, keeping the interpolation, the statistics and the particles.
    void advance(Session& s, Game& game, Actions actions) {
        s.interpolation.capture(game.world());
        game.tick(actions);
        tallyStep(game);
        s.particles.spawnFor(game.events(), game.tickCount());
        s.particles.tick(kTickSeconds);
    }

    // The frame: the shown game, the screen's own overlay, hot reload's notices.
    void drawFrame(Session& s, double alpha, double fps) {
        DrawOptions draw;
        draw.tasks = &pool_;
        draw.debugOverlay = s.debug;
        draw.fps = fps;
        draw.effectMs = effectMs_;
        draw.hud = s.screen != Screen::Title;
        draw.highScore =
            s.scores.entries().empty() ? 0 : static_cast<std::uint64_t>(s.scores.entries().front().score);
        drawGame(canvas_, s.shown(), sprites_, s.interpolation, s.particles, alpha, draw);
        switch (s.screen) {
            case Screen::Title:
                drawTitle(s.scores, s.screenTicks);
                break;
            case Screen::Paused:
                drawPaused();
                break;
            case Screen::GameOver:
                drawCentredText(canvas_, "GAME OVER", 150, 4, kTitleColor);
                break;
            case Screen::NameEntry:
                drawNameEntry(s.game->score(), s.nameEntry, s.nameCursor);
                break;
            case Screen::Playing:
                break;
        }
        drawHotReloadStatus(canvas_, hotReload_);
        reportSpriteProblems();
    }

    static constexpr Color kTitleColor{255, 214, 120, 255};
    static constexpr Color kTextColor{220, 228, 255, 255};
    static constexpr Color kDimColor{150, 160, 200, 255};

    // The title over the attract demo: the help lines, every other 8 s the high-score table.
    void drawTitle(const HighScores& scores, int ticks) {
        drawCentredText(canvas_, "POLARCADE", 70, 5, kTitleColor);
        bool table = (ticks / 480) % 2 == 1 && !scores.entries().empty();
        if (table) {
            drawCentredText(canvas_, "HIGH SCORES", 140, 2, kTextColor);
            int y = 170;
            for (const auto& e : scores.entries()) {
                char line[64];
                std::snprintf(line, sizeof line, "%-3s %8d  WAVE %d", e.name.c_str(), e.score, e.wave);
                drawCentredText(canvas_, line, y, 1, kDimColor);
                y += 12;
            }
        } else {
            drawCentredText(canvas_, "A ROCK CAVE. A SHIP. NO WAY OUT.", 140, 1, kDimColor);
            drawCentredText(canvas_, "ARROWS/WASD TURN AND THRUST   SPACE FIRES   P PAUSES", 160, 1,
                            kDimColor);
            drawCentredText(canvas_, "F1 SHOWS THE BOUNDS   F11 FULLSCREEN", 174, 1, kDimColor);
        }
        if ((ticks / 30) % 2 == 0) drawCentredText(canvas_, "PRESS SPACE TO START", 300, 2, kTextColor);
    }

    void drawPaused() {
        render::fillRect(canvas_, 0, 150, kScreenWidth, 60, Color{0, 0, 0, 160});
        drawCentredText(canvas_, "PAUSED", 158, 3, kTitleColor);
        drawCentredText(canvas_, "P TO RESUME   ESC FOR THE TITLE", 192, 1, kTextColor);
    }

    // The score and three letters, the one under the cursor underlined.
    void drawNameEntry(int score, const std::string& name, std::size_t cursor) {
        render::fillRect(canvas_, 0, 110, kScreenWidth, 130, Color{0, 0, 0, 170});
        drawCentredText(canvas_, "A NEW HIGH SCORE", 120, 2, kTitleColor);
        char line[32];
        std::snprintf(line, sizeof line, "%d", score);
        drawCentredText(canvas_, line, 146, 2, kTextColor);
        for (std::size_t i = 0; i < 3; ++i) {
            std::string letter(1, name[i]);
            int x = kScreenWidth / 2 - 45 + static_cast<int>(i) * 34;
            render::drawText(canvas_, letter, x, 176, 4, i == cursor ? kTitleColor : kTextColor);
            if (i == cursor) render::fillRect(canvas_, x, 214, 20, 2, kTitleColor);
        }
        drawCentredText(canvas_, "UP/DOWN CHANGE   SPACE NEXT", 224, 1, kDimColor);
    }

    AppOptions options_;
    ThreadPool pool_;  // every game's world steps on it (--threads)
    std::optional<DataFolder> data_;
    std::unique_ptr<Windowed> windowed_;
    bool recordIntoData_ = false;  // headless with --data: record the game into its replays/ too
    AssetFs assets_;
    SpriteCache sprites_;
    render::Canvas canvas_;
    std::string scenePath_;
    std::size_t reportedProblems_ = 0;
    HotReload hotReload_;
    bool timing_ = false;  // worlds measure their time per effect (--stats, the debug overlay)
    StepStats statsTotal_;
    std::uint64_t statsSteps_ = 0;
    std::array<double, kEffectCount> effectMs_{};
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
