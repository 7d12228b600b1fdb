// polarcade-bench replay: how long verifying a replay takes. The demo pilot plays 60 s (3600 ticks)
// and is recorded exactly as the game records a player; the recording is then read and verified
// headless (every tick's trace, every checkpoint) without drawing, and again with a frame drawn
// after every tick (drawGame at alpha 1 into the 640×360 canvas, as checkpoint screenshots are).
// The rest of the table splits the time: reading, the start (scene and bounds files), simulation
// alone and with the per-tick state hash, and drawing alone. Medians over runs, wall clock and thread CPU
// time.
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

#include "app/draw.h"
#include "bench.h"
#include "cli.h"
#include "demo_replay.h"
#include "files/assets.h"
#include "polar/atomic_file.h"
#include "replay/replay.h"
#include "rules/bot.h"

namespace {

using namespace polar;
using namespace polar::game;
namespace fs = std::filesystem;

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return t.tv_sec + t.tv_nsec * 1e-9;
}

struct Timing {
    double wallMs = 0, cpuMs = 0;
};

// Runs `work` `runs` times (after one untimed warm-up) and returns the medians.
Timing measure(int runs, const std::function<void()>& work) {
    work();
    std::vector<double> wall, cpu;
    for (int i = 0; i < runs; ++i) {
        auto start = std::chrono::steady_clock::now();
        double cpuStart = cpuSeconds();
        work();
        cpu.push_back((cpuSeconds() - cpuStart) * 1e3);
        wall.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v[v.size() / 2];
    };
    return {median(wall), median(cpu)};
}

int run(int runs, int ticks, std::uint64_t seed, const std::string& csvPath) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "replay: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    AssetFs assets(*root);
    const fs::path folder =
        fs::temp_directory_path() / ("polarcade-bench-replay-" + std::to_string(::getpid()));
    std::error_code ec;
    fs::create_directories(folder, ec);
    const std::string path = (folder / "demo.replay").string();
    if (auto error = polar::bench::recordDemo(path, assets, seed, ticks, 30)) {
        std::fprintf(stderr, "%s\n", error->message().c_str());
        return 1;
    }
    Result<Replay> recorded = readReplay(path);
    if (!recorded) {
        std::fprintf(stderr, "%s\n", recorded.error().message().c_str());
        return 1;
    }
    const Replay& replay = *recorded;
    int failures = 0;
    std::size_t objects = 0;

    auto verify = [&](bool draw) {
        Result<Replay> again = readReplay(path);
        Result<ReplayPlayer> player = ReplayPlayer::start(*again, assets);
        SpriteCache sprites(assets);
        Particles particles;
        render::Canvas canvas(kScreenWidth, kScreenHeight);
        while (!player->done()) {
            if (player->step()) ++failures;
            objects = std::max(objects, player->game().world().objects().size());
            if (!draw) continue;
            particles.spawnFor(player->game().events(), player->game().tickCount());
            particles.tick(1.0 / 60);
            drawGame(canvas, player->game(), sprites, Interpolation{}, particles, 1.0, DrawOptions{});
        }
    };
    auto fresh = [&] { return std::move(*Game::create(configFor(replay, assets))); };

    struct Row {
        const char* name;
        Timing timing;
        double goalMs;  // 0: no goal
    };
    std::vector<Row> rows;
    rows.push_back({"verify, no drawing", measure(runs, [&] { verify(false); }), 100});
    rows.push_back({"verify + a frame every tick", measure(runs, [&] { verify(true); }), 3000});
    rows.push_back({"  read and parse the file", measure(runs, [&] { (void)readReplay(path); }), 0});
    rows.push_back({"  start: scene and bounds", measure(runs, [&] { (void)fresh(); }), 0});
    rows.push_back({"  simulate only (Game::tick)",
                    measure(runs,
                            [&] {
                                Game game = fresh();
                                for (Actions a : replay.actions) game.tick(a);
                            }),
                    0});
    {
        Game end = fresh();
        for (Actions a : replay.actions) end.tick(a);
        rows.push_back({"  simulate + Game::hash per tick",
                        measure(runs,
                                [&] {
                                    Game game = fresh();
                                    std::uint64_t sink = 0;
                                    for (Actions a : replay.actions) {
                                        game.tick(a);
                                        sink += game.hash();
                                    }
                                    if (sink == 42) std::printf(" ");
                                }),
                        0});
        SpriteCache sprites(assets);
        Particles particles;
        render::Canvas canvas(kScreenWidth, kScreenHeight);
        rows.push_back({"  drawGame x ticks (last state)",
                        measure(runs,
                                [&] {
                                    for (std::size_t i = 0; i < replay.actions.size(); ++i)
                                        drawGame(canvas, end, sprites, Interpolation{}, particles, 1.0,
                                                 DrawOptions{});
                                }),
                        0});
    }
    fs::remove_all(folder, ec);

    std::printf(
        "%d ticks (%.0f s) of the demo pilot, seed %llu, up to %zu objects; %zu checkpoints; median of %d "
        "runs\n",
        ticks, ticks / 60.0, static_cast<unsigned long long>(seed), objects, replay.checkpoints.size(), runs);
    std::printf("%-32s  %9s  %9s  %9s  %s\n", "case", "wall ms", "cpu ms", "goal ms", "");
    std::ostringstream csv;
    csv << "case,wall_ms,cpu_ms,goal_ms\n";
    for (const Row& row : rows) {
        std::printf("%-32s  %9.2f  %9.2f  ", row.name, row.timing.wallMs, row.timing.cpuMs);
        if (row.goalMs > 0)
            std::printf("%9.0f  %s\n", row.goalMs, row.timing.wallMs <= row.goalMs ? "met" : "MISSED");
        else
            std::printf("%9s\n", "");
        std::string name = row.name;
        name.erase(0, name.find_first_not_of(' '));
        csv << '"' << name << "\"," << row.timing.wallMs << ',' << row.timing.cpuMs << ',' << row.goalMs
            << '\n';
    }
    if (failures) {
        std::fprintf(stderr, "the recording did not verify (%d desyncs): the game is not deterministic\n",
                     failures);
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
    "replay",
    "Verifying 60 s of recorded demo play headless, without drawing and with a frame every tick",
    [](CLI::App& sub) -> std::function<int()> {
        struct Options {
            int runs = 11;
            int ticks = 3600;
            std::uint64_t seed = 16;
            std::string csv;
        };
        auto options = std::make_shared<Options>();
        sub.add_option("--runs", options->runs, "Timed runs per case (the median is shown)")
            ->check(CLI::Range(1, 1000))
            ->capture_default_str();
        sub.add_option("--ticks", options->ticks, "Ticks of demo play to record and verify")
            ->check(CLI::Range(60, 1000000))
            ->capture_default_str();
        sub.add_option("--seed", options->seed, "The demo game's seed")->capture_default_str();
        sub.add_option("--csv", options->csv, "Also write case,wall_ms,cpu_ms,goal_ms to this CSV file");
        return [options] { return run(options->runs, options->ticks, options->seed, options->csv); };
    },
}};

}  // namespace
