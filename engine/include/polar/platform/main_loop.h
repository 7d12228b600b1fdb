#pragma once
#include <functional>
#include <optional>

namespace polar::platform {

// What one frame tells the loop that runs it.
struct FrameResult {
    std::optional<int> exitCode;  // stop the loop with this exit code; nothing: go on
    double idleSeconds = 0;       // how long the next frame can wait (where the platform must pace)
};

// Calls `frame` once per displayed frame until it returns an exit code.
//
// Why not a plain loop in the game? A browser owns its event loop: a page that never returns
// from main shows nothing. On the desktop this is that loop (it rests idleSeconds between
// frames, since a window surface has no vsync) and returns the exit code. On the web each frame
// is one requestAnimationFrame callback, and this call never returns: it unwinds to the browser,
// so whatever `frame` uses must live on the heap, not on the caller's stack; the exit code ends
// the program.
int runFrames(std::function<FrameResult()> frame);

}  // namespace polar::platform
