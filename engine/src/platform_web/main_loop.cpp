#include "polar/platform/main_loop.h"

#include <emscripten.h>

#include <memory>

namespace polar::platform {
namespace {

void callFrame(void* data) {
    auto& frame = *static_cast<std::function<FrameResult()>*>(data);
    const FrameResult result = frame();
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
