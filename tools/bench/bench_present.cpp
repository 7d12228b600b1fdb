// polarcade-bench present: what showing the game in a real window costs, by present path. The
// game (`polarcade`, beside this program) runs in a window on the X display in $DISPLAY, at the
// title and in a busy wave (the demo pilot's replay seeked into wave 7), once through SDL's
// framebuffer (the default, SDL_FRAMEBUFFER_ACCELERATION=0) and once through its OpenGL texture
// path (=1). After a warm-up, the child's CPU time over a wall interval gives its share of one
// core (from /proc/PID/stat), and its peak resident memory (VmHWM). The game paces itself at 60
// frames a second, so the share is what 60 frames a second cost. Goal (issue 26): at most 15 %.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <thread>

#include "bench.h"
#include "cli.h"
#include "demo_replay.h"
#include "files/assets.h"

namespace {

using namespace polar;
namespace fs = std::filesystem;

constexpr double kGoalPercent = 15.0;

struct Usage {
    double cpuSeconds = 0;  // user + system
    double peakMiB = 0;
};

// The child's CPU time and peak memory so far, or nothing once it is gone.
std::optional<Usage> usageOf(pid_t pid) {
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string text;
    if (!std::getline(stat, text)) return std::nullopt;
    // Fields after the command's closing parenthesis: state is field 3, utime 14, stime 15.
    std::istringstream fields(text.substr(text.rfind(')') + 2));
    std::string field;
    unsigned long long utime = 0, stime = 0;
    for (int k = 3; k <= 15 && fields >> field; ++k) {
        if (k == 3 && field == "Z") return std::nullopt;
        if (k == 14) utime = std::stoull(field);
        if (k == 15) stime = std::stoull(field);
    }
    Usage usage;
    usage.cpuSeconds = double(utime + stime) / double(::sysconf(_SC_CLK_TCK));
    usage.peakMiB = polar::bench::peakResidentMiB(pid);
    return usage;
}

struct Case {
    const char* path;    // framebuffer or opengl
    const char* screen;  // title or busy wave
    double percent = 0, peakMiB = 0;
};

// Runs the game with `args` under SDL_FRAMEBUFFER_ACCELERATION=`acceleration`; measures it.
std::optional<std::string> measure(Case& c, const std::string& game, const std::vector<std::string>& args,
                                   const char* acceleration, double warmup, double seconds) {
    const pid_t pid = ::fork();
    if (pid < 0) return std::string("could not start ") + game;
    if (pid == 0) {
        ::setenv("SDL_FRAMEBUFFER_ACCELERATION", acceleration, 1);
        std::vector<char*> argv{const_cast<char*>(game.c_str())};
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(game.c_str(), argv.data());
        std::_Exit(127);
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(warmup));
    const std::optional<Usage> before = usageOf(pid);
    const polar::bench::Stopwatch interval(polar::bench::CpuClock::None);
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    const std::optional<Usage> after = usageOf(pid);
    const double wall = interval.wallMs() / 1e3;
    ::kill(pid, SIGTERM);
    int status = 0;
    ::waitpid(pid, &status, 0);
    if (!before || !after)
        return game + " " + c.screen + " (" + c.path + ") ended before it was measured, exit status " +
               std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status));
    c.percent = 100.0 * (after->cpuSeconds - before->cpuSeconds) / wall;
    c.peakMiB = after->peakMiB;
    return std::nullopt;
}

struct Options {
    double warmup = 2;
    double seconds = 8;
    std::string csv;
};

// The game beside this program, or "" after a message when there is no display or no game.
std::string gameToMeasure() {
    if (!std::getenv("DISPLAY")) {
        std::fprintf(
            stderr,
            "present: no X display in $DISPLAY; expected one, e.g. xvfb-run -a -s '-screen 0 1280x800x24' "
            "polarcade-bench present\n");
        return "";
    }
    std::error_code ec;
    const fs::path game = fs::read_symlink("/proc/self/exe", ec).parent_path() / "polarcade";
    if (ec || !fs::exists(game)) {
        std::fprintf(stderr, "present: %s: not found; expected the game beside polarcade-bench\n",
                     game.string().c_str());
        return "";
    }
    return game.string();
}

// Each path on each screen, the busy wave from the demo pilot's replay seeked into wave 7; the
// replay and the game's data folder live in `folder`.
std::optional<std::string> measureCases(std::vector<Case>& cases, const std::string& game,
                                        const game::AssetFs& assets, const fs::path& folder,
                                        const Options& options) {
    std::error_code ec;
    fs::create_directories(folder / "data", ec);
    const std::string replay = (folder / "busy.replay").string();
    std::printf("present: recording the demo pilot's game into wave 7 ...\n");
    std::fflush(stdout);
    if (auto error = polar::bench::recordDemo(replay, assets, 16, 21600, 99)) return error->message();
    const std::string data = (folder / "data").string();
    const std::vector<std::string> title{"--windowed", "--mute", "--data", data};
    const std::vector<std::string> busy{"--windowed", "--mute", "--data", data,
                                        "--replay",   replay,   "--seek", "18000"};
    for (Case& c : cases) {
        std::printf("present: %s through %s, %.0f s ...\n", c.screen, c.path,
                    options.warmup + options.seconds);
        std::fflush(stdout);
        const bool gl = std::string(c.path) == "opengl";
        const bool isTitle = std::string(c.screen) == "title";
        if (auto error =
                measure(c, game, isTitle ? title : busy, gl ? "1" : "0", options.warmup, options.seconds))
            return "present: " + *error;
    }
    return std::nullopt;
}

bool report(const std::vector<Case>& cases, const Options& options) {
    std::printf("The game in a 640x360 window on %s at 60 frames a second; share of one core over %.0f s\n",
                std::getenv("DISPLAY"), options.seconds);
    std::printf("%-12s %-10s %8s %9s  %s\n", "path", "screen", "core %", "peak MiB",
                "default path's goal 15 %");
    polar::bench::Csv csv("path,screen,core_percent,peak_mib");
    for (const Case& c : cases) {
        std::printf("%-12s %-10s %8.1f %9.1f  %s\n", c.path, c.screen, c.percent, c.peakMiB,
                    std::strcmp(c.path, "opengl") == 0 ? "-"
                    : c.percent <= kGoalPercent        ? "met"
                                                       : "MISSED");
        csv.row(c.path, c.screen, c.percent, c.peakMiB);
    }
    return options.csv.empty() || csv.write(options.csv);
}

int run(const Options& options) {
    const std::string game = gameToMeasure();
    if (game.empty()) return polar::cli::kBadInput;
    Result<std::string> root = game::AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "present: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const fs::path folder =
        fs::temp_directory_path() / ("polarcade-bench-present-" + std::to_string(::getpid()));
    std::vector<Case> cases{
        {"framebuffer", "title"}, {"framebuffer", "busy wave"}, {"opengl", "title"}, {"opengl", "busy wave"}};
    const std::optional<std::string> error = measureCases(cases, game, game::AssetFs(*root), folder, options);
    std::error_code ec;
    fs::remove_all(folder, ec);
    if (error) {
        std::fprintf(stderr, "%s\n", error->c_str());
        return 1;
    }
    return report(cases, options) ? 0 : 2;
}

const polar::bench::Registrar registrar{{
    "present",
    "The game in a real window (X display): share of a core and memory at the title and in a busy wave, "
    "framebuffer against OpenGL",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--warmup", options->warmup, "Seconds the game runs before it is measured", {0.5, 60.0})
            .showDefault();
        sub.option("--seconds", options->seconds, "Seconds measured for each path and screen", {1.0, 600.0})
            .showDefault();
        sub.option("--csv", options->csv, "Also write path,screen,core_percent,peak_mib to this CSV file")
            .outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
