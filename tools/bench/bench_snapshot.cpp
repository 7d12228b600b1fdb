// polarcade-bench snapshot: how long saving and restoring a state takes, and how many bytes it holds.
// Two worlds: the game's (the demo pilot's cave at its busiest in the second half of 5 minutes, as Game::save
// and World alone) and the scale benchmark's rock field of 10k objects. Each restore alternates between two
// snapshots a second of play apart, so every restore rewrites the state rather than finding it already there.
// Medians and worst of single calls, at 1 thread.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <functional>
#include <optional>
#include <sstream>

#include "bench.h"
#include "cli.h"
#include "files/assets.h"
#include "median.h"
#include "polar/atomic_file.h"
#include "polar/authoring/random_scene.h"
#include "polar/world_snapshot.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace {

using namespace polar;
using namespace polar::game;

struct Sample {
    double medianUs = 0, worstUs = 0;
};

// Times `calls` calls of `work(k)` one by one (after a few untimed ones).
Sample timeCalls(int calls, const std::function<void(int)>& work) {
    for (int k = 0; k < 8; ++k) work(k);
    std::vector<double> us;
    us.reserve(static_cast<std::size_t>(calls));
    for (int k = 0; k < calls; ++k) {
        auto start = std::chrono::steady_clock::now();
        work(k);
        us.push_back(
            std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
    }
    return {polar::bench::median(us), *std::max_element(us.begin(), us.end())};
}

struct Row {
    std::string name;
    std::size_t objects = 0;
    std::size_t bytes = 0;
    Sample save{}, restore{};
    double goalUs = 0;
};

int fail(const std::string& message) {
    std::fprintf(stderr, "snapshot: %s\n", message.c_str());
    return 1;
}

int run(int calls, int ticks, std::uint64_t seed, std::size_t rocks, const std::string& csvPath) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "snapshot: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    AssetFs assets(*root);
    Game::Config config;
    config.reader = assets.reader();
    config.seed = seed;
    config.tuning.startLives = 99;
    Result<Game> created = Game::create(config);
    if (!created) return fail(created.error().message());
    Game play = std::move(*created);
    Bot bot(seed);
    // The busiest moment of the second half of the game: the most objects in the cave.
    std::optional<Game> busiest;
    for (int t = 0; t < ticks; ++t) {
        play.tick(bot.decide(play));
        if (2 * t >= ticks && (!busiest || play.world().objects().size() > busiest->world().objects().size()))
            busiest = play;
    }
    Game game = std::move(*busiest);
    Game later = game;
    for (int t = 0; t < 60; ++t) later.tick(bot.decide(later));
    std::vector<Row> rows;

    {
        GameSnapshot a, b;
        game.save(a);
        later.save(b);
        Game target = game;
        Row row{
            "game (Game::save, world and rules)", game.world().objects().size(), a.heldBytes(), {}, {}, 0};
        GameSnapshot out;
        row.save = timeCalls(calls, [&](int) { game.save(out); });
        row.restore = timeCalls(calls, [&](int k) {
            if (target.restore(k % 2 ? b : a)) std::abort();
        });
        if (target.restore(a) || target.hash() != game.hash())
            return fail("a restored game has another hash");
        row.goalUs = 20;
        rows.push_back(row);

        WorldSnapshot wa, wb, wout;
        saveSnapshot(game.world(), wa);
        saveSnapshot(later.world(), wb);
        World world = game.world();
        Row worldRow{
            "game's world alone (saveSnapshot)", game.world().objects().size(), wa.heldBytes(), {}, {}, 0};
        worldRow.save = timeCalls(calls, [&](int) { saveSnapshot(game.world(), wout); });
        worldRow.restore = timeCalls(calls, [&](int k) {
            if (restoreSnapshot(world, k % 2 ? wb : wa)) std::abort();
        });
        if (restoreSnapshot(world, wa) || world.hash() != game.world().hash())
            return fail("a restored world has another hash");
        worldRow.goalUs = 20;
        rows.push_back(worldRow);
    }
    {
        World field = buildRockField(seed, rocks, 3.0, BroadPhase::Grid, 1);
        for (int s = 0; s < 5; ++s) field.step(1.0 / 60);
        WorldSnapshot a, b, out;
        saveSnapshot(field, a);
        World on = field;
        for (int s = 0; s < 60; ++s) on.step(1.0 / 60);
        saveSnapshot(on, b);
        Row row{"rock field (saveSnapshot)", field.objects().size(), a.heldBytes(), {}, {}, 0};
        int fieldCalls = std::max(20, calls / 20);
        row.save = timeCalls(fieldCalls, [&](int) { saveSnapshot(field, out); });
        World target = field;
        row.restore = timeCalls(fieldCalls, [&](int k) {
            if (restoreSnapshot(target, k % 2 ? b : a)) std::abort();
        });
        if (restoreSnapshot(target, a) || target.hash() != field.hash())
            return fail("a restored rock field has another hash");
        row.goalUs = 1000;
        rows.push_back(row);
    }

    std::printf(
        "snapshots at 1 thread: the demo pilot's game at its busiest in ticks %d/2…%d (wave %d), seed %llu; "
        "%d calls each\n",
        ticks, ticks, game.wave(), static_cast<unsigned long long>(seed), calls);
    std::printf("%-36s %8s %8s  %9s %9s  %9s %9s  %7s\n", "case", "objects", "bytes", "save med", "worst",
                "rest. med", "worst", "goal us");
    std::ostringstream csv;
    csv << "case,objects,bytes,save_median_us,save_worst_us,restore_median_us,restore_worst_us,goal_us\n";
    for (const Row& r : rows) {
        bool met = r.save.medianUs <= r.goalUs && r.restore.medianUs <= r.goalUs;
        std::printf("%-36s %8zu %8zu  %9.2f %9.2f  %9.2f %9.2f  %7.0f %s\n", r.name.c_str(), r.objects,
                    r.bytes, r.save.medianUs, r.save.worstUs, r.restore.medianUs, r.restore.worstUs, r.goalUs,
                    met ? "met" : "MISSED");
        csv << '"' << r.name << "\"," << r.objects << ',' << r.bytes << ',' << r.save.medianUs << ','
            << r.save.worstUs << ',' << r.restore.medianUs << ',' << r.restore.worstUs << ',' << r.goalUs
            << '\n';
    }
    if (!csvPath.empty()) {
        if (auto error = writeFileAtomically(csvPath, csv.str())) return fail(error->message());
        std::printf("wrote %s\n", csvPath.c_str());
    }
    return 0;
}

const polar::bench::Registrar registrar{{
    "snapshot",
    "Saving and restoring a world: the game's in a late wave and a 10k rock field; times and bytes",
    [](CLI::App& sub) -> std::function<int()> {
        struct Options {
            int calls = 2000;
            int ticks = 18000;
            std::uint64_t seed = 16;
            std::size_t rocks = 10000;
            std::string csv;
        };
        auto options = std::make_shared<Options>();
        sub.add_option("--calls", options->calls,
                       "Timed calls per case of the game (a twentieth for the field)")
            ->check(CLI::Range(20, 1000000))
            ->capture_default_str();
        sub.add_option("--ticks", options->ticks, "Ticks the demo pilot plays before the game is saved")
            ->check(CLI::Range(1, 1000000))
            ->capture_default_str();
        sub.add_option("--seed", options->seed, "The demo game's and the rock field's seed")
            ->capture_default_str();
        sub.add_option("--rocks", options->rocks, "Objects in the rock field")
            ->check(CLI::Range(1, 1000000))
            ->capture_default_str();
        sub.add_option("--csv", options->csv, "Also write the table to this CSV file");
        return [options] {
            return run(options->calls, options->ticks, options->seed, options->rocks, options->csv);
        };
    },
}};

}  // namespace
