// polarcade-bench accuracy: what each accuracy level costs in time and what it gets wrong, measured
// against the pixel truth of the game's own sprites.
//
// For every pair of sprites (each with itself too) it draws random placements near contact: both
// objects get a random rotation and scale (from 0.5 to 2, a third of them non-uniform up to 2:1, a
// quarter of the axes mirrored), and B approaches A along a random line through A's position.
//   - D* is the true contact distance along that line: coming from far, the first distance at which
//     the opaque pixels (alpha > 127) overlap (steps of 1/4 px, then bisection).
//   - D_level is the same for a level's pair test.
//   - Penetration error = |D_level − D*|, in world pixels: how far a level lets B sink in (or stops
//     it short) on the way in. Mean and max over all placements.
//   - fp/fn: at four distances D* + δ per placement, δ uniform in [−3, 3] px, the level's verdict
//     against the pixel truth: a false positive is a hit the pixels do not have, a false negative a
//     miss where they overlap; both in % of all such tests.
//   - ns per pair: the median over repetitions of testPair on 1024 of those tests, poses built
//     beforehand (once per object per step in the world); the test includes mapping world directions
//     into bound space. The pose itself is timed apart.
// A sprite whose opaque pixels surround a transparent centre (the cave) is a container, as the game
// uses it: its pairs are container pairs, the other sprite moves out from the container's centre,
// D* is the first distance (going out) at which its pixels touch the wall's pixels, and a level's
// D_level the first at which its container rule hits. Two containers are never paired.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "accuracy_pairs.h"
#include "accuracy_plot.h"
#include "accuracy_sprites.h"
#include "accuracy_timing.h"
#include "bench.h"
#include "cli.h"
#include "narrow_phase/pair_test.h"
#include "polar/atomic_file.h"
#include "polar/collision.h"

namespace polar::bench {
namespace {

struct Level {
    std::string name;
    Accuracy accuracy;
    bool plain = false;  // through the plain formulas (the baseline)
    std::uint32_t colour = 0xff000000;
};

struct Row {
    std::string name;
    double fpPct = 0, fnPct = 0, meanErr = 0, maxErr = 0, ns = 0;
    std::uint32_t colour = 0;
    // The penetration error split by kind of pair: [contact, container], mean and max.
    double kindMean[2] = {0, 0}, kindMax[2] = {0, 0};
};

// The levels compared, in the table's order, with their colours in the plot.
std::vector<Level> levelsCompared() {
    return {
        {"circle", Accuracy::Circle, false, 0xff1f77b4},
        {"nearest", Accuracy::Nearest, false, 0xffff7f0e},
        {"chord", Accuracy::Chord, false, 0xff2ca02c},
        {"bounds", Accuracy::Bounds, false, 0xff17becf},
        {"all-radii", Accuracy::AllRadii, false, 0xff9467bd},
        {"exact", Accuracy::Exact, false, 0xffd62728},
        {"chord-plain", Accuracy::Chord, true, 0xff7f7f7f},
    };
}

// The sprites to test: the game's in `spritesDir`, or the stand-ins (with --stand-ins, or when that
// folder holds none and was not chosen); `source` says which. Nothing, after a message, on bad input.
std::optional<std::vector<Sprite>> chooseSprites(const std::string& spritesDir, bool spritesChosen,
                                                 bool standIns, std::string& source) {
    std::string problem;
    std::vector<Sprite> sprites = standIns ? std::vector<Sprite>{} : loadSprites(spritesDir, problem);
    if (!problem.empty()) {
        std::fprintf(stderr, "%s\n", problem.c_str());
        return std::nullopt;
    }
    source = "the game's sprites in " + spritesDir;
    if (sprites.empty() && !standIns && spritesChosen) {
        std::fprintf(stderr,
                     "%s: no sprite with a .bounds.json beside it; expected a folder of NAME.png with "
                     "NAME.bounds.json\n",
                     spritesDir.c_str());
        return std::nullopt;
    }
    if (sprites.empty()) {
        sprites = standInSprites();
        source = standIns ? "stand-in sprites drawn by the benchmark (--stand-ins)"
                          : "stand-in sprites drawn by the benchmark (no sprite with a .bounds.json in " +
                                spritesDir + ")";
    }
    return sprites;
}

// A level's errors against the pixel truth: the penetration error over the placements (all, and by
// kind of pair), fp and fn over the tests near contact.
Row measureLevel(const Level& level, const std::vector<Sprite>& sprites,
                 const std::vector<Placement>& placements, const std::vector<Sample>& samples) {
    std::fprintf(stderr, "  level %s\n", level.name.c_str());
    auto hitAt = [&](const Placement& p, double d) {
        ObjectPose a = poseA(sprites, p), b = poseB(sprites, p, d);
        return level.plain ? testPairPlain(a, b, level.accuracy).hit : testPair(a, b, level.accuracy).hit;
    };
    Row row;
    row.name = level.name;
    row.colour = level.colour;
    double errSum = 0, kindSum[2] = {0, 0};
    std::size_t kindCount[2] = {0, 0};
    for (const Placement& p : placements) {
        auto hit = [&](double d) { return hitAt(p, d); };
        std::optional<double> contact =
            p.container ? firstWallContact(hit, p.far, 1.0) : firstContact(hit, p.far, 0.25);
        double err = std::fabs(contact.value_or(0.0) - p.truth);
        errSum += err;
        row.maxErr = std::max(row.maxErr, err);
        int kind = p.container ? 1 : 0;
        kindSum[kind] += err;
        ++kindCount[kind];
        row.kindMax[kind] = std::max(row.kindMax[kind], err);
    }
    row.meanErr = placements.empty() ? 0 : errSum / static_cast<double>(placements.size());
    for (int k = 0; k < 2; ++k)
        row.kindMean[k] = kindCount[k] ? kindSum[k] / static_cast<double>(kindCount[k]) : 0;
    std::size_t fp = 0, fn = 0;
    for (const Sample& s : samples) {
        bool hit = hitAt(placements[s.placement], s.distance);
        fp += hit && !s.truth;
        fn += !hit && s.truth;
    }
    row.fpPct =
        100.0 * static_cast<double>(fp) / static_cast<double>(std::max<std::size_t>(samples.size(), 1));
    row.fnPct =
        100.0 * static_cast<double>(fn) / static_cast<double>(std::max<std::size_t>(samples.size(), 1));
    return row;
}

// Each level's ns per pair, the best of three medians. Timing last and in one pass, so the levels
// are measured side by side under the same conditions.
void timeLevels(TimedSet& timed, const std::vector<Level>& levels, std::vector<Row>& rows) {
    for (int pass = 0; pass < 3; ++pass) {
        for (std::size_t i = 0; i < levels.size(); ++i) {
            double ns = timeLevel(timed, levels[i].accuracy, levels[i].plain);
            rows[i].ns = pass == 0 ? ns : std::min(rows[i].ns, ns);  // best of three medians
        }
    }
}

// chord one pair at a time (testPair instead of testPairs), the best of three medians.
double timeChordOneAtATime(TimedSet& timed, const std::vector<Level>& levels) {
    const Level& chordLevel =
        *std::find_if(levels.begin(), levels.end(), [](const Level& l) { return l.name == "chord"; });
    double chordOneAtATime = timeLevel(timed, chordLevel.accuracy, chordLevel.plain, true);
    for (int pass = 1; pass < 3; ++pass)
        chordOneAtATime =
            std::min(chordOneAtATime, timeLevel(timed, chordLevel.accuracy, chordLevel.plain, true));
    return chordOneAtATime;
}

// The table of errors and ns per pair, and the penetration error by kind of pair.
void printErrors(const std::vector<Row>& rows, const std::vector<Placement>& placements, std::size_t skipped,
                 std::size_t sampleCount, std::size_t timedCount) {
    std::printf(
        "%zu placements kept (%zu had no pixel contact on their line), %zu tests near contact (%zu "
        "timed)\n\n",
        placements.size(), skipped, sampleCount, timedCount);
    std::printf("%-12s %8s %8s %12s %11s %12s\n", "level", "fp %", "fn %", "mean err px", "max err px",
                "ns per pair");
    for (const Row& r : rows)
        std::printf("%-12s %8.2f %8.2f %12.3f %11.3f %12.1f\n", r.name.c_str(), r.fpPct, r.fnPct, r.meanErr,
                    r.maxErr, r.ns);
    std::size_t containerPlacements = static_cast<std::size_t>(
        std::count_if(placements.begin(), placements.end(), [](const Placement& p) { return p.container; }));
    if (containerPlacements > 0) {
        std::printf("\npenetration error by kind of pair (%zu contact, %zu container placements)\n",
                    placements.size() - containerPlacements, containerPlacements);
        std::printf("%-12s %14s %13s %16s %15s\n", "level", "contact mean", "contact max", "container mean",
                    "container max");
        for (const Row& r : rows)
            std::printf("%-12s %14.3f %13.3f %16.3f %15.3f\n", r.name.c_str(), r.kindMean[0], r.kindMax[0],
                        r.kindMean[1], r.kindMax[1]);
    }
}

// The timings beside the table: chord against the plain formulas and exact, one pair at a time, by
// kind of pair, the floor and the pose.
void printTimings(const std::vector<Row>& rows, double chordOneAtATime,
                  const std::array<KindTiming, 3>& kinds, const FloorTiming& floor, double poseNs,
                  std::size_t timedCount) {
    auto rowNamed = [&](const std::string& name) -> const Row& {
        return *std::find_if(rows.begin(), rows.end(), [&](const Row& r) { return r.name == name; });
    };
    std::printf(
        "\nchord: %.1f ns with the tables vs %.1f ns through the plain formulas (%.1fx); exact / chord = "
        "%.1fx\n",
        rowNamed("chord").ns, rowNamed("chord-plain").ns, rowNamed("chord-plain").ns / rowNamed("chord").ns,
        rowNamed("exact").ns / rowNamed("chord").ns);
    std::printf("chord one pair at a time (testPair instead of testPairs): %.1f ns\n", chordOneAtATime);
    std::printf("chord by kind of pair (each kind timed alone):\n");
    for (const KindTiming& kind : kinds)
        std::printf("  %-24s %5.1f%% of the timed pairs  %6.1f ns\n", kind.name,
                    100.0 * static_cast<double>(kind.a.size()) / static_cast<double>(timedCount), kind.ns);
    std::printf(
        "one bound each, one pair at a time: reading the poses and writing the outcome %.1f ns; with the two "
        "sector look-ups %.1f ns\n",
        floor.readWriteNs, floor.lookUpNs);
    std::printf(
        "pose (once per object per step: L, |det L| and its sign, sigma max, condition number, single-radii "
        "offset): %.1f ns\n",
        poseNs);
}

// Writes the table as CSV; false after a message when it cannot.
bool writeCsv(const std::vector<Row>& rows, const std::string& csvPath) {
    Csv csv("level,fp_pct,fn_pct,mean_err_px,max_err_px,ns_per_pair");
    for (const Row& r : rows)
        csv.row(r.name, Fixed{r.fpPct, 4}, Fixed{r.fnPct, 4}, Fixed{r.meanErr, 4}, Fixed{r.maxErr, 4},
                Fixed{r.ns, 2});
    return csv.write(csvPath);
}

// Plots mean penetration error against ns per pair; false after a message when it cannot.
bool writePlot(const std::vector<Row>& rows, std::size_t placementCount, const std::string& plotPath) {
    std::vector<PlotPoint> points;
    for (const Row& r : rows) points.push_back({r.name, r.ns, r.meanErr, r.colour});
    PlotSpec spec;
    spec.title = "accuracy levels: error against cost (" + std::to_string(placementCount) + " placements)";
    spec.xLabel = "ns per pair test";
    spec.yLabel = "mean penetration error (px)";
    if (std::optional<Error> e = saveScatterPlot(plotPath, spec, points)) {
        std::fprintf(stderr, "%s\n", e->message().c_str());
        return false;
    }
    std::printf("wrote %s\n", plotPath.c_str());
    return true;
}

int run(std::size_t placementCount, std::uint64_t seed, const std::string& spritesDir, bool spritesChosen,
        bool standIns, const std::string& csvPath, const std::string& plotPath) {
    std::string source;
    std::optional<std::vector<Sprite>> chosen = chooseSprites(spritesDir, spritesChosen, standIns, source);
    if (!chosen) return cli::kBadInput;
    const std::vector<Sprite>& sprites = *chosen;
    std::vector<SpritePair> pairs = spritePairs(sprites);
    if (pairs.empty()) {
        std::fprintf(stderr,
                     "%s: no pair of sprites to test; expected at least one sprite that is not a container\n",
                     spritesDir.c_str());
        return cli::kBadInput;
    }

    std::printf("accuracy: %zu sprites (%s), %zu pairs, %zu placements, seed %llu\n", sprites.size(),
                source.c_str(), pairs.size(), placementCount, static_cast<unsigned long long>(seed));
    for (const Sprite& s : sprites)
        if (s.container)
            std::printf("container (pixels surround a transparent centre): %s\n", s.name.c_str());

    // Placements and their pixel truth.
    std::mt19937_64 rng(seed);
    std::size_t skipped = 0;
    std::vector<Placement> placements = placeNearContact(sprites, pairs, placementCount, rng, skipped);

    // The tests near contact: four distances per placement, and their pixel truth.
    std::vector<Sample> samples = samplesNearContact(sprites, placements, rng);
    const std::vector<Level> levels = levelsCompared();
    TimedSet timed = timedSetOf(sprites, placements, samples);

    std::vector<Row> rows;
    for (const Level& level : levels) rows.push_back(measureLevel(level, sprites, placements, samples));
    timeLevels(timed, levels, rows);
    double chordOneAtATime = timeChordOneAtATime(timed, levels);
    std::array<KindTiming, 3> kinds = timeChordByKind(timed);
    FloorTiming floor = timeFloor(timed, kinds[0]);
    double poseNs = timePose(timed);

    printErrors(rows, placements, skipped, samples.size(), timed.a.size());
    printTimings(rows, chordOneAtATime, kinds, floor, poseNs, timed.a.size());
    if (!csvPath.empty() && !writeCsv(rows, csvPath)) return cli::kBadInput;
    if (!plotPath.empty() && !writePlot(rows, placements.size(), plotPath)) return cli::kBadInput;
    return 0;
}

Registrar registrar{Command{
    "accuracy",
    "Accuracy levels against the pixel truth of the game's sprites: fp/fn %, penetration error, ns per pair",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto csv = std::make_shared<std::string>();
        auto plot = std::make_shared<std::string>();
        auto dir = std::make_shared<std::string>(std::string(POLAR_ASSET_DIR) + "/sprites");
        auto count = std::make_shared<std::size_t>(3000);
        auto seed = std::make_shared<std::uint64_t>(20240601);
        auto standIns = std::make_shared<bool>(false);
        sub.option("--csv", *csv, "Write level,fp_pct,fn_pct,mean_err_px,max_err_px,ns_per_pair to this file")
            .outputFile();
        sub.option("--plot", *plot, "Write a PNG plot of mean penetration error against ns per pair")
            .outputFile();
        const polar::cli::Option sprites =
            sub.option("--sprites", *dir, "Folder of sprites (NAME.png with NAME.bounds.json beside it)");
        sub.option("--placements", *count, "Random placements near contact", {1, 10000000});
        sub.option("--seed", *seed, "Seed of the placements");
        sub.flag("--stand-ins", *standIns, "Use the benchmark's own drawn sprites instead of the game's");
        return [=] { return run(*count, *seed, *dir, sprites.given(), *standIns, *csv, *plot); };
    }}};

}  // namespace
}  // namespace polar::bench
