// polarcade: the demo game. Windowed by default; --headless runs without a window or audio.
#include <cstdio>
#include <filesystem>

#include "app/run/app.h"
#include "cli.h"
#include "files/assets.h"

int main(int argc, char** argv) {
    polar::game::AppOptions options;
    CLI::App app{
        "Polarcade: a ship among tumbling rocks, in four scenes (cave, field, ghosts, storm) and any a mod "
        "adds. Menus take the keyboard, a controller or the mouse. By default arrows or WASD turn and "
        "thrust, space fires, Esc or P pauses (Options remaps every key and button), F1 shows the collision "
        "bounds, F5 reloads edited bounds files at once (they also reload by themselves within a second), "
        "F11 or Alt+Enter toggles fullscreen. Modding: see " +
            polar::game::moddingGuidePath() + ".",
        "polarcade"};
    app.footer(
        "Environment: POLARCADE_ASSETS=DIR picks the asset folder (default: ../share/polarcade beside the "
        "executable, or the source tree's assets/ in the build tree); POLARCADE_DATA=DIR as --data.");
    std::vector<std::string> shots;
    std::uint64_t seed = 0;
    app.add_flag("--headless", options.headless, "Render off-screen: no window, no audio device");
    app.add_option("--ticks", options.ticks, "Headless: run this many 60 Hz ticks, then exit (default 600)")
        ->check(CLI::NonNegativeNumber);
    app.add_option("--screenshot", shots, "Save the frame after tick TICK to FILE.png (repeatable)")
        ->type_name("TICK:FILE.png");
    app.add_option("--scene", options.scene, "A scene name from assets/scenes/ or a scene file")
        ->type_name("NAME|FILE");
    auto* seedOption =
        app.add_option("--seed", seed, "The random seed (default: from the clock; 1 headless)");
    int lives = 0;
    auto* livesOption =
        app.add_option("--lives", lives,
                       "Start each game with N lives (default 3): practice, or a long headless run")
            ->check(CLI::Range(1, 99))
            ->type_name("N");
    app.add_option("--mod", options.mods, "A mod folder laid over assets/ (repeatable; later ones win)")
        ->check(CLI::ExistingDirectory);
    app.add_flag("--stats", options.stats, "Print per-effect calls and time per step at exit");
    app.add_option(
           "--threads", options.threads,
           "Threads for the world's step (default: every core); the game plays the same on any number")
        ->check(CLI::Range(1u, 256u))
        ->type_name("N");
    app.add_flag("--show-bounds", options.showBounds,
                 "Start with the collision bounds shown (as F1 does); headless screenshots show them too");
    app.add_flag("--mute", options.mute, "No sound (this run; the Options' mute is kept in settings.json)");
    bool fullscreen = false, windowed = false;
    std::string scaleMode;
    auto* fullscreenFlag = app.add_flag("--fullscreen", fullscreen,
                                        "Start fullscreen (this run only; settings.json is not changed)");
    app.add_flag("--windowed", windowed, "Start in a window (this run only)")->excludes(fullscreenFlag);
    app.add_option(
           "--scale-mode", scaleMode,
           "Scale the picture by whole pixels only (integer) or as large as fits (fit), this run only")
        ->check(CLI::IsMember({"integer", "fit"}))
        ->type_name("integer|fit");
    app.add_option(
           "--record", options.record,
           "Also record the first game played into FILE (every game is recorded into the data folder's "
           "replays/ anyway; headless: the demo pilot's game)")
        ->type_name("FILE");
    auto* replayOption =
        app.add_option("--replay", options.replay,
                       "Play a replay back in the replay theatre (or off-screen with --headless), checking "
                       "every tick against the recording; a folder opens the theatre's list of its replays")
            ->type_name("FILE|DIR");
    app.add_option("--script", options.script,
                   "Drive the screens by the events in FILE, one tick a frame, with no window (for tests; "
                   "the commands are in game/app/run/script.h)")
        ->type_name("FILE");
    auto* verifyFlag =
        app.add_flag("--verify", options.verify,
                     "With --replay: exit 1 at the first checkpoint that differs from the recording, at a "
                     "damaged trace or checkpoint line, or when the replay has no end line, with a report")
            ->needs(replayOption);
    app.add_flag("--allow-incomplete", options.allowIncomplete,
                 "With --verify: pass a replay without its end line (an interrupted recording) when every "
                 "tick it holds matches; by default it fails (exit 1), as in polarcade-replay")
        ->needs(verifyFlag);
    app.add_option("--seek", options.seek,
                   "With --replay: start at tick TICK, reached by keyframes and checked like straight play")
        ->check(CLI::NonNegativeNumber)
        ->type_name("TICK")
        ->needs(replayOption);
    app.add_option("--data", options.data,
                   "The data folder for high scores and replays (default: $POLARCADE_DATA, else the per-user "
                   "folder); headless runs record their game into its replays/ only when this is given")
        ->type_name("DIR");
    if (int code = polar::cli::parse(app, argc, argv); code >= 0) return code;
    if (*seedOption) options.seed = seed;
    if (fullscreen || windowed) options.fullscreen = fullscreen;
    if (!scaleMode.empty()) options.integerScaling = scaleMode == "integer";
    if (*livesOption) options.lives = lives;
    std::error_code folderCheck;
    if (!options.script.empty() && !options.replay.empty() &&
        !std::filesystem::is_directory(options.replay, folderCheck)) {
        std::fprintf(
            stderr,
            "polarcade: --script cannot be used with --replay FILE: a script starts at the title, or at "
            "the replay list of --replay DIR\n");
        return 2;
    }
    for (const char* flag : {"--scene", "--seed", "--lives", "--record"}) {
        if (!options.replay.empty() && app.count(flag) > 0) {
            std::fprintf(stderr,
                         "polarcade: %s cannot be used with --replay: a replay plays the scene, seed and "
                         "inputs it was recorded with\n",
                         flag);
            return 2;
        }
    }
    for (const std::string& shot : shots) {
        std::size_t colon = shot.find(':');
        std::uint64_t tick = 0;
        bool ok = colon != std::string::npos && colon > 0 && colon + 1 < shot.size();
        if (ok) {
            try {
                std::size_t used = 0;
                tick = std::stoull(shot.substr(0, colon), &used);
                ok = used == colon && shot[0] != '-';
            } catch (...) {
                ok = false;
            }
        }
        if (!ok) {
            std::fprintf(stderr, "polarcade: --screenshot %s: expected TICK:FILE.png, e.g. 600:out.png\n",
                         shot.c_str());
            return 2;
        }
        options.screenshots.emplace_back(tick, shot.substr(colon + 1));
    }
    return polar::game::runApp(std::move(options));
}
