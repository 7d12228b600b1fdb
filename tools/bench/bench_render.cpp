// polarcade-bench render: Polarcade's software renderer against SDL2's own software renderer,
// drawing the same rotated, scaled, alpha-blended 64×64 sprites into the same 1280×720 surface in
// the same run. Each frame is a clear plus N sprite draws; the table shows medians over frames of
// wall-clock time (the CSV's ms_per_frame) and of the thread's CPU time, and the mean difference
// per channel between the two renderers' pictures (they differ only in rounding and sampling).
#include <SDL.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "bench.h"
#include "polar/atomic_file.h"
#include "polar/platform/image_file.h"
#include "polar/render/render.h"

namespace {

using namespace polar;
using namespace polar::render;

constexpr int kWidth = 1280;
constexpr int kHeight = 720;
constexpr int kSpriteSide = 64;
const Color kBackground{24, 28, 40, 255};

// A 64×64 sprite with every kind of alpha: an opaque striped core (r < 22), a translucent halo
// fading from alpha 200 to 40 (22 ≤ r < 30) with a brighter nose marking the heading, and fully
// transparent corners (r ≥ 30). By area: 37% opaque, 32% translucent, 31% transparent.
Canvas makeSpriteArt() {
    Canvas art(kSpriteSide, kSpriteSide);
    art.clear(kTransparent);
    for (int y = 0; y < kSpriteSide; ++y)
        for (int x = 0; x < kSpriteSide; ++x) {
            const double dx = x + 0.5 - 32.0, dy = y + 0.5 - 32.0, r = std::sqrt(dx * dx + dy * dy);
            if (r < 22.0) {
                const bool stripe = ((x + y) / 6) % 2 == 0;
                art.setPixel(x, y, stripe ? Color{230, 120, 40, 255} : Color{250, 210, 90, 255});
            } else if (r < 30.0) {
                const auto alpha = std::uint8_t(200.0 - (r - 22.0) * 20.0);
                const bool nose = dx > 0 && std::abs(dy) < 5.0;
                art.setPixel(x, y, nose ? Color{255, 255, 255, alpha} : Color{80, 160, 255, alpha});
            }
        }
    return art;
}

struct Placement {
    double x, y;     // centre on the canvas (y down)
    double degrees;  // counter-clockwise as seen on the screen
    double scale;    // uniform, 0.5 to 1.5
};

// The same pseudo-random placements every run (a 32-bit LCG), spread over the whole canvas and a
// little beyond its edges so clipping is exercised too.
std::vector<Placement> makePlacements(int count) {
    std::uint32_t state = 12345;
    auto next = [&state] {
        state = state * 1664525u + 1013904223u;
        return (state >> 8) / 16777216.0;
    };
    std::vector<Placement> out;
    for (int i = 0; i < count; ++i) {
        Placement p;
        p.x = -32.0 + next() * (kWidth + 64.0);
        p.y = -32.0 + next() * (kHeight + 64.0);
        p.degrees = next() * 360.0;
        p.scale = 0.5 + next();
        out.push_back(p);
    }
    return out;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2.0;
}

// Wall-clock and this thread's CPU time, in milliseconds. On a shared machine the CPU time shows
// the work itself when other processes take turns on the core.
struct Clocks {
    double wall, cpu;
};
Clocks now() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return {std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch())
                .count(),
            t.tv_sec * 1e3 + t.tv_nsec / 1e6};
}
Clocks since(const Clocks& start) {
    const Clocks end = now();
    return {end.wall - start.wall, end.cpu - start.cpu};
}

void drawPolarcade(Canvas& canvas, const Image& sprite, const View& view,
                   const std::vector<Placement>& placements) {
    canvas.clear(kBackground);
    for (const Placement& p : placements) {
        // Canvas y runs down, world y up: the view turns the canvas point back into a world one.
        const Transform t(view.toWorld({p.x, p.y}), degToRad(p.degrees), Vec2(p.scale, p.scale));
        drawSprite(canvas, sprite, view, t);
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

int run(const std::vector<int>& counts, int frames, const std::string& only, const std::string& csvPath,
        const std::string& pngDir) {
    const bool runOurs = only != "sdl", runSdl = only != "polarcade";
    // The CSV is gathered here and written at the end through a temporary file and a rename, so an
    // interrupted run leaves any earlier file whole; its folder is checked before the long work.
    std::ostringstream csv;
    csv << "renderer,sprites,ms_per_frame\n";
    if (!csvPath.empty()) {
        const std::filesystem::path folder = std::filesystem::absolute(csvPath).parent_path();
        std::error_code ec;
        if (!std::filesystem::is_directory(folder, ec)) {
            std::fprintf(stderr, "%s: no folder %s; expected a path in an existing folder\n", csvPath.c_str(),
                         folder.string().c_str());
            return 2;
        }
    }

    Canvas art = makeSpriteArt();
    const Image sprite = Image::fromCanvas(art);
    Canvas canvas(kWidth, kHeight);
    const View view(kWidth, kHeight);

    Canvas sdlTarget(kWidth, kHeight);
    SDL_Surface* targetSurface = surfaceOver(sdlTarget);
    SDL_Surface* artSurface = surfaceOver(art);
    SDL_Renderer* renderer = targetSurface ? SDL_CreateSoftwareRenderer(targetSurface) : nullptr;
    SDL_Texture* texture =
        renderer && artSurface ? SDL_CreateTextureFromSurface(renderer, artSurface) : nullptr;
    if (!texture) {
        std::fprintf(stderr, "SDL software renderer: %s\n", SDL_GetError());
        return 1;
    }
    SDL_SetTextureBlendMode(texture, SDL_BLENDMODE_BLEND);

    std::printf(
        "%d×%d canvas, %d×%d sprites rotated, scaled 0.5–1.5 and alpha-blended; median of %d frames\n",
        kWidth, kHeight, kSpriteSide, kSpriteSide, frames);
    std::printf("%8s  %12s  %12s  %9s  %10s  %10s  %9s  %11s\n", "sprites", "polarcade ms", "sdl ms",
                "speed-up", "cpu ms", "sdl cpu ms", "cpu ratio", "mean |diff|");
    std::fflush(stdout);
    for (int count : counts) {
        const std::vector<Placement> placements = makePlacements(count);
        // Two untimed frames warm the caches, then the renderers alternate frame by frame.
        if (runOurs) drawPolarcade(canvas, sprite, view, placements);
        if (runSdl) drawSdl(renderer, texture, placements);
        std::vector<double> ours, theirs, oursCpu, theirsCpu;
        for (int f = 0; f < frames; ++f) {
            if (runOurs) {
                const Clocks start = now();
                drawPolarcade(canvas, sprite, view, placements);
                const Clocks t = since(start);
                ours.push_back(t.wall);
                oursCpu.push_back(t.cpu);
            }
            if (runSdl) {
                const Clocks start = now();
                drawSdl(renderer, texture, placements);
                const Clocks t = since(start);
                theirs.push_back(t.wall);
                theirsCpu.push_back(t.cpu);
            }
        }
        const double a = runOurs ? median(ours) : 0.0, b = runSdl ? median(theirs) : 0.0;
        const double aCpu = runOurs ? median(oursCpu) : 0.0, bCpu = runSdl ? median(theirsCpu) : 0.0;
        if (runOurs && runSdl)
            std::printf("%8d  %12.2f  %12.2f  %8.1f×  %10.2f  %10.2f  %8.1f×  %11.2f\n", count, a, b, b / a,
                        aCpu, bCpu, bCpu / aCpu, meanDifference(canvas, sdlTarget));
        else
            std::printf("%8d  %12.2f  %12.2f  %9s  %10.2f  %10.2f  %9s  %11s\n", count, a, b, "-", aCpu, bCpu,
                        "-", "-");
        std::fflush(stdout);
        if (runOurs) csv << "polarcade," << count << ',' << a << '\n';
        if (runSdl) csv << "sdl," << count << ',' << b << '\n';
        if (!pngDir.empty()) {
            for (auto [name, target] : {std::pair{"polarcade", &canvas}, std::pair{"sdl", &sdlTarget}}) {
                const std::string path = pngDir + "/render-" + name + "-" + std::to_string(count) + ".png";
                if (auto error = savePng(*target, path)) {
                    std::fprintf(stderr, "%s\n", error->message().c_str());
                    return 2;
                }
            }
        }
    }
    SDL_DestroyTexture(texture);
    SDL_DestroyRenderer(renderer);
    SDL_FreeSurface(artSurface);
    SDL_FreeSurface(targetSurface);
    if (!csvPath.empty()) {
        if (std::optional<Error> error = writeFileAtomically(csvPath, csv.str())) {
            std::fprintf(stderr, "%s\n", error->message().c_str());
            return 2;
        }
        std::printf("wrote %s\n", csvPath.c_str());
    }
    return 0;
}

const polar::bench::Registrar registrar{{
    "render",
    "Sprites per frame: Polarcade's software renderer beside SDL2's software renderer",
    [](CLI::App& sub) -> std::function<int()> {
        struct Options {
            std::vector<int> counts{250, 500, 1000, 2000, 4000};
            int frames = 15;
            std::string only = "both", csv, png;
        };
        auto options = std::make_shared<Options>();
        sub.add_option("--sprites", options->counts, "Sprite counts to measure")
            ->check(CLI::Range(1, 1000000))
            ->capture_default_str();
        sub.add_option("--frames", options->frames, "Timed frames per count and renderer")
            ->check(CLI::Range(1, 100000))
            ->capture_default_str();
        sub.add_option("--renderer", options->only, "Which renderers to run: both, polarcade or sdl")
            ->check(CLI::IsMember({"both", "polarcade", "sdl"}))
            ->capture_default_str();
        sub.add_option("--csv", options->csv, "Also write renderer,sprites,ms_per_frame to this CSV file");
        sub.add_option("--png", options->png,
                       "Save each count's last frame of both renderers into this folder")
            ->check(CLI::ExistingDirectory);
        return [options] {
            return run(options->counts, options->frames, options->only, options->csv, options->png);
        };
    },
}};

}  // namespace
