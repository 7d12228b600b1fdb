// polarcade-bench seek: how long a seek in a watched replay takes once its keyframes are built. The
// demo pilot plays 10 minutes (36000 ticks, 99 lives), recorded as the game records; the recording
// is played once to build the keyframes (ReplaySeek), then seeks go to random ticks, each followed by
// its drawn frame (drawGame at alpha 1 into the 640×360 canvas, one thread). Medians and worst of the
// whole seek and of its parts: restore, stepping forward, drawing. And the keyframes' memory.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include "app/draw.h"
#include "app/replay_seek.h"
#include "bench.h"
#include "cli.h"
#include "demo_replay.h"
#include "files/assets.h"
#include "median.h"
#include "polar/atomic_file.h"
#include "replay/replay.h"

namespace {

using namespace polar;
using namespace polar::game;
namespace fs = std::filesystem;

double msSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

int run(int seeks, int ticks, std::uint64_t seed, std::uint64_t interval, const std::string& csvPath) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "seek: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    AssetFs assets(*root);
    const fs::path folder =
        fs::temp_directory_path() / ("polarcade-bench-seek-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(folder, ec);
    const std::string path = (folder / "ten-minutes.replay").string();
    auto recordStart = std::chrono::steady_clock::now();
    if (auto error = polar::bench::recordDemo(path, assets, seed, ticks, 99)) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        return 1;
    }
    double recordMs = msSince(recordStart);
    Result<Replay> replay = readReplay(path);
    fs::remove_all(folder, ec);
    if (!replay) {
        std::fprintf(stderr, "%s\n", replay.error().message().c_str());
        return 1;
    }
    Result<ReplayPlayer> player = ReplayPlayer::start(*replay, assets);
    if (!player) {
        std::fprintf(stderr, "%s\n", player.error().message().c_str());
        return 1;
    }
    Particles particles;
    ReplaySeek seek(*player, particles, 1.0 / replay->header.tuning.tickRate, interval);
    auto buildStart = std::chrono::steady_clock::now();
    int desyncs = seek.seek(replay->actions.size()) ? 1 : 0;
    double buildMs = msSince(buildStart);

    SpriteCache sprites(assets);
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    // One untimed frame first: the sprite cache decodes its images on first use, as it would
    // before a player's first seek.
    drawGame(canvas, player->game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
    Rng pick(seed);
    std::vector<double> total, restore, stepping, drawing, stepped;
    for (int k = 0; k < seeks; ++k) {
        std::uint64_t target = pick.below(static_cast<std::uint32_t>(replay->actions.size() + 1));
        auto start = std::chrono::steady_clock::now();
        if (seek.seek(target)) ++desyncs;
        auto drawStart = std::chrono::steady_clock::now();
        drawGame(canvas, player->game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        drawing.push_back(msSince(drawStart));
        total.push_back(msSince(start));
        restore.push_back(seek.lastSeek().restoreMs);
        stepping.push_back(seek.lastSeek().steppingMs);
        stepped.push_back(static_cast<double>(seek.lastSeek().ticks));
    }
    auto worst = [](const std::vector<double>& v) { return *std::max_element(v.begin(), v.end()); };
    const double mib = seek.heldBytes() / (1024.0 * 1024.0);
    std::printf(
        "%d ticks (%.0f min) of the demo pilot, seed %llu, recorded in %.0f ms; keyframes every %llu ticks\n",
        ticks, ticks / 3600.0, static_cast<unsigned long long>(seed), recordMs,
        static_cast<unsigned long long>(seek.interval()));
    std::printf("keyframes: %zu, %.2f MiB (goal 8 MiB: %s), built by playing the replay once in %.0f ms\n",
                seek.keyframes(), mib, mib <= 8.0 ? "met" : "MISSED", buildMs);
    std::printf("%d seeks to random ticks, each with its frame drawn, 1 thread\n", seeks);
    std::printf("%-24s  %9s  %9s  %s\n", "part", "median ms", "worst ms", "");
    std::ostringstream csv;
    csv << "part,median_ms,worst_ms\n";
    auto row = [&](const char* name, const std::vector<double>& v, double goal) {
        std::printf("%-24s  %9.3f  %9.3f  %s\n", name, polar::bench::median(v), worst(v),
                    goal > 0 ? (worst(v) <= goal ? "goal 4 ms: met" : "goal 4 ms: MISSED") : "");
        csv << '"' << name << "\"," << polar::bench::median(v) << ',' << worst(v) << '\n';
    };
    row("seek with its frame", total, 4.0);
    row("  restore", restore, 0);
    row("  stepping", stepping, 0);
    row("  drawing", drawing, 0);
    std::printf("%-24s  %9.0f  %9.0f\n", "ticks stepped", polar::bench::median(stepped), worst(stepped));
    if (desyncs) {
        std::fprintf(stderr, "seek: %d seeks found a desync: the keyframes do not reproduce straight play\n",
                     desyncs);
        return 1;
    }
    if (!csvPath.empty()) {
        if (auto error = writeFileAtomically(csvPath, csv.str())) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 2;
        }
        std::printf("wrote %s\n", csvPath.c_str());
    }
    return 0;
}

const polar::bench::Registrar registrar{{
    "seek",
    "Seeking in a 10-minute replay by keyframes: each seek with its frame; restore, stepping, drawing",
    [](CLI::App& sub) -> std::function<int()> {
        struct Options {
            int seeks = 300;
            int ticks = 36000;
            std::uint64_t seed = 16;
            std::uint64_t interval = ReplaySeek::kDefaultInterval;
            std::string csv;
        };
        auto options = std::make_shared<Options>();
        sub.add_option("--seeks", options->seeks, "Seeks to random ticks")
            ->check(CLI::Range(1, 100000))
            ->capture_default_str();
        sub.add_option("--ticks", options->ticks, "Ticks of demo play to record (36000: 10 minutes)")
            ->check(CLI::Range(60, 1000000))
            ->capture_default_str();
        sub.add_option("--seed", options->seed, "The demo game's seed")->capture_default_str();
        sub.add_option("--interval", options->interval, "Ticks between keyframes")
            ->check(CLI::Range(1, 100000))
            ->capture_default_str();
        sub.add_option("--csv", options->csv, "Also write part,median_ms,worst_ms to this CSV file");
        return [options] {
            return run(options->seeks, options->ticks, options->seed, options->interval, options->csv);
        };
    },
}};

}  // namespace
