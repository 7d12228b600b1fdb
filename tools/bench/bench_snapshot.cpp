// polarcade-bench snapshot: how long saving and restoring a state takes, and how many bytes it holds.
// Two worlds: the game's (the demo pilot's cave at its busiest in the second half of 5 minutes, as Game::save
// and World alone) and the scale benchmark's rock field of 10k objects. Each restore alternates between two
// snapshots a second of play apart, so every restore rewrites the state rather than finding it already there.
// Medians and worst of single calls, at 1 thread.
#include <algorithm>
#include <cstdio>
#include <optional>

#include "bench.h"
#include "cli.h"
#include "files/assets.h"
#include "polar/authoring/random_scene.h"
#include "polar/world_snapshot.h"
#include "rules/bot.h"
#include "rules/game.h"

namespace {

using namespace polar;
using namespace polar::game;
using polar::bench::Summary;

// One call at a time on the wall clock only (a call takes microseconds), after 8 untimed ones; in µs.
template <class Work>
Summary timeCalls(int calls, Work&& work) {
    std::vector<double> us = polar::bench::repeat({8, calls, polar::bench::CpuClock::None}, work).wallMs;
    for (double& t : us) t *= 1e3;
    return polar::bench::summarize(std::move(us));
}

struct Row {
    std::string name;
    std::size_t objects = 0;
    std::size_t bytes = 0;
    Summary save{}, restore{};
    double goalUs = 0;
};

struct Options {
    int calls = 2000;
    int ticks = 18000;
    std::uint64_t seed = 16;
    std::size_t rocks = 10000;
    std::string csv;
};

int fail(const std::string& message) {
    std::fprintf(stderr, "snapshot: %s\n", message.c_str());
    return 1;
}

// The demo pilot's game at its busiest in the second half of `ticks` (the most objects in the cave),
// and the same game a second of play later.
struct Subject {
    Game game, later;
};
Result<Subject> busiestGame(const AssetFs& assets, const Options& options) {
    Game::Config config;
    config.reader = assets.reader();
    config.seed = options.seed;
    config.tuning.startLives = 99;
    Result<Game> created = Game::create(config);
    if (!created) return created.error();
    Game play = std::move(*created);
    Bot bot(options.seed);
    std::optional<Game> busiest;
    for (int t = 0; t < options.ticks; ++t) {
        play.tick(bot.decide(play));
        if (2 * t >= options.ticks &&
            (!busiest || play.world().objects().size() > busiest->world().objects().size()))
            busiest = play;
    }
    Game later = *busiest;
    for (int t = 0; t < 60; ++t) later.tick(bot.decide(later));
    return Subject{std::move(*busiest), std::move(later)};
}

// Game::save and Game::restore, each restore alternating between the two snapshots.
std::optional<Row> measureGame(const Subject& subject, int calls) {
    const Game& game = subject.game;
    GameSnapshot a, b, out;
    game.save(a);
    subject.later.save(b);
    Game target = game;
    Row row{"game (Game::save, world and rules)", game.world().objects().size(), a.heldBytes(), {}, {}, 20};
    row.save = timeCalls(calls, [&] { game.save(out); });
    row.restore = timeCalls(calls, [&](int k) {
        if (target.restore(k % 2 ? b : a)) std::abort();
    });
    if (target.restore(a) || target.hash() != game.hash()) return std::nullopt;
    return row;
}

// saveSnapshot and restoreSnapshot on the game's world alone.
std::optional<Row> measureGameWorld(const Subject& subject, int calls) {
    const World& original = subject.game.world();
    WorldSnapshot a, b, out;
    saveSnapshot(original, a);
    saveSnapshot(subject.later.world(), b);
    World world = original;
    Row row{"game's world alone (saveSnapshot)", original.objects().size(), a.heldBytes(), {}, {}, 20};
    row.save = timeCalls(calls, [&] { saveSnapshot(original, out); });
    row.restore = timeCalls(calls, [&](int k) {
        if (restoreSnapshot(world, k % 2 ? b : a)) std::abort();
    });
    if (restoreSnapshot(world, a) || world.hash() != original.hash()) return std::nullopt;
    return row;
}

// The scale benchmark's rock field, a twentieth of the calls (at least 20).
std::optional<Row> measureRockField(const Options& options) {
    World field = buildRockField(options.seed, options.rocks, 3.0, BroadPhase::Grid, 1);
    for (int s = 0; s < 5; ++s) field.step(1.0 / 60);
    WorldSnapshot a, b, out;
    saveSnapshot(field, a);
    World on = field;
    for (int s = 0; s < 60; ++s) on.step(1.0 / 60);
    saveSnapshot(on, b);
    Row row{"rock field (saveSnapshot)", field.objects().size(), a.heldBytes(), {}, {}, 1000};
    const int calls = std::max(20, options.calls / 20);
    row.save = timeCalls(calls, [&] { saveSnapshot(field, out); });
    World target = field;
    row.restore = timeCalls(calls, [&](int k) {
        if (restoreSnapshot(target, k % 2 ? b : a)) std::abort();
    });
    if (restoreSnapshot(target, a) || target.hash() != field.hash()) return std::nullopt;
    return row;
}

bool report(const std::vector<Row>& rows, const Game& game, const Options& options) {
    std::printf(
        "snapshots at 1 thread: the demo pilot's game at its busiest in ticks %d/2…%d (wave %d), seed %llu; "
        "%d calls each\n",
        options.ticks, options.ticks, game.wave(), static_cast<unsigned long long>(options.seed),
        options.calls);
    std::printf("%-36s %8s %8s  %9s %9s  %9s %9s  %7s\n", "case", "objects", "bytes", "save med", "worst",
                "rest. med", "worst", "goal us");
    polar::bench::Csv csv(
        "case,objects,bytes,save_median_us,save_worst_us,restore_median_us,restore_worst_us,goal_us");
    for (const Row& r : rows) {
        const bool met = r.save.median <= r.goalUs && r.restore.median <= r.goalUs;
        std::printf("%-36s %8zu %8zu  %9.2f %9.2f  %9.2f %9.2f  %7.0f %s\n", r.name.c_str(), r.objects,
                    r.bytes, r.save.median, r.save.worst, r.restore.median, r.restore.worst, r.goalUs,
                    met ? "met" : "MISSED");
        csv.row(r.name, r.objects, r.bytes, r.save.median, r.save.worst, r.restore.median, r.restore.worst,
                r.goalUs);
    }
    return options.csv.empty() || csv.write(options.csv);
}

int run(const Options& options) {
    Result<std::string> root = AssetFs::findRoot();
    if (!root) {
        std::fprintf(stderr, "snapshot: %s\n", root.error().message().c_str());
        return polar::cli::kBadInput;
    }
    const AssetFs assets(*root);
    Result<Subject> subject = busiestGame(assets, options);
    if (!subject) return fail(subject.error().message());

    std::vector<Row> rows;
    std::optional<Row> row = measureGame(*subject, options.calls);
    if (!row) return fail("a restored game has another hash");
    rows.push_back(*row);
    if (!(row = measureGameWorld(*subject, options.calls))) return fail("a restored world has another hash");
    rows.push_back(*row);
    if (!(row = measureRockField(options))) return fail("a restored rock field has another hash");
    rows.push_back(*row);

    return report(rows, subject->game, options) ? 0 : 1;
}

const polar::bench::Registrar registrar{{
    "snapshot",
    "Saving and restoring a world: the game's in a late wave and a 10k rock field; times and bytes",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--calls", options->calls, "Timed calls per case of the game (a twentieth for the field)",
                   {20, 1000000})
            .showDefault();
        sub.option("--ticks", options->ticks, "Ticks the demo pilot plays before the game is saved",
                   {1, 1000000})
            .showDefault();
        sub.option("--seed", options->seed, "The demo game's and the rock field's seed").showDefault();
        sub.option("--rocks", options->rocks, "Objects in the rock field", {1, 1000000}).showDefault();
        sub.option("--csv", options->csv, "Also write the table to this CSV file").outputFile();
        return [options] { return run(*options); };
    },
}};

}  // namespace
