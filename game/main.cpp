// polarcade: the demo game. Windowed by default; --headless runs without a window or audio.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "app/run/app.h"
#include "cli.h"
#include "files/assets.h"
#include "replay/replay_writer.h"

int main(int argc, char** argv) {
    polar::game::AppOptions options;
    polar::cli::Command app{
        "Polarcade: a ship among tumbling rocks, in six scenes (cave, field, ghosts, storm; minefield and "
        "saucers, with foes and power-ups) and any a mod adds. Menus take the keyboard, a controller or the "
        "mouse. By default arrows or WASD turn and "
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
    app.flag("--headless", options.headless, "Render off-screen: no window, no audio device");
    app.option("--ticks", options.ticks, "Headless: run this many 60 Hz ticks, then exit (default 600)",
               {0, std::numeric_limits<std::int64_t>::max()});
    app.option("--screenshot", shots, "Save the frame after tick TICK to FILE.png (repeatable)")
        .typeName("TICK:FILE.png");
    app.option("--scene", options.scene, "A scene name from assets/scenes/ or a scene file")
        .typeName("NAME|FILE");
    const polar::cli::Option seedOption =
        app.option("--seed", seed, "The random seed (default: from the clock; 1 headless)");
    int lives = 0;
    const polar::cli::Option livesOption =
        app.option("--lives", lives,
                   "Start each game with N lives (default 3): practice, or a long headless run", {1, 99})
            .typeName("N");
    app.option("--mod", options.mods, "A mod folder laid over assets/ (repeatable; later ones win)")
        .existingFolder();
    app.flag("--stats", options.stats, "Print per-effect calls and time per step at exit");
    app.option("--threads", options.threads,
               "Threads for the world's step (default: every core); the game plays the same on any number",
               {1, 256})
        .typeName("N");
    app.flag("--show-bounds", options.showBounds,
             "Start with the collision bounds shown (as F1 does); headless screenshots show them too");
    app.flag("--mute", options.mute, "No sound (this run; the Options' mute is kept in settings.json)");
    bool fullscreen = false, windowed = false;
    std::string scaleMode;
    const polar::cli::Option fullscreenFlag = app.flag(
        "--fullscreen", fullscreen, "Start fullscreen (this run only; settings.json is not changed)");
    app.flag("--windowed", windowed, "Start in a window (this run only)").excludes(fullscreenFlag);
    app.option("--scale-mode", scaleMode,
               "Scale the picture by whole pixels only (integer) or as large as fits (fit), this run only")
        .oneOf({"integer", "fit"})
        .typeName("integer|fit");
    app.option("--record", options.record,
               "Also record the first game played into FILE (every game is recorded into the data folder's "
               "replays/ anyway; headless: the demo pilot's game)")
        .outputFile()
        .check([](const std::string& path) {
            // The recording goes to FILE.part until the game ends, so that must be free too.
            const std::string part = polar::game::ReplayWriter::partPathOf(path);
            std::error_code ec;
            if (!std::filesystem::is_directory(part, ec)) return std::string();
            return path + ": " + part +
                   ", where the recording is written until the game ends, is a folder; "
                   "expected a file in a writable folder";
        });
    const polar::cli::Option replayOption =
        app.option("--replay", options.replay,
                   "Play a replay back in the replay theatre (or off-screen with --headless), checking "
                   "every tick against the recording; a folder opens the theatre's list of its replays")
            .typeName("FILE|DIR");
    app.option("--script", options.script,
               "Drive the screens by the events in FILE, one tick a frame, with no window (for tests; "
               "the commands are in game/app/run/script.h)")
        .typeName("FILE");
    const polar::cli::Option verifyFlag =
        app.flag("--verify", options.verify,
                 "With --replay: exit 1 at the first checkpoint that differs from the recording, at a "
                 "damaged trace or checkpoint line, or when the replay has no end line, with a report")
            .needs(replayOption);
    app.flag("--allow-incomplete", options.allowIncomplete,
             "With --verify: pass a replay without its end line (an interrupted recording) when every "
             "tick it holds matches; by default it fails (exit 1), as in polarcade-replay")
        .needs(verifyFlag);
    app.option("--seek", options.seek,
               "With --replay: start at tick TICK, reached by keyframes and checked like straight play",
               {0, std::numeric_limits<std::int64_t>::max()})
        .typeName("TICK")
        .needs(replayOption);
    app.option("--data", options.data,
               "The data folder for high scores and replays (default: $POLARCADE_DATA, else the per-user "
               "folder); headless runs record their game into its replays/ only when this is given")
        .typeName("DIR");
    if (int code = app.parse(argc, argv); code >= 0) return code;
    if (seedOption.given()) options.seed = seed;
    if (fullscreen || windowed) options.fullscreen = fullscreen;
    if (!scaleMode.empty()) options.integerScaling = scaleMode == "integer";
    if (livesOption.given()) options.lives = lives;
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
    // TICK:FILE.png; whether the run reaches TICK is checked once its length is known (app/run/).
    for (const std::string& shot : shots) {
        const std::size_t colon = shot.find(':');
        if (colon == std::string::npos || colon == 0 || colon + 1 == shot.size()) {
            std::fprintf(stderr, "polarcade: --screenshot %s: expected TICK:FILE.png, e.g. 600:out.png\n",
                         shot.c_str());
            return 2;
        }
        const std::string tickText = shot.substr(0, colon);
        const polar::cli::Range<std::uint64_t> ticks;
        std::string problem;
        const std::optional<std::uint64_t> tick = polar::cli::parseNumber(tickText, ticks, problem);
        if (!tick) {
            std::fprintf(stderr, "polarcade: --screenshot %s: expected TICK:FILE.png with TICK %s, got %s\n",
                         shot.c_str(), polar::cli::rangeWords(ticks).c_str(), tickText.c_str());
            return 2;
        }
        const std::string file = shot.substr(colon + 1);
        if (const std::string why = polar::cli::outputFileProblem(file); !why.empty()) {
            std::fprintf(stderr, "polarcade: --screenshot %s: %s: %s; expected a file in a writable folder\n",
                         shot.c_str(), file.c_str(), why.c_str());
            return 2;
        }
        options.screenshots.emplace_back(*tick, file);
    }
    return polar::game::runApp(std::move(options));
}
