#include "polar/platform/main_loop.h"

#include <chrono>
#include <thread>

namespace polar::platform {

int runFrames(std::function<FrameResult()> frame) {
    while (true) {
        const FrameResult result = frame();
        if (result.exitCode) return *result.exitCode;
        if (result.idleSeconds > 0)
            std::this_thread::sleep_for(
                std::chrono::milliseconds(static_cast<int>(result.idleSeconds * 1000)));
    }
}

}  // namespace polar::platform
