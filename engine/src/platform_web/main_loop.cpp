#include "polar/platform/main_loop.h"

#include <emscripten.h>

#include <memory>

// Each frame's end and its cost in milliseconds, the last 1200 kept in Module.polarFrameTimes
// for the page (the browser test reads the frame times there).
EM_JS(void, polarWebFrameTimed, (double start), {
    var now = performance.now();
    var times = Module.polarFrameTimes = Module.polarFrameTimes || [];
    times.push([ now, now - start ]);
    if (times.length > 1200) times.shift();
});

namespace polar::platform {
namespace {

void callFrame(void* data) {
    auto& frame = *static_cast<std::function<FrameResult()>*>(data);
    const double start = emscripten_get_now();
    const FrameResult result = frame();
    polarWebFrameTimed(start);
    if (!result.exitCode) return;
    emscripten_cancel_main_loop();
    emscripten_force_exit(*result.exitCode);
}

}  // namespace

int runFrames(std::function<FrameResult()> frame) {
    // Kept for the page's lifetime: the browser calls it on every animation frame. The infinite
    // loop is simulated: this call unwinds to the browser and never returns.
    auto* kept = new std::function<FrameResult()>(std::move(frame));
    emscripten_set_main_loop_arg(callFrame, kept, 0, 1);
    return 0;
}

}  // namespace polar::platform
