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
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "accuracy_plot.h"
#include "bench.h"
#include "cli.h"
#include "narrow_phase/pair_test.h"
#include "polar/atomic_file.h"
#include "polar/authoring/pixel_truth.h"
#include "polar/bounds_file.h"
#include "polar/collision.h"
#include "polar/platform/png_io.h"
#include "shapes/outline.h"

namespace polar::bench {
namespace {

struct Sprite {
    std::string name;
    OpaquePixels pixels;
    BoundsPtr bounds;
    bool container = false;
};

// Whether the sprite's opaque pixels surround its transparent centre: walking out from the centre
// in each of 16 directions meets an opaque pixel.
bool surroundsItsCentre(const OpaquePixels& pixels) {
    int x, y;
    pixels.mask().pixelAt(Vec2::Zero(), x, y);
    if (pixels.opaque(x, y)) return false;
    for (int k = 0; k < 16; ++k) {
        Vec2 dir(std::cos(kTwoPi * k / 16), std::sin(kTwoPi * k / 16));
        bool met = false;
        for (double t = 0; t < pixels.boundRadius() && !met; t += 0.5) {
            pixels.mask().pixelAt(t * dir, x, y);
            met = pixels.opaque(x, y);
        }
        if (!met) return false;
    }
    return true;
}

// The game's sprites: every PNG in `dir` with a `.bounds.json` of the same name beside it.
std::vector<Sprite> loadSprites(const std::string& dir, std::string& problem) {
    std::vector<Sprite> sprites;
    std::error_code ec;
    if (!std::filesystem::is_directory(dir, ec)) return sprites;
    std::vector<std::filesystem::path> pngs;
    for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
        if (entry.path().extension() == ".png") pngs.push_back(entry.path());
    std::sort(pngs.begin(), pngs.end());
    for (const auto& png : pngs) {
        std::filesystem::path boundsPath = png;
        boundsPath.replace_extension(".bounds.json");
        if (!std::filesystem::exists(boundsPath)) continue;
        Result<RgbaImage> image = loadPng(png.string());
        if (!image) {
            problem = image.error().message();
            return {};
        }
        Result<BoundsPtr> bounds = loadBounds(boundsPath.string(), diskReader());
        if (!bounds) {
            problem = bounds.error().message();
            return {};
        }
        if ((*bounds)->empty()) continue;
        OpaquePixels pixels(image->alphaMask());
        bool container = surroundsItsCentre(pixels);
        sprites.push_back({png.stem().string(), std::move(pixels), *bounds, container});
    }
    return sprites;
}

// ---- Stand-in sprites, drawn here when the game's are not there (nothing is written to assets/).

AlphaMask drawMask(int width, int height, const std::function<bool(const Vec2&)>& inside) {
    AlphaMask mask;
    mask.width = width;
    mask.height = height;
    mask.alpha.assign(static_cast<std::size_t>(width) * height, 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x)
            mask.alpha[static_cast<std::size_t>(y) * width + x] = inside(mask.pixelCentre(x, y)) ? 255 : 0;
    return mask;
}

// Radii about `centre` whose samples reach where each ray leaves the last opaque pixel within `keep`.
CollisionRadii traceRadii(const OpaquePixels& pixels, const Vec2& centre, int count, bool interpolate,
                          const std::function<bool(const Vec2&)>& keep) {
    std::vector<RadiusSample> samples;
    for (int k = 0; k < count; ++k) {
        double angle = kTwoPi * k / count;
        Vec2 dir(std::cos(angle), std::sin(angle));
        double last = 0.5;
        for (double t = 0; t < 200; t += 0.02) {
            Vec2 p = centre + t * dir;
            int x, y;
            pixels.mask().pixelAt(p, x, y);
            if (keep(p) && pixels.opaque(x, y)) last = t;
        }
        samples.push_back({angle, last + 0.02});
    }
    return CollisionRadii(centre, samples, interpolate);
}

std::vector<Sprite> standInSprites() {
    std::vector<Sprite> sprites;
    auto all = [](const Vec2&) { return true; };
    {  // a lumpy rock, read with the nearest rule (a star of arcs)
        OpaquePixels px(drawMask(52, 48, [](const Vec2& p) {
            double a = std::atan2(p.y(), p.x());
            return p.norm() < 17 + 3.5 * std::sin(3 * a + 1) + 2 * std::cos(5 * a);
        }));
        Bounds b{traceRadii(px, Vec2::Zero(), 32, false, all)};
        sprites.push_back({"rock", px, std::make_shared<const Bounds>(b)});
    }
    {  // a dart: a concave quadrilateral, read by chord
        auto inTriangle = [](const Vec2& p, const Vec2& a, const Vec2& b, const Vec2& c) {
            double d1 = cross(b - a, p - a), d2 = cross(c - b, p - b), d3 = cross(a - c, p - c);
            return (d1 >= 0 && d2 >= 0 && d3 >= 0) || (d1 <= 0 && d2 <= 0 && d3 <= 0);
        };
        OpaquePixels px(drawMask(44, 36, [&](const Vec2& p) {
            return inTriangle(p, Vec2(20, 0), Vec2(-16, 15), Vec2(-9, 0)) ||
                   inTriangle(p, Vec2(20, 0), Vec2(-9, 0), Vec2(-16, -15));
        }));
        Bounds b{traceRadii(px, Vec2::Zero(), 24, true, all)};
        sprites.push_back({"dart", px, std::make_shared<const Bounds>(b)});
    }
    {  // a long bar, three radii along it
        OpaquePixels px(
            drawMask(74, 10, [](const Vec2& p) { return std::fabs(p.x()) < 35 && std::fabs(p.y()) < 3.5; }));
        Bounds b;
        for (double cx : {-24.0, 0.0, 24.0})
            b.push_back(traceRadii(px, Vec2(cx, 0), 16, true,
                                   [cx](const Vec2& p) { return std::fabs(p.x() - cx) <= 12; }));
        sprites.push_back({"bar", px, std::make_shared<const Bounds>(b)});
    }
    return sprites;
}

// ---- Placements

// A uniform double in [0, 1) from the generator's bits (std distributions differ between libraries).
double uniform(std::mt19937_64& rng) {
    return static_cast<double>(rng() >> 11) * 0x1.0p-53;
}

Mat2 randomLinear(std::mt19937_64& rng) {
    double rotation = uniform(rng) * kTwoPi;
    double s = std::exp(std::log(0.5) + uniform(rng) * std::log(4.0));  // 0.5 … 2, log-uniform
    Vec2 scale(s, s);
    if (uniform(rng) < 1.0 / 3) scale.y() = s * std::exp(std::log(0.5) + uniform(rng) * std::log(4.0));
    if (uniform(rng) < 0.25) scale.x() = -scale.x();
    if (uniform(rng) < 0.25) scale.y() = -scale.y();
    return rotationMatrix(rotation) * scale.asDiagonal();
}

struct Placement {
    std::size_t a = 0, b = 0;
    Vec2 position = Vec2::Zero();  // A's; B sits at position + D·dir
    Mat2 la, lb;
    Vec2 dir = Vec2::UnitX();
    double far = 0.0;    // a distance where nothing can touch yet (contact), or surely touches (container)
    double truth = 0.0;  // D*
    bool container = false;  // A holds B
};

// A world circle about the pose's position holding every radii's outline:
// max_k |L·c_k| + maxRadius_k·σmax.
double boundRadiusOf(const ObjectPose& pose) {
    double reach = 0.0;
    for (const CollisionRadii& r : *pose.radii)
        reach = std::max(reach, (pose.linear * r.centre()).norm() + r.maxRadius() * pose.stretchMax);
    return reach;
}

ObjectFlags flagsOf(const Sprite& s) {
    return s.container ? kCollisions | kContainer : kCollisions;
}

// Coming from `far` toward 0 in steps, the first distance at which `hit` holds, refined by bisection.
std::optional<double> firstContact(const std::function<bool(double)>& hit, double far, double step) {
    for (double d = far; d > 0;) {
        double next = std::max(0.0, d - step);
        if (hit(next)) {
            double lo = next, hi = d;  // hit at lo, miss at hi
            for (int i = 0; i < 24; ++i) {
                double mid = 0.5 * (lo + hi);
                (hit(mid) ? lo : hi) = mid;
            }
            return 0.5 * (lo + hi);
        }
        d = next;
    }
    return std::nullopt;
}

// Going out from 0 in steps, the first distance at which `hit` holds (touching the wall), refined.
std::optional<double> firstWallContact(const std::function<bool(double)>& hit, double far, double step) {
    if (hit(0.0)) return 0.0;
    for (double d = 0; d < far;) {
        double next = std::min(far, d + step);
        if (hit(next)) {
            double lo = d, hi = next;  // miss at lo, hit at hi
            for (int i = 0; i < 24; ++i) {
                double mid = 0.5 * (lo + hi);
                (hit(mid) ? hi : lo) = mid;
            }
            return 0.5 * (lo + hi);
        }
        d = next;
    }
    return std::nullopt;
}

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

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

int run(std::size_t placementCount, std::uint64_t seed, const std::string& spritesDir, bool spritesChosen,
        bool standIns, const std::string& csvPath, const std::string& plotPath) {
    // Output folders are checked before the long work, not after it.
    for (const std::string& out : {csvPath, plotPath}) {
        if (out.empty()) continue;
        std::error_code ec;
        std::filesystem::path folder = std::filesystem::absolute(out, ec).parent_path();
        if (ec || !std::filesystem::is_directory(folder, ec)) {
            std::fprintf(stderr, "%s: no folder %s; expected a path in an existing folder\n", out.c_str(),
                         folder.string().c_str());
            return cli::kBadInput;
        }
    }
    std::string problem;
    std::vector<Sprite> sprites = standIns ? std::vector<Sprite>{} : loadSprites(spritesDir, problem);
    if (!problem.empty()) {
        std::fprintf(stderr, "%s\n", problem.c_str());
        return cli::kBadInput;
    }
    std::string source = "the game's sprites in " + spritesDir;
    if (sprites.empty() && !standIns && spritesChosen) {
        std::fprintf(stderr,
                     "%s: no sprite with a .bounds.json beside it; expected a folder of NAME.png with "
                     "NAME.bounds.json\n",
                     spritesDir.c_str());
        return cli::kBadInput;
    }
    if (sprites.empty()) {
        sprites = standInSprites();
        source = standIns ? "stand-in sprites drawn by the benchmark (--stand-ins)"
                          : "stand-in sprites drawn by the benchmark (no sprite with a .bounds.json in " +
                                spritesDir + ")";
    }
    std::vector<std::pair<std::size_t, std::size_t>> pairs;
    for (std::size_t i = 0; i < sprites.size(); ++i)
        for (std::size_t j = i; j < sprites.size(); ++j)
            if (!(sprites[i].container && sprites[j].container)) pairs.emplace_back(i, j);
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
    std::vector<Placement> placements;
    std::size_t skipped = 0;
    for (std::size_t n = 0; n < placementCount; ++n) {
        if (n % 50 == 0) std::fprintf(stderr, "\r  pixel truth: %zu/%zu placements", n, placementCount);
        Placement p;
        std::tie(p.a, p.b) = pairs[n % pairs.size()];
        if (sprites[p.b].container) std::swap(p.a, p.b);  // the container is always A
        p.position = Vec2(200 * uniform(rng) - 100, 200 * uniform(rng) - 100);
        p.la = randomLinear(rng);
        p.lb = randomLinear(rng);
        double angle = uniform(rng) * kTwoPi;
        p.dir = Vec2(std::cos(angle), std::sin(angle));
        const Sprite& sa = sprites[p.a];
        const Sprite& sb = sprites[p.b];
        p.container = sa.container;
        ObjectPose poseA(p.position, p.la, sa.bounds.get(), flagsOf(sa)),
            poseB(p.position, p.lb, sb.bounds.get(), kCollisions);
        double pixelReach = sa.pixels.boundRadius() * LinearMap(p.la).stretchMax +
                            sb.pixels.boundRadius() * LinearMap(p.lb).stretchMax;
        p.far = std::max(pixelReach, boundRadiusOf(poseA) + boundRadiusOf(poseB)) * 1.02 + 1.0;
        auto truthAt = [&](double d) {
            return opaquePixelsOverlap(sa.pixels, p.position, p.la, sb.pixels, p.position + d * p.dir, p.lb);
        };
        std::optional<double> truth =
            p.container ? firstWallContact(truthAt, p.far, 1.0) : firstContact(truthAt, p.far, 0.25);
        if (!truth) {
            ++skipped;
            continue;
        }
        p.truth = *truth;
        placements.push_back(p);
    }
    std::fprintf(stderr, "\r  pixel truth: %zu/%zu placements\n", placementCount, placementCount);

    // The tests near contact: four distances per placement, and their pixel truth.
    struct Sample {
        std::size_t placement;
        double distance;
        bool truth;
    };
    std::vector<Sample> samples;
    for (std::size_t i = 0; i < placements.size(); ++i) {
        const Placement& p = placements[i];
        for (int k = 0; k < 4; ++k) {
            double d = std::max(0.0, p.truth + 6 * uniform(rng) - 3);
            bool truth = opaquePixelsOverlap(sprites[p.a].pixels, p.position, p.la, sprites[p.b].pixels,
                                             p.position + d * p.dir, p.lb);
            samples.push_back({i, d, truth});
        }
    }
    auto poseA = [&](const Placement& p) {
        return ObjectPose(p.position, p.la, sprites[p.a].bounds.get(), flagsOf(sprites[p.a]));
    };
    auto poseB = [&](const Placement& p, double d) {
        return ObjectPose(p.position + d * p.dir, p.lb, sprites[p.b].bounds.get(), kCollisions);
    };

    const std::vector<Level> levels = {
        {"circle", Accuracy::Circle, false, 0xff1f77b4},
        {"nearest", Accuracy::Nearest, false, 0xffff7f0e},
        {"chord", Accuracy::Chord, false, 0xff2ca02c},
        {"bounds", Accuracy::Bounds, false, 0xff17becf},
        {"all-radii", Accuracy::AllRadii, false, 0xff9467bd},
        {"exact", Accuracy::Exact, false, 0xffd62728},
        {"chord-plain", Accuracy::Chord, true, 0xff7f7f7f},
    };

    // Timing set: up to 1024 tests, poses laid out contiguously as the world would have them.
    std::vector<ObjectPose> timedA, timedB;
    for (std::size_t i = 0; i < samples.size() && timedA.size() < 1024; ++i) {
        const Placement& p = placements[samples[i].placement];
        timedA.push_back(poseA(p));
        timedB.push_back(poseB(p, samples[i].distance));
    }
    std::vector<PosePair> timedPairs;
    for (std::size_t i = 0; i < timedA.size(); ++i) timedPairs.push_back({&timedA[i], &timedB[i]});
    std::vector<PairTest> timedTests(timedPairs.size());
    volatile std::size_t sink = 0;
    // Median ns per item of `run`, which handles `count` items (pairs, poses), over 301 repetitions.
    auto nsEach = [&](std::size_t count, auto&& run) {
        std::vector<double> perRep;
        for (int rep = 0; rep < 301 && count > 0; ++rep) {
            auto t0 = std::chrono::steady_clock::now();
            sink = sink + run();
            auto t1 = std::chrono::steady_clock::now();
            perRep.push_back(std::chrono::duration<double, std::nano>(t1 - t0).count() /
                             static_cast<double>(count));
        }
        return perRep.empty() ? 0.0 : median(perRep);
    };
    // The levels run through testPairs, as the world's detector runs them; `oneAtATime` times
    // testPair called pair by pair instead, for comparison.
    auto timeLevel = [&](const Level& level, bool oneAtATime = false) {
        return nsEach(timedA.size(), [&] {
            std::size_t hits = 0;
            if (level.plain) {
                for (std::size_t i = 0; i < timedA.size(); ++i)
                    hits += testPairPlain(timedA[i], timedB[i], level.accuracy).hit;
            } else if (oneAtATime) {
                for (std::size_t i = 0; i < timedA.size(); ++i)
                    hits += testPair(timedA[i], timedB[i], level.accuracy).hit;
            } else {
                testPairs(timedPairs, level.accuracy, timedTests.data());
                for (const PairTest& t : timedTests) hits += t.hit;
            }
            return hits;
        });
    };

    std::vector<Row> rows;
    for (const Level& level : levels) {
        std::fprintf(stderr, "  level %s\n", level.name.c_str());
        auto hitAt = [&](const Placement& p, double d) {
            ObjectPose a = poseA(p), b = poseB(p, d);
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
        rows.push_back(row);
    }
    // Timing last and in one pass, so the levels are measured side by side under the same conditions.
    for (int pass = 0; pass < 3; ++pass) {
        for (std::size_t i = 0; i < levels.size(); ++i) {
            double ns = timeLevel(levels[i]);
            rows[i].ns = pass == 0 ? ns : std::min(rows[i].ns, ns);  // best of three medians
        }
    }
    const Level& chordLevel =
        *std::find_if(levels.begin(), levels.end(), [](const Level& l) { return l.name == "chord"; });
    double chordOneAtATime = timeLevel(chordLevel, true);
    for (int pass = 1; pass < 3; ++pass)
        chordOneAtATime = std::min(chordOneAtATime, timeLevel(chordLevel, true));
    // chord by kind of pair, each kind's poses in arrays of their own: where the average goes.
    struct KindTiming {
        const char* name;
        std::vector<ObjectPose> a, b;
        double ns = 0;
    };
    KindTiming kinds[3] = {
        {"one radii each, contact", {}, {}}, {"several radii, contact", {}, {}}, {"container", {}, {}}};
    for (std::size_t i = 0; i < timedA.size(); ++i) {
        const ObjectPose &a = timedA[i], &b = timedB[i];
        std::size_t kind = ((a.flags | b.flags) & kContainer)             ? 2
                           : a.radii->size() == 1 && b.radii->size() == 1 ? 0
                                                                          : 1;
        kinds[kind].a.push_back(a);
        kinds[kind].b.push_back(b);
    }
    for (KindTiming& kind : kinds) {
        std::vector<PosePair> pairs;
        for (std::size_t i = 0; i < kind.a.size(); ++i) pairs.push_back({&kind.a[i], &kind.b[i]});
        kind.ns = nsEach(pairs.size(), [&] {
            testPairs(pairs, Accuracy::Chord, timedTests.data());
            return static_cast<std::size_t>(timedTests[0].hit);
        });
    }
    // What a chord contact cannot do without, on the single-radii contacts, one pair at a time:
    // reading the two poses, u and both bound-space directions, and writing the 64-byte outcome;
    // then the same with the two sector look-ups (Outline::sectorOf and the sector's fields).
    const std::vector<ObjectPose>&singleA = kinds[0].a, &singleB = kinds[0].b;
    auto floorPass = [&](bool lookUp) {
        for (std::size_t k = 0; k < singleA.size(); ++k) {
            const ObjectPose &a = singleA[k], &b = singleB[k];
            Vec2 u = b.position - a.position + b.onlyCentreOffset - a.onlyCentreOffset;
            Vec2 ea = a.toBound(u), eb = -b.toBound(u);
            PairTest& t = timedTests[k];
            t.normal = u;
            t.distance = ea.x();
            t.ra = a.absDet;
            t.rb = b.absDet;
            t.penetration = eb.y();
            if (lookUp && a.onlyChord && b.onlyChord) {
                double sa = std::fabs(ea.x()) + std::fabs(ea.y()), sb = std::fabs(eb.x()) + std::fabs(eb.y());
                double q = 1.0 / (sa * sb);
                const Outline &oa = *a.onlyChord, &ob = *b.onlyChord;
                const Outline::Sector& secA =
                    oa.sectors()[oa.sectorOf(ea.x(), ea.y(), std::fabs(ea.y()) * sb * q)];
                const Outline::Sector& secB =
                    ob.sectors()[ob.sectorOf(eb.x(), eb.y(), std::fabs(eb.y()) * sa * q)];
                t.ra *= secA.level;
                t.rb *= secB.level;
                t.penetration = secA.nx * ea.x() + secB.ny * eb.y();
            }
            t.hit = ea.y() > eb.x();
        }
        return static_cast<std::size_t>(timedTests[0].hit);
    };
    double readWriteNs = nsEach(singleA.size(), [&] { return floorPass(false); });
    double lookUpNs = nsEach(singleA.size(), [&] { return floorPass(true); });
    double poseNs = nsEach(timedA.size(), [&] {
        double acc = 0;
        for (std::size_t i = 0; i < timedA.size(); ++i) {
            ObjectPose p(timedA[i].position, timedA[i].linear, timedA[i].radii, kCollisions);
            acc += p.absDet + p.onlyCentreOffset.x();
        }
        return static_cast<std::size_t>(acc);
    });

    std::printf(
        "%zu placements kept (%zu had no pixel contact on their line), %zu tests near contact (%zu "
        "timed)\n\n",
        placements.size(), skipped, samples.size(), timedA.size());
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
                    100.0 * static_cast<double>(kind.a.size()) / static_cast<double>(timedA.size()), kind.ns);
    std::printf(
        "one radii each, one pair at a time: reading the poses and writing the outcome %.1f ns; with the two "
        "sector look-ups %.1f ns\n",
        readWriteNs, lookUpNs);
    std::printf(
        "pose (once per object per step: L, |det L| and its sign, sigma max, condition number, single-radii "
        "offset): %.1f ns\n",
        poseNs);

    if (!csvPath.empty()) {
        std::string text = "level,fp_pct,fn_pct,mean_err_px,max_err_px,ns_per_pair\n";
        for (const Row& r : rows) {
            char line[256];
            std::snprintf(line, sizeof line, "%s,%.4f,%.4f,%.4f,%.4f,%.2f\n", r.name.c_str(), r.fpPct,
                          r.fnPct, r.meanErr, r.maxErr, r.ns);
            text += line;
        }
        if (std::optional<Error> e = writeFileAtomically(csvPath, text)) {
            std::fprintf(stderr, "%s\n", e->message().c_str());
            return cli::kBadInput;
        }
        std::printf("wrote %s\n", csvPath.c_str());
    }
    if (!plotPath.empty()) {
        std::vector<PlotPoint> points;
        for (const Row& r : rows) points.push_back({r.name, r.ns, r.meanErr, r.colour});
        PlotSpec spec;
        spec.title =
            "accuracy levels: error against cost (" + std::to_string(placements.size()) + " placements)";
        spec.xLabel = "ns per pair test";
        spec.yLabel = "mean penetration error (px)";
        if (std::optional<Error> e = saveScatterPlot(plotPath, spec, points)) {
            std::fprintf(stderr, "%s\n", e->message().c_str());
            return cli::kBadInput;
        }
        std::printf("wrote %s\n", plotPath.c_str());
    }
    return 0;
}

Registrar registrar{Command{
    "accuracy",
    "Accuracy levels against the pixel truth of the game's sprites: fp/fn %, penetration error, ns per pair",
    [](CLI::App& sub) -> std::function<int()> {
        auto csv = std::make_shared<std::string>();
        auto plot = std::make_shared<std::string>();
        auto dir = std::make_shared<std::string>(std::string(POLAR_ASSET_DIR) + "/sprites");
        auto count = std::make_shared<std::size_t>(3000);
        auto seed = std::make_shared<std::uint64_t>(20240601);
        auto standIns = std::make_shared<bool>(false);
        sub.add_option("--csv", *csv,
                       "Write level,fp_pct,fn_pct,mean_err_px,max_err_px,ns_per_pair to this file");
        sub.add_option("--plot", *plot, "Write a PNG plot of mean penetration error against ns per pair");
        CLI::Option* sprites =
            sub.add_option("--sprites", *dir, "Folder of sprites (NAME.png with NAME.bounds.json beside it)");
        sub.add_option("--placements", *count, "Random placements near contact")
            ->check(CLI::Range(1, 10000000));
        sub.add_option("--seed", *seed, "Seed of the placements");
        sub.add_flag("--stand-ins", *standIns, "Use the benchmark's own drawn sprites instead of the game's");
        return [=] { return run(*count, *seed, *dir, sprites->count() > 0, *standIns, *csv, *plot); };
    }}};

}  // namespace
}  // namespace polar::bench
