// A window on the engine: a round wall holds a few lumpy rocks that drift, spin and bounce, drawn
// by the software renderer and shown in a Window. Esc or closing the window quits.
//   polar-example-windowed                                      in a window, until closed
//   polar-example-windowed --headless --ticks 240 --screenshot out.png    no window: the frame as PNG
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <thread>

#include "polar/bound_outline.h"
#include "polar/platform/platform.h"
#include "polar/render/render.h"
#include "polar/world.h"

using namespace polar;

constexpr int kWidth = 320, kHeight = 180;  // canvas pixels; the view makes them world units too
constexpr double kTick = 1.0 / 60.0;        // seconds per step

// A rock of about `size` units: eight radii joined by straight edges.
BoundsPtr rockBounds(double size) {
    const double lumps[8] = {1.0, 0.8, 0.95, 0.7, 1.0, 0.85, 0.75, 0.9};
    std::vector<DegreeSample> samples;
    for (int k = 0; k < 8; ++k) samples.push_back({45.0 * k, size * lumps[k]});
    return std::make_shared<const Bounds>(Bounds{Bound::fromDegrees(Vec2::Zero(), samples, true)});
}

World makeWorld() {
    World world({kEffectPhysics | kEffectCollisions | kEffectResponse | kEffectContainers, 0.9});
    ObjectDef wall;  // a container holds objects inside it; as a ghost, hits never move it
    wall.name = "wall";
    wall.bounds = std::make_shared<const Bounds>(Bounds{Bound(Vec2::Zero(), 84.0)});
    wall.transform.setPosition({160, 90});
    wall.flags = kCollisions | kContainer | kGhost;
    world.add(wall);
    struct Start {
        Vec2 position, velocity;  // world units, and per second
        double size;
    };
    const Start starts[] = {{{110, 90}, {70, 20}, 18},
                            {{200, 110}, {-50, -35}, 22},
                            {{160, 40}, {25, 60}, 14},
                            {{150, 130}, {-40, -20}, 12},
                            {{215, 65}, {-20, 45}, 16}};
    for (const Start& start : starts) {
        ObjectDef rock;
        rock.name = "rock " + std::to_string(world.objects().size());
        rock.bounds = rockBounds(start.size);
        rock.transform.setPosition(start.position);
        rock.velocity = start.velocity;
        rock.spin = 2.1 - 0.6 * double(world.objects().size());  // radians per second
        rock.flags = kPhysics | kCollisions;
        world.add(rock);
    }
    return world;
}

void draw(render::Canvas& canvas, const render::View& view, const World& world) {
    canvas.clear({16, 20, 32, 255});
    for (const GameObject& object : world.objects()) {
        const Mat3 toCanvas = view.matrix() * object.transform.matrix();  // bound space → canvas
        for (const Bound& bound : object.boundsOrEmpty()) {
            const std::vector<Vec2> outline = boundOutline(bound, toCanvas);
            if (!object.has(kContainer)) render::fillPolygon(canvas, outline, {150, 120, 96, 255});
            render::drawPolygon(canvas, outline, object.has(kContainer) ? render::kGray : render::kOrange);
        }
    }
}

// True when the player asks to leave (the window's close button, or Esc); drains the events.
bool quitAsked(platform::Window& window) {
    bool quit = false;
    while (std::optional<platform::Event> event = window.pollEvent()) {
        const auto* key = std::get_if<platform::KeyPressed>(&*event);
        quit |= std::holds_alternative<platform::QuitRequested>(*event) ||
                (key && key->key == platform::Key::Escape);
    }
    return quit;
}

// The command line: --headless, --ticks N, --screenshot FILE, --help.
struct Options {
    bool headless = false;
    long ticks = -1;  // -1: until the window closes (240 when headless)
    const char* screenshot = nullptr;
};
constexpr const char* kUsage =
    "Usage: polar-example-windowed [--headless] [--ticks N] [--screenshot FILE.png]\n"
    "A round wall holds lumpy rocks, stepped at 60 Hz and drawn in a window (Esc quits).\n"
    "  --headless         no window: step N ticks (default 240) off-screen\n"
    "  --ticks N          stop after N ticks\n"
    "  --screenshot FILE  write the last frame to FILE as PNG\n";

// Parses the command line; on bad input or --help prints and returns the exit code to leave with.
std::optional<int> parse(int argc, char** argv, Options& options) {
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        const char* value = i + 1 < argc ? argv[i + 1] : nullptr;
        char* end = nullptr;
        if (arg == "--help" || arg == "-h") {
            std::fputs(kUsage, stdout);
            return 0;
        }
        if (arg == "--headless") {
            options.headless = true;
            continue;
        }
        if (arg == "--ticks" && value) {
            options.ticks = std::strtol(value, &end, 10);
            if (options.ticks > 0 && *end == '\0') {
                ++i;
                continue;
            }
        }
        if (arg == "--screenshot" && value) {
            options.screenshot = argv[++i];
            continue;
        }
        std::fprintf(stderr, "polar-example-windowed: bad option '%s'; expected:\n%s", arg.c_str(), kUsage);
        return 2;
    }
    if (options.headless && options.ticks < 0) options.ticks = 240;
    return std::nullopt;
}

int main(int argc, char** argv) {
    // Init: the command line, the world, the canvas and (unless headless) the window.
    Options options;
    if (std::optional<int> exit = parse(argc, argv, options)) return *exit;
    const bool headless = options.headless;
    const long ticks = options.ticks;
    const char* screenshot = options.screenshot;
    World world = makeWorld();
    render::Canvas canvas(kWidth, kHeight);
    const render::View view(kWidth, kHeight);
    std::unique_ptr<platform::Window> window;
    if (!headless) {
        auto opened = platform::Window::open({"Polar: windowed example", kWidth, kHeight, 3});
        if (!opened) {
            std::fprintf(stderr, "%s (try --headless)\n", opened.error().message().c_str());
            return 1;
        }
        window = std::move(*opened);
    }

    // Loop: update (one fixed step), then draw; paced at 60 steps a second while a window shows it.
    auto due = std::chrono::steady_clock::now();
    for (long tick = 0; ticks < 0 || tick < ticks; ++tick) {
        if (window && quitAsked(*window)) break;
        world.step(kTick);
        if (!window) continue;
        draw(canvas, view, world);
        window->present(canvas);
        std::this_thread::sleep_until(due += std::chrono::microseconds(16667));
    }

    // Shutdown: the last frame into a file if asked; the window closes as it goes out of scope.
    draw(canvas, view, world);
    std::optional<Error> error = screenshot ? render::savePng(canvas, screenshot) : std::nullopt;
    if (error) std::fprintf(stderr, "%s\n", error->message().c_str());
    return error ? 1 : 0;
}
