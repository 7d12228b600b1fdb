// polarcade-bench seek: how long a seek in a watched replay takes once its keyframes are built. The
// demo pilot plays 10 minutes (36000 ticks, 99 lives), recorded as the game records; the recording
// is played once to build the keyframes (ReplaySeek), then seeks go to random ticks, each followed by
// its drawn frame (drawGame at alpha 1 into the 640×360 canvas, one thread). Medians and worst of the
// whole seek and of its parts: restore, stepping forward, drawing. And the keyframes' memory.
#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "app/hud/game_drawing.h"
#include "app/theatre/replay_seek.h"
#include "bench.h"
#include "cli.h"
#include "demo_replay.h"
#include "files/assets.h"
#include "replay/replay.h"

namespace {

using namespace polar;
using namespace polar::game;
namespace fs = std::filesystem;
using polar::bench::Stopwatch;
using polar::bench::Summary;

struct Options {
    int seeks = 300;
    int ticks = 36000;
    std::uint64_t seed = 16;
    std::uint64_t interval = ReplaySeek::kDefaultInterval;
    std::string csv;
};

// The demo pilot's recording, read back; how long recording took.
struct Recording {
    Replay replay;
    double recordMs = 0;
};
Result<Recording> recordTenMinutes(const AssetFs& assets, const Options& options) {
    const fs::path folder =
        fs::temp_directory_path() / ("polarcade-bench-seek-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(folder, ec);
    const std::string path = (folder / "ten-minutes.replay").string();
    const Stopwatch recording(polar::bench::CpuClock::None);
    if (auto error = polar::bench::recordDemo(path, assets, options.seed, options.ticks, 99)) {
        fs::remove_all(folder, ec);
        return *error;
    }
    const double recordMs = recording.wallMs();
    Result<Replay> replay = readReplay(path);
    fs::remove_all(folder, ec);
    if (!replay) return replay.error();
    return Recording{std::move(*replay), recordMs};
}

// Every seek's parts, in ms, and the ticks it stepped.
struct Seeks {
    std::vector<double> total, restore, stepping, drawing, stepped;
    int desyncs = 0;
};

// Seeks to random ticks, each followed by its frame, after one untimed frame (the sprite cache
// decodes its images on first use, as it would before a player's first seek).
Seeks measureSeeks(ReplaySeek& seek, const ReplayPlayer& player, Particles& particles, const AssetFs& assets,
                   std::size_t ticks, const Options& options) {
    SpriteCache sprites(assets);
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    drawGame(canvas, player.game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
    Rng pick(options.seed);
    Seeks s;
    for (int k = 0; k < options.seeks; ++k) {
        const std::uint64_t target = pick.below(static_cast<std::uint32_t>(ticks + 1));
        const Stopwatch whole(polar::bench::CpuClock::None);
        if (seek.seek(target)) ++s.desyncs;
        const Stopwatch drawing(polar::bench::CpuClock::None);
        drawGame(canvas, player.game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        s.drawing.push_back(drawing.wallMs());
        s.total.push_back(whole.wallMs());
        s.restore.push_back(seek.lastSeek().restoreMs);
        s.stepping.push_back(seek.lastSeek().steppingMs);
        s.stepped.push_back(static_cast<double>(seek.lastSeek().ticks));
    }
    return s;
}

bool report(const Seeks& s, const ReplaySeek& seek, double recordMs, double buildMs, const Options& options) {
    const double mib = seek.heldBytes() / (1024.0 * 1024.0);
    std::printf(
        "%d ticks (%.0f min) of the demo pilot, seed %llu, recorded in %.0f ms; keyframes every %llu ticks\n",
        options.ticks, options.ticks / 3600.0, static_cast<unsigned long long>(options.seed), recordMs,
        static_cast<unsigned long long>(seek.interval()));
    std::printf("keyframes: %zu, %.2f MiB (goal 8 MiB: %s), built by playing the replay once in %.0f ms\n",
                seek.keyframes(), mib, mib <= 8.0 ? "met" : "MISSED", buildMs);
    std::printf("%d seeks to random ticks, each with its frame drawn, 1 thread\n", options.seeks);
    std::printf("%-24s  %9s  %9s  %8s  %s\n", "part", "median ms", "worst ms", "spread", "");
    polar::bench::Csv csv("part,median_ms,worst_ms,spread_pct");
    auto row = [&](const char* name, const std::vector<double>& v, double goal) {
        const Summary t = polar::bench::summarize(v);
        std::printf("%-24s  %9.3f  %9.3f  %7.1f%%  %s\n", name, t.median, t.worst, t.spreadPercent(),
                    goal > 0 ? (t.worst <= goal ? "goal 4 ms: met" : "goal 4 ms: MISSED") : "");
        csv.row(name, t.median, t.worst, t.spreadPercent());
    };
    row("seek with its frame", s.total, 4.0);
    row("  restore", s.restore, 0);
    row("  stepping", s.stepping, 0);
    row("  drawing", s.drawing, 0);
    const Summary stepped = polar::bench::summarize(s.stepped);
    std::printf("%-24s  %9.0f  %9.0f\n", "ticks stepped", stepped.median, stepped.worst);
    std::printf("spread: the middle half of the seeks (interquartile range) over the median\n");
    if (s.desyncs) {
        std::fprintf(stderr, "seek: %d seeks found a desync: the keyframes do not reproduce straight play\n",
                     s.desyncs);
        return false;
    }
    return options.csv.empty() || csv.write(options.csv);
}

int run(const Options& options) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "seek: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const AssetFs assets(*root);
    Result<Recording> recording = recordTenMinutes(assets, options);
    if (!recording) {
        std::fprintf(stderr, "%s\n", recording.error().message().c_str());
        return 1;
    }
    const Replay& replay = recording->replay;
    Result<ReplayPlayer> player = ReplayPlayer::start(replay, assets);
    if (!player) {
        std::fprintf(stderr, "%s\n", player.error().message().c_str());
        return 1;
    }
    Particles particles;
    ReplaySeek seek(*player, particles, 1.0 / replay.header.tuning.tickRate, options.interval);
    const Stopwatch building(polar::bench::CpuClock::None);
    const int buildDesyncs = seek.seek(replay.actions.size()) ? 1 : 0;
    const double buildMs = building.wallMs();

    Seeks seeks = measureSeeks(seek, *player, particles, assets, replay.actions.size(), options);
    seeks.desyncs += buildDesyncs;
    return report(seeks, seek, recording->recordMs, buildMs, options) ? 0 : 1;
}

const polar::bench::Registrar registrar{{
    "seek",
    "Seeking in a 10-minute replay by keyframes: each seek with its frame; restore, stepping, drawing",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--seeks", options->seeks, "Seeks to random ticks", {1, 100000}).showDefault();
        sub.option("--ticks", options->ticks, "Ticks of demo play to record (36000: 10 minutes)",
                   {60, 1000000})
            .showDefault();
        sub.option("--seed", options->seed, "The demo game's seed").showDefault();
        sub.option("--interval", options->interval, "Ticks between keyframes", {1, 100000}).showDefault();
        sub.option("--csv", options->csv, "Also write part,median_ms,worst_ms,spread_pct to this CSV file")
            .outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
