// polarcade-bench replay: how long verifying a replay takes. The demo pilot plays 60 s (3600 ticks)
// and is recorded exactly as the game records a player; the recording is then read and verified
// headless (every tick's trace, every checkpoint) without drawing, and again with a frame drawn
// after every tick (drawGame at alpha 1 into the 640×360 canvas, as checkpoint screenshots are).
// The rest of the table splits the time: reading, the start (scene and bounds files), simulation
// alone and with the per-tick state hash, and drawing alone. Medians over runs, wall clock and thread CPU
// time, and the spread of the wall times.
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "app/hud/game_drawing.h"
#include "bench.h"
#include "cli.h"
#include "demo_replay.h"
#include "files/assets.h"
#include "replay/replay.h"

namespace {

using namespace polar;
using namespace polar::game;
namespace fs = std::filesystem;
using polar::bench::Summary;

struct Options {
    int runs = 11;
    int ticks = 3600;
    std::uint64_t seed = 16;
    std::string csv;
};

struct Row {
    const char* name;
    Summary wall, cpu;
    double goalMs;  // 0: no goal
};

// `work` once untimed, then `runs` times on the wall clock and this thread's CPU clock.
template <class Work>
Row measure(const char* name, int runs, double goalMs, Work&& work) {
    const polar::bench::Timings t = polar::bench::repeat({1, runs, polar::bench::CpuClock::Thread}, work);
    return {name, t.wall(), t.cpu(), goalMs};
}

// What the verifications saw: desyncs and the most objects at once.
struct Verified {
    int failures = 0;
    std::size_t objects = 0;
};

// Every case, on the recording in `path` (already read into `replay`).
std::vector<Row> measureCases(const std::string& path, const Replay& replay, const AssetFs& assets, int runs,
                              Verified& verified) {
    auto verify = [&](bool draw) {
        Result<Replay> again = readReplay(path);
        Result<ReplayPlayer> player = ReplayPlayer::start(*again, assets);
        SpriteCache sprites(assets);
        Particles particles;
        render::Canvas canvas(kScreenWidth, kScreenHeight);
        while (!player->done()) {
            if (player->step()) ++verified.failures;
            verified.objects = std::max(verified.objects, player->game().world().objects().size());
            if (!draw) continue;
            particles.spawnFor(player->game().events(), player->game().tickCount());
            particles.tick(1.0 / 60);
            drawGame(canvas, player->game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        }
    };
    auto fresh = [&] { return std::move(*Game::create(configFor(replay, assets))); };

    std::vector<Row> rows;
    rows.push_back(measure("verify, no drawing", runs, 100, [&] { verify(false); }));
    rows.push_back(measure("verify + a frame every tick", runs, 3000, [&] { verify(true); }));
    rows.push_back(measure("  read and parse the file", runs, 0, [&] { (void)readReplay(path); }));
    rows.push_back(measure("  start: scene and bounds", runs, 0, [&] { (void)fresh(); }));
    rows.push_back(measure("  simulate only (Game::tick)", runs, 0, [&] {
        Game game = fresh();
        for (Actions a : replay.actions) game.tick(a);
    }));
    rows.push_back(measure("  simulate + Game::hash per tick", runs, 0, [&] {
        Game game = fresh();
        std::uint64_t sink = 0;
        for (Actions a : replay.actions) {
            game.tick(a);
            sink += game.hash();
        }
        if (sink == 42) std::printf(" ");
    }));
    Game end = fresh();
    for (Actions a : replay.actions) end.tick(a);
    SpriteCache sprites(assets);
    Particles particles;
    render::Canvas canvas(kScreenWidth, kScreenHeight);
    rows.push_back(measure("  drawGame x ticks (last state)", runs, 0, [&] {
        for (std::size_t i = 0; i < replay.actions.size(); ++i)
            drawGame(canvas, end, sprites, Interpolation{}, particles, 1.0, DrawOptions{});
    }));
    return rows;
}

bool report(const std::vector<Row>& rows, const Replay& replay, const Verified& verified,
            const Options& options) {
    std::printf(
        "%d ticks (%.0f s) of the demo pilot, seed %llu, up to %zu objects; %zu checkpoints; median of %d "
        "runs\n",
        options.ticks, options.ticks / 60.0, static_cast<unsigned long long>(options.seed), verified.objects,
        replay.checkpoints.size(), options.runs);
    std::printf("%-32s  %9s  %9s  %7s  %9s  %s\n", "case", "wall ms", "cpu ms", "spread", "goal ms", "");
    polar::bench::Csv csv("case,wall_ms,cpu_ms,goal_ms,spread_pct");
    for (const Row& row : rows) {
        std::printf("%-32s  %9.2f  %9.2f  %6.1f%%  ", row.name, row.wall.median, row.cpu.median,
                    row.wall.spreadPercent());
        if (row.goalMs > 0)
            std::printf("%9.0f  %s\n", row.goalMs, row.wall.median <= row.goalMs ? "met" : "MISSED");
        else
            std::printf("%9s\n", "");
        std::string name = row.name;
        name.erase(0, name.find_first_not_of(' '));
        csv.row(name, row.wall.median, row.cpu.median, row.goalMs, row.wall.spreadPercent());
    }
    std::printf("spread: the middle half of the runs' wall times (interquartile range) over the median\n");
    if (verified.failures) {
        std::fprintf(stderr, "the recording did not verify (%d desyncs): the game is not deterministic\n",
                     verified.failures);
        return false;
    }
    return options.csv.empty() || csv.write(options.csv);
}

int run(const Options& options) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "replay: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const AssetFs assets(*root);
    const fs::path folder =
        fs::temp_directory_path() / ("polarcade-bench-replay-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(folder, ec);
    const std::string path = (folder / "demo.replay").string();
    if (auto error = polar::bench::recordDemo(path, assets, options.seed, options.ticks, 30)) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        fs::remove_all(folder, ec);
        return 1;
    }
    Result<Replay> recorded = readReplay(path);
    if (!recorded) {
        std::fprintf(stderr, "%s\n", recorded.error().message().c_str());
        fs::remove_all(folder, ec);
        return 1;
    }
    Verified verified;
    const std::vector<Row> rows = measureCases(path, *recorded, assets, options.runs, verified);
    fs::remove_all(folder, ec);
    return report(rows, *recorded, verified, options) ? 0 : 1;
}

const polar::bench::Registrar registrar{{
    "replay",
    "Verifying 60 s of recorded demo play headless, without drawing and with a frame every tick",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--runs", options->runs, "Timed runs per case (the median is shown)", {1, 1000})
            .showDefault();
        sub.option("--ticks", options->ticks, "Ticks of demo play to record and verify", {60, 1000000})
            .showDefault();
        sub.option("--seed", options->seed, "The demo game's seed").showDefault();
        sub.option("--csv", options->csv,
                   "Also write case,wall_ms,cpu_ms,goal_ms,spread_pct to this CSV file")
            .outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
