// polarcade-render-bench: the render benchmark's scene in the web build, drawn with every span
// kernel the module has (scalar and, with POLAR_WEB_SIMD, simd128) on one thread, in the browser
// (tests/web/page_test.mjs opens it in chromium) or under node. It prints the median frame time of
// each kernel and the ratio, and fails when the kernels' frames differ in any byte: the plain scene
// and the same sprites tinted and faded.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "cli.h"
#include "harness/samples.h"
#include "polar/render/render.h"
#include "render/sprite_span.h"
#include "render_scene.h"

namespace {

using namespace polar;
using namespace polar::bench::render_scene;

struct Options {
    int sprites = 500;
    int frames = 30;
};

double nowMs() {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now().time_since_epoch())
        .count();
}

bool sameBytes(const render::Canvas& a, const render::Canvas& b) {
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            if (a.row(y)[x] != b.row(y)[x]) return false;
    return true;
}

int run(const Options& options) {
    const render::Image sprite = render::Image::fromCanvas(makeSpriteArt());
    const render::View view(kWidth, kHeight);
    const std::vector<Placement> placements = makePlacements(options.sprites);
    const std::vector<render::detail::NamedKernel> kernels = render::detail::spanKernels();
    const std::string active = render::detail::activeSpanKernel().name;
    render::DrawList list;
    std::printf("web render bench: %d sprites of %d×%d on %d×%d, one thread, median of %d frames\n",
                options.sprites, kSpriteSide, kSpriteSide, kWidth, kHeight, options.frames);
    std::printf("%-8s %9s\n", "kernel", "ms/frame");
    std::vector<double> medians;
    std::vector<render::Canvas> plain, styled;
    for (const render::detail::NamedKernel& kernel : kernels) {
        render::detail::chooseSpanKernel(kernel.name);
        render::Canvas canvas(kWidth, kHeight);
        recordScene(list, sprite, view, placements);
        list.draw(canvas);  // warm-up
        std::vector<double> times;
        for (int f = 0; f < options.frames; ++f) {
            const double start = nowMs();
            recordScene(list, sprite, view, placements);
            list.draw(canvas);
            times.push_back(nowMs() - start);
        }
        medians.push_back(bench::median(times));
        std::printf("%-8s %9.2f\n", kernel.name, medians.back());
        plain.push_back(std::move(canvas));
        render::Canvas tinted(kWidth, kHeight);
        recordScene(list, sprite, view, placements, {render::Color{255, 180, 120, 220}, 160});
        list.draw(tinted);
        styled.push_back(std::move(tinted));
    }
    render::detail::chooseSpanKernel(active);
    for (std::size_t k = 1; k < kernels.size(); ++k) {
        std::printf("%s over %s: %.2f× faster\n", kernels[k].name, kernels[0].name, medians[0] / medians[k]);
        if (!sameBytes(plain[k], plain[0]) || !sameBytes(styled[k], styled[0])) {
            std::printf("FAIL: the %s kernel's frame differs from the %s kernel's\n", kernels[k].name,
                        kernels[0].name);
            return 1;
        }
    }
    std::printf("web render bench done: every kernel drew the same bytes (drawSprite uses %s)\n",
                active.c_str());
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    polar::cli::Command app{
        "The render benchmark's scene in WebAssembly: every span kernel's median frame time, and a "
        "check that all draw the same bytes.",
        "polarcade-render-bench"};
    Options options;
    app.option("--sprites", options.sprites, "Sprites per frame", {1, 100000}).showDefault();
    app.option("--frames", options.frames, "Timed frames per kernel", {1, 10000}).showDefault();
    if (int code = app.parse(argc, argv); code >= 0) return code;
    return run(options);
}
