// polarcade-bench render: Polarcade's software renderer against two others, drawing the same
// rotated, scaled, alpha-blended 64×64 sprites into the same 1280×720 ARGB canvas in the same run:
// SDL2's own software renderer, and pixman (the compositor under cairo and the X server:
// pixman_image_composite32, OP_OVER, an affine transform per sprite, nearest filtering).
// Each frame is a clear plus N sprite draws; Polarcade records them in a DrawList and draws it on
// 1, 2, … threads (--threads). The table shows medians over frames of wall-clock time (the CSV's
// ms_per_frame) and of the process's CPU time (every thread's), and the mean difference per channel
// between each other renderer's picture and Polarcade's (they differ in rounding and sampling).
// Polarcade runs with each span kernel of --kernels in turn (default: the one drawSprite picks), and
// its rows show the CPU cycles per destination pixel: CPU time × the clock in /proc/cpuinfo over the
// pixels of every sprite's spans (transparent texels included), the distance to the kernel's floor.
#include <SDL.h>
#include <pixman.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "amdahl.h"
#include "bench.h"
#include "polar/platform/image_file.h"
#include "polar/render/render.h"
#include "polar/tasks.h"
#include "render/sprite_span.h"
#include "render_floor.h"
#include "render_scene.h"

namespace {

using namespace polar;
using namespace polar::render;
using polar::bench::CpuClock;
using polar::bench::Summary;
using polar::bench::timeInto;
using polar::bench::Timings;

using namespace polar::bench::render_scene;

// The CPU's clock in MHz as /proc/cpuinfo gives it (the first "cpu MHz" line), or 0 when unknown.
double cpuMegahertz() {
    std::ifstream in("/proc/cpuinfo");
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("cpu MHz", 0) == 0) {
            const std::size_t colon = line.find(':');
            if (colon != std::string::npos) return std::atof(line.c_str() + colon + 1);
        }
    return 0.0;
}

// Destination pixels of a frame: the pixels of every sprite's spans, counted by a kernel that draws
// nothing.
std::int64_t countedPixels = 0;
void countPixels(const detail::SpanBatch& batch) {
    for (int n = 0; n < batch.spanCount; ++n) countedPixels += batch.spans[n].count;
}
std::int64_t destinationPixels(Canvas& canvas, const Image& sprite, const View& view,
                               const std::vector<Placement>& placements) {
    countedPixels = 0;
    for (const Placement& p : placements) {
        const Transform t = placementTransform(view, p);
        detail::drawSpriteWith(canvas, sprite, Mat3(view.matrix() * t.matrix()), {}, countPixels);
    }
    return countedPixels;
}

// One frame: recorded into `list`, then drawn on `tasks` (null: this thread).
void drawPolarcade(Canvas& canvas, DrawList& list, TaskSystem* tasks, const Image& sprite, const View& view,
                   const std::vector<Placement>& placements) {
    recordScene(list, sprite, view, placements);
    list.draw(canvas, tasks);
}

// pixman over a canvas's pixels (both are premultiplied ARGB8888), and the sprite as a pixman
// source with nearest filtering; transparent outside the image (pixman's default repeat, none).
struct Pixman {
    pixman_image_t* target = nullptr;
    pixman_image_t* sprite = nullptr;
    pixman_color_t background{};
    pixman_image_t* fill = nullptr;

    Pixman(Canvas& canvas, const Image& image) {
        target = pixman_image_create_bits(PIXMAN_a8r8g8b8, canvas.width(), canvas.height(), canvas.row(0),
                                          canvas.pitch());
        // pixman reads a source only; the cast is its C signature.
        auto* texels = const_cast<std::uint32_t*>(image.premultiplied());
        sprite = pixman_image_create_bits(PIXMAN_a8r8g8b8, image.width(), image.height(), texels,
                                          image.width() * 4);
        if (sprite) pixman_image_set_filter(sprite, PIXMAN_FILTER_NEAREST, nullptr, 0);
        // 16-bit channels: 0xXX → 0xXXXX.
        background = {std::uint16_t(kBackground.r * 257), std::uint16_t(kBackground.g * 257),
                      std::uint16_t(kBackground.b * 257), 0xFFFF};
        fill = pixman_image_create_solid_fill(&background);
    }
    ~Pixman() {
        for (pixman_image_t* image : {target, sprite, fill})
            if (image) pixman_image_unref(image);
    }
    Pixman(const Pixman&) = delete;
    Pixman& operator=(const Pixman&) = delete;
    bool ok() const { return target && sprite && fill; }
};

void drawPixman(Pixman& px, const Image& image, const View& view, const std::vector<Placement>& placements) {
    const int width = pixman_image_get_width(px.target), height = pixman_image_get_height(px.target);
    pixman_image_composite32(PIXMAN_OP_SRC, px.fill, nullptr, px.target, 0, 0, 0, 0, 0, 0, width, height);
    const double hw = image.width() / 2.0, hh = image.height() / 2.0;
    for (const Placement& p : placements) {
        const Transform t = placementTransform(view, p);
        // Texel → canvas: M · B, where B maps texel (u, v) (y down) to bound space (u − w/2, h/2 − v).
        const Mat3 m = view.matrix() * t.matrix();
        pixman_f_transform forward{};
        const double b[3][3] = {{1, 0, -hw}, {0, -1, hh}, {0, 0, 1}};
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) {
                double sum = 0;
                for (int k = 0; k < 3; ++k) sum += m(r, k) * b[k][c];
                forward.m[r][c] = sum;
            }
        // pixman maps destination pixels to source points, so it takes the inverse (16.16 fixed).
        pixman_f_transform inverse{};
        pixman_transform fixed{};
        if (!pixman_f_transform_invert(&inverse, &forward) ||
            !pixman_transform_from_pixman_f_transform(&fixed, &inverse))
            continue;
        pixman_image_set_transform(px.sprite, &fixed);
        // Destination: the canvas bounding box of the corners, clipped to the canvas. With the source
        // origin equal to the destination's, the transform sees canvas coordinates.
        double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
        for (double u : {0.0, 2 * hw})
            for (double v : {0.0, 2 * hh}) {
                const double x = forward.m[0][0] * u + forward.m[0][1] * v + forward.m[0][2];
                const double y = forward.m[1][0] * u + forward.m[1][1] * v + forward.m[1][2];
                x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
            }
        const int left = std::max(0, int(std::floor(x0))), top = std::max(0, int(std::floor(y0)));
        const int right = std::min(width, int(std::ceil(x1))), bottom = std::min(height, int(std::ceil(y1)));
        if (left >= right || top >= bottom) continue;
        pixman_image_composite32(PIXMAN_OP_OVER, px.sprite, nullptr, px.target, left, top, 0, 0, left, top,
                                 right - left, bottom - top);
    }
}

void drawSdl(SDL_Renderer* renderer, SDL_Texture* texture, const std::vector<Placement>& placements) {
    SDL_SetRenderDrawColor(renderer, kBackground.r, kBackground.g, kBackground.b, 255);
    SDL_RenderClear(renderer);
    for (const Placement& p : placements) {
        const float side = float(kSpriteSide * p.scale);
        const SDL_FRect dst{float(p.x) - side / 2, float(p.y) - side / 2, side, side};
        // SDL's angle turns clockwise on the screen.
        SDL_RenderCopyExF(renderer, texture, nullptr, &dst, -p.degrees, nullptr, SDL_FLIP_NONE);
    }
    SDL_RenderFlush(renderer);
}

// Mean absolute difference per channel between two canvases of the same size (alpha ignored).
double meanDifference(const Canvas& a, const Canvas& b) {
    double sum = 0;
    for (int y = 0; y < a.height(); ++y) {
        const auto* ra = reinterpret_cast<const std::uint8_t*>(a.row(y));
        const auto* rb = reinterpret_cast<const std::uint8_t*>(b.row(y));
        for (int x = 0; x < a.width() * 4; ++x)
            if (x % 4 != 3) sum += std::abs(int(ra[x]) - int(rb[x]));
    }
    return sum / (double(a.width()) * a.height() * 3);
}

// An SDL surface over a canvas's own pixels (same ARGB8888 layout), so SDL's renderer draws into
// the canvas and reads sprites from one; free it before the canvas goes.
SDL_Surface* surfaceOver(Canvas& canvas) {
    return SDL_CreateRGBSurfaceWithFormatFrom(canvas.row(0), canvas.width(), canvas.height(), 32,
                                              canvas.pitch(), SDL_PIXELFORMAT_ARGB8888);
}

struct Options {
    std::vector<int> counts{250, 500, 1000, 2000, 4000};
    std::vector<int> threads{1, 2};
    std::vector<std::string> kernels;  // empty: the active one
    bool floor = false;
    int frames = 15;
    std::string only = "all", csv, png;
};

// The floor table: the frame drawn as in the race (a DrawList on this thread) with each part of
// the AVX2 kernel in turn (render_floor.h), frame by frame; medians of wall and CPU time, and CPU
// cycles per destination pixel.
int runFloor(const Options& options, double megahertz) {
    const std::vector<detail::NamedKernel> parts = polar::bench::floorKernels();
    if (parts.empty()) {
        std::fprintf(stderr, "--floor: this CPU has no AVX2; the floor is measured on the AVX2 kernel\n");
        return 2;
    }
    const detail::NamedKernel chosen = detail::activeSpanKernel();
    const Image sprite = Image::fromCanvas(makeSpriteArt());
    Canvas canvas(kWidth, kHeight);
    const View view(kWidth, kHeight);
    DrawList list;
    std::printf(
        "floor: the frame on one thread with parts of the AVX2 kernel only; median of %d frames; "
        "clock %.0f MHz\n",
        options.frames, megahertz);
    std::printf("%8s %-16s %9s %9s %7s\n", "sprites", "part", "ms", "cpu ms", "cyc/px");
    for (int count : options.counts) {
        const std::vector<Placement> placements = makePlacements(count);
        const std::int64_t pixels = destinationPixels(canvas, sprite, view, placements);
        std::vector<Timings> times(parts.size());
        for (int f = -1; f < options.frames; ++f)  // frame −1 warms up
            for (std::size_t k = 0; k < parts.size(); ++k) {
                detail::useSpanKernel(parts[k]);
                Timings warm;
                timeInto(f < 0 ? warm : times[k], CpuClock::Process,
                         [&] { drawPolarcade(canvas, list, nullptr, sprite, view, placements); });
            }
        detail::useSpanKernel(chosen);
        for (std::size_t k = 0; k < parts.size(); ++k) {
            const double c = times[k].cpu().median;
            std::printf("%8d %-16s %9.2f %9.2f %7.2f\n", count, parts[k].name, times[k].wall().median, c,
                        megahertz > 0 ? c * 1e3 * megahertz / double(pixels) : 0.0);
        }
        std::fflush(stdout);
    }
    std::printf(
        "row setup alone: everything but the kernel (recording, clearing, each sprite's and row's setup);\n"
        "stores alone: a constant stored over the spans; fetch + store: texels fetched and stored, no\n"
        "blend; blend alone: a constant blended over the spans, no fetch; avx2 (all): the real kernel.\n");
    return 0;
}

// SDL's software renderer drawing into a canvas of its own, with the sprite as its texture.
struct SdlRace {
    Canvas target{kWidth, kHeight};
    SDL_Surface* targetSurface = nullptr;
    SDL_Surface* artSurface = nullptr;
    SDL_Renderer* renderer = nullptr;
    SDL_Texture* texture = nullptr;

    explicit SdlRace(Canvas& art) {
        targetSurface = surfaceOver(target);
        artSurface = surfaceOver(art);
        renderer = targetSurface ? SDL_CreateSoftwareRenderer(targetSurface) : nullptr;
        texture = renderer && artSurface ? SDL_CreateTextureFromSurface(renderer, artSurface) : nullptr;
        if (texture) SDL_SetTextureBlendMode(texture, SDL_BLENDMODE_BLEND);
    }
    ~SdlRace() {
        if (texture) SDL_DestroyTexture(texture);
        if (renderer) SDL_DestroyRenderer(renderer);
        if (artSurface) SDL_FreeSurface(artSurface);
        if (targetSurface) SDL_FreeSurface(targetSurface);
    }
    SdlRace(const SdlRace&) = delete;
    SdlRace& operator=(const SdlRace&) = delete;
};

// What the race runs: which renderers, and Polarcade's runs (every kernel at every thread count,
// run r = kernel · threadCounts + thread).
struct RacePlan {
    bool ours = false, sdl = false, pixman = false;
    std::vector<std::string> kernels;
    std::vector<int> threads;
    std::size_t runs() const { return kernels.size() * threads.size(); }
    const std::string& kernelOf(std::size_t r) const { return kernels[r / threads.size()]; }
    int threadsOf(std::size_t r) const { return threads[r % threads.size()]; }
};

// A Polarcade frame's phases, wall ms: recording the list (the calling thread), setting the sprites
// up and drawing the bands (DrawList::lastTimes).
struct FramePhases {
    std::vector<double> record, setup, bands;
};

// One count's frames: each Polarcade run (and its phases), SDL and pixman.
struct CountTimes {
    std::vector<Timings> ours;
    std::vector<FramePhases> phases;
    Timings sdl, pixman;
};

// The kernels named by --kernels (default: the active one), or nothing after a message when this
// CPU lacks one.
std::optional<std::vector<std::string>> chooseKernels(const Options& options) {
    std::vector<std::string> kernels = options.kernels;
    const std::string defaultKernel = detail::activeSpanKernel().name;
    if (kernels.empty()) kernels.push_back(defaultKernel);
    for (const std::string& name : kernels)
        if (!detail::chooseSpanKernel(name)) {
            std::string known;
            for (const detail::NamedKernel& k : detail::spanKernels()) known += std::string(" ") + k.name;
            std::fprintf(stderr, "--kernels: no span kernel '%s' on this CPU; expected one of:%s\n",
                         name.c_str(), known.c_str());
            return std::nullopt;
        }
    detail::chooseSpanKernel(defaultKernel);
    return kernels;
}

// The race state that lives across counts: the canvases, the list, one pool per thread count (1
// means no pool: the list draws on this thread), SDL's renderer and pixman.
struct Racers {
    Canvas art = makeSpriteArt();
    Image sprite = Image::fromCanvas(art);
    Canvas canvas{kWidth, kHeight};
    View view{kWidth, kHeight};
    DrawList list;
    std::vector<std::unique_ptr<ThreadPool>> pools;
    SdlRace sdl{art};
    Canvas pixmanTarget{kWidth, kHeight};
    Pixman pixman{pixmanTarget, sprite};

    explicit Racers(const std::vector<int>& threads) {
        list.setTiming(true);
        for (int n : threads) pools.push_back(n > 1 ? std::make_unique<ThreadPool>(n) : nullptr);
    }
};

// Untimed frames warm the caches (and the list's memory), then the renderers alternate frame by
// frame, Polarcade with each kernel at each thread count in turn.
CountTimes raceOneCount(Racers& racers, const RacePlan& plan, const std::vector<Placement>& placements,
                        int frames) {
    // Each phase is timed apart too, into `phases` (null: untimed).
    auto drawOurs = [&](std::size_t r, FramePhases* phases) {
        detail::chooseSpanKernel(plan.kernelOf(r));
        const polar::bench::Stopwatch watch(CpuClock::None);
        recordScene(racers.list, racers.sprite, racers.view, placements);
        const double record = watch.wallMs();
        racers.list.draw(racers.canvas, racers.pools[r % plan.threads.size()].get());
        if (!phases) return;
        const DrawList::Times& t = racers.list.lastTimes();
        phases->record.push_back(record);
        phases->setup.push_back(double(t.setupNanoseconds) * 1e-6);
        phases->bands.push_back(double(t.bandsNanoseconds) * 1e-6);
    };
    auto drawTheSdl = [&] { drawSdl(racers.sdl.renderer, racers.sdl.texture, placements); };
    auto drawThePixman = [&] { drawPixman(racers.pixman, racers.sprite, racers.view, placements); };
    const std::size_t runs = plan.runs();
    if (plan.ours)
        for (std::size_t r = 0; r < runs; ++r) drawOurs(r, nullptr);
    if (plan.sdl) drawTheSdl();
    if (plan.pixman) drawThePixman();
    CountTimes times;
    times.ours.resize(runs);
    times.phases.resize(runs);
    for (int f = 0; f < frames; ++f) {
        if (plan.ours)
            for (std::size_t r = 0; r < runs; ++r)
                timeInto(times.ours[r], CpuClock::Process, [&] { drawOurs(r, &times.phases[r]); });
        if (plan.sdl) timeInto(times.sdl, CpuClock::Process, drawTheSdl);
        if (plan.pixman) timeInto(times.pixman, CpuClock::Process, drawThePixman);
    }
    return times;
}

// A run's frame as its phases one after another (medians of wall ms), beside the same at 1 thread.
std::vector<polar::bench::PhaseTime> phasesOf(const FramePhases& one, const FramePhases& many) {
    using polar::bench::median;
    return {{"record", median(one.record), median(many.record)},
            {"setup", median(one.setup), median(many.setup)},
            {"bands", median(one.bands), median(many.bands)}};
}

// The frame's serial fraction (its phases' serial parts over their sum) and the gains at 16 and 64
// threads, from the phases' fits at `threads`.
struct FrameFit {
    double serialFraction = 0.0, gain16 = 1.0, gain64 = 1.0;
};
FrameFit fitFrame(const std::vector<polar::bench::PhaseTime>& phases, int threads) {
    using namespace polar::bench;
    FrameFit fit;
    double serial = 0.0, total = 0.0;
    for (const PhaseTime& p : phases) {
        serial += fitAmdahl(p.oneMs, p.manyMs, threads).serialFraction * p.oneMs;
        total += p.oneMs;
    }
    fit.serialFraction = total > 0.0 ? serial / total : 0.0;
    fit.gain16 = projectedGain(phases, threads, kProjectedThreads[0]);
    fit.gain64 = projectedGain(phases, threads, kProjectedThreads[1]);
    return fit;
}

// For every Polarcade run at N > 1 threads, when the first thread count is 1: each phase's Amdahl fit
// against the same kernel at 1 thread, and the gains it allows.
void printAmdahlTables(const std::vector<std::pair<int, CountTimes>>& measured, const RacePlan& plan) {
    if (plan.threads.empty() || plan.threads[0] != 1 || plan.threads.size() < 2) return;
    const std::size_t threadCounts = plan.threads.size();
    for (const auto& [count, times] : measured)
        for (std::size_t i = 0; i < plan.runs(); ++i) {
            const int threads = plan.threads[i % threadCounts];
            if (threads == 1) continue;
            const std::size_t base = i - i % threadCounts;
            char title[160];
            std::snprintf(title, sizeof title,
                          "\nAmdahl, %d sprites, %s, 1 -> %d threads (wall medians):", count,
                          plan.kernelOf(i).c_str(), threads);
            polar::bench::printAmdahl(title, phasesOf(times.phases[base], times.phases[i]), threads);
            std::printf(
                "cpu ms per frame: %.3f at 1 thread, %.3f at %d (the work the threads add: %+.1f %%)\n",
                times.ours[base].cpu().median, times.ours[i].cpu().median, threads,
                100.0 * (times.ours[i].cpu().median / times.ours[base].cpu().median - 1.0));
        }
    std::printf(
        "record: DrawList calls on the calling thread; setup: the sprites set up (DrawList::lastTimes);\n"
        "bands: the bands of rows drawn. s: the serial fraction that gives the measured speed-up by\n"
        "Amdahl's law (* clamped to [0, 1]); serial ms: s x the 1-thread time; gain 16, 64: what that s\n"
        "allows at 16 and 64 threads; sum: the phases together, each by its own fit. A ceiling: the fit\n"
        "cannot see what only more threads cost (memory, wake-ups, more bands per sprite).\n");
}

std::string formatted(bool shown, const char* format, double value) {
    char text[32] = "-";
    if (shown) std::snprintf(text, sizeof text, format, value);
    return text;
}

// The table's rows for one count, and its CSV rows.
void reportCount(int count, const CountTimes& times, const RacePlan& plan, const Racers& racers,
                 std::int64_t pixels, double megahertz, polar::bench::Csv& csv) {
    using polar::bench::Fixed;
    const double b = times.sdl.wall().median, bCpu = times.sdl.cpu().median;
    const double c = times.pixman.wall().median, cCpu = times.pixman.cpu().median;
    const double dSdl = plan.ours && plan.sdl ? meanDifference(racers.canvas, racers.sdl.target) : 0.0;
    const double dPix = plan.ours && plan.pixman ? meanDifference(racers.canvas, racers.pixmanTarget) : 0.0;
    const std::size_t threadCounts = plan.threads.size();
    for (std::size_t i = 0; i < (plan.ours ? plan.runs() : 1); ++i) {
        const Summary wall = plan.ours ? times.ours[i].wall() : Summary{};
        const double a = wall.median, aCpu = plan.ours ? times.ours[i].cpu().median : 0.0;
        // Speed-up over the same kernel at the first thread count.
        const double one = plan.ours ? times.ours[i - i % threadCounts].wall().median : 0.0;
        const char* kernel = plan.ours ? plan.kernelOf(i).c_str() : "-";
        const int threads = plan.threads[i % threadCounts];
        const bool cycles = plan.ours && megahertz > 0 && pixels > 0;
        std::printf("%8d %7d %-11s %12s %9s %10s %7s %9s %9s %10s %10s %9s %9s %6s %6s %7s\n", count,
                    plan.ours ? threads : 1, kernel, formatted(plan.ours, "%.2f", a).c_str(),
                    formatted(plan.ours && a > 0, "%.1f×", one / a).c_str(),
                    formatted(plan.ours, "%.2f", aCpu).c_str(),
                    formatted(cycles, "%.2f", aCpu * 1e3 * megahertz / double(pixels)).c_str(),
                    formatted(plan.sdl, "%.2f", b).c_str(), formatted(plan.pixman, "%.2f", c).c_str(),
                    formatted(plan.sdl, "%.2f", bCpu).c_str(), formatted(plan.pixman, "%.2f", cCpu).c_str(),
                    formatted(plan.ours && plan.sdl && a > 0, "%.1f×", b / a).c_str(),
                    formatted(plan.ours && plan.pixman && a > 0, "%.1f×", c / a).c_str(),
                    formatted(plan.ours && plan.sdl, "%.2f", dSdl).c_str(),
                    formatted(plan.ours && plan.pixman, "%.2f", dPix).c_str(),
                    formatted(plan.ours, "%.1f%%", wall.spreadPercent()).c_str());
        if (!plan.ours) continue;
        using polar::bench::median;
        const FramePhases& mine = times.phases[i];
        const std::size_t base = i - i % threadCounts;
        if (threads == 1 || plan.threads[0] != 1) {
            csv.row("polarcade", count, a, threads, kernel, Fixed{aCpu, 4}, Fixed{median(mine.record), 4},
                    Fixed{median(mine.setup), 4}, Fixed{median(mine.bands), 4}, "", "", "");
            continue;
        }
        const FrameFit fit = fitFrame(phasesOf(times.phases[base], mine), threads);
        csv.row("polarcade", count, a, threads, kernel, Fixed{aCpu, 4}, Fixed{median(mine.record), 4},
                Fixed{median(mine.setup), 4}, Fixed{median(mine.bands), 4}, Fixed{fit.serialFraction, 4},
                Fixed{fit.gain16, 2}, Fixed{fit.gain64, 2});
    }
    std::fflush(stdout);
    if (plan.sdl) csv.row("sdl", count, b, 1, "-", Fixed{bCpu, 4}, "", "", "", "", "", "");
    if (plan.pixman) csv.row("pixman", count, c, 1, "-", Fixed{cCpu, 4}, "", "", "", "", "", "");
}

// Each count's last frame of every renderer run, into the --png folder; false after a message.
bool savePictures(int count, const RacePlan& plan, const Racers& racers, const std::string& folder) {
    const std::pair<const char*, const Canvas*> pictures[] = {
        {"polarcade", plan.ours ? &racers.canvas : nullptr},
        {"sdl", plan.sdl ? &racers.sdl.target : nullptr},
        {"pixman", plan.pixman ? &racers.pixmanTarget : nullptr}};
    for (auto [name, target] : pictures) {
        if (!target) continue;
        const std::string path = folder + "/render-" + name + "-" + std::to_string(count) + ".png";
        if (auto error = savePng(*target, path)) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return false;
        }
    }
    return true;
}

int run(const Options& options) {
    const std::string& only = options.only;
    RacePlan plan;
    plan.ours = only == "all" || only == "both" || only == "polarcade";
    plan.sdl = only == "all" || only == "both" || only == "sdl";
    plan.pixman = only == "all" || only == "pixman";
    plan.threads = options.threads;
    std::optional<std::vector<std::string>> kernels = chooseKernels(options);
    if (!kernels) return 2;
    plan.kernels = *kernels;
    const double megahertz = cpuMegahertz();
    if (options.floor) return runFloor(options, megahertz);

    Racers racers(options.threads);
    if (!racers.sdl.texture) {
        std::fprintf(stderr, "SDL software renderer: %s\n", SDL_GetError());
        return 1;
    }
    if (!racers.pixman.ok()) {
        std::fprintf(stderr, "pixman: could not create its images\n");
        return 1;
    }

    std::printf(
        "%d×%d canvas, %d×%d sprites rotated, scaled 0.5–1.5 and alpha-blended; median of %d frames; "
        "clock %.0f MHz\n",
        kWidth, kHeight, kSpriteSide, kSpriteSide, options.frames, megahertz);
    std::printf("%8s %7s %-11s %12s %8s %10s %7s %9s %9s %10s %10s %8s %8s %6s %6s %7s\n", "sprites",
                "threads", "kernel", "polarcade ms", "speed-up", "cpu ms", "cyc/px", "sdl ms", "pixman ms",
                "sdl cpu", "pixman cpu", "vs sdl", "vs pixm", "|d|sdl", "|d|pix", "spread");
    std::fflush(stdout);
    polar::bench::Csv csv(
        "renderer,sprites,ms_per_frame,threads,kernel,cpu_ms,record_ms,setup_ms,bands_ms,serial_fraction,"
        "gain16,"
        "gain64");
    std::int64_t lastPixels = 0;
    std::vector<std::pair<int, CountTimes>> measured;  // for the Amdahl tables after the race's
    for (int count : options.counts) {
        const std::vector<Placement> placements = makePlacements(count);
        lastPixels = destinationPixels(racers.canvas, racers.sprite, racers.view, placements);
        const CountTimes times = raceOneCount(racers, plan, placements, options.frames);
        reportCount(count, times, plan, racers, lastPixels, megahertz, csv);
        measured.emplace_back(count, times);
        if (!options.png.empty() && !savePictures(count, plan, racers, options.png)) return 2;
    }
    std::printf(
        "speed-up: Polarcade at the first thread count over this one, same kernel; cpu: the process's\n"
        "CPU time, every thread; cyc/px: cpu ms × clock over the frame's %lld destination pixels at the\n"
        "last count (the sprites' spans); vs sdl, vs pixm: their wall time over Polarcade's at this count;\n"
        "|d|: mean difference per channel from Polarcade's picture; spread: the middle half of Polarcade's\n"
        "frame times (interquartile range) over their median.\n",
        static_cast<long long>(lastPixels));
    if (plan.ours) printAmdahlTables(measured, plan);
    if (!options.csv.empty() && !csv.write(options.csv)) return 2;
    return 0;
}

const polar::bench::Registrar registrar{{
    "render",
    "Sprites per frame: Polarcade's software renderer on 1, 2, … threads beside SDL2's and pixman",
    [](polar::cli::Command& sub) -> std::function<int()> {
        auto options = std::make_shared<Options>();
        sub.option("--sprites", options->counts, "Sprite counts to measure", {1, 1000000})
            .delimiter(',')
            .showDefault();
        sub.option("--threads", options->threads,
                   "Thread counts for Polarcade's renderer, e.g. 1,2 (1: no worker threads)", {1, 256})
            .delimiter(',')
            .showDefault();
        sub.option("--kernels", options->kernels,
                   "Polarcade's span kernels to run in turn, e.g. sse2,avx2 (default: the one "
                   "drawSprite picks on this CPU; scalar, sse2, avx2, avx2-gather, avx2-runs)")
            .delimiter(',');
        sub.flag("--floor", options->floor,
                 "Instead of the race, time the parts of the AVX2 kernel alone (row setup, stores, "
                 "fetches, blend) over the same spans: the floor under the frame time");
        sub.option("--frames", options->frames, "Timed frames per count and renderer", {1, 100000})
            .showDefault();
        sub.option("--renderer", options->only,
                   "Which renderers to run: all, polarcade, sdl, pixman, or both (polarcade and sdl)")
            .oneOf({"all", "both", "polarcade", "sdl", "pixman"})
            .showDefault();
        sub.option(
               "--csv", options->csv,
               "Also write renderer,sprites,ms_per_frame,threads,kernel,cpu_ms,record_ms,setup_ms,bands_ms,"
               "serial_fraction,gain16,gain64 to this CSV file (sdl and pixman always run on 1 thread)")
            .outputFile();
        sub.option("--png", options->png,
                   "Save each count's last frame of every renderer run into this folder")
            .existingFolder();
        return [options] { return run(*options); };
    },
}};

}  // namespace
