#pragma once
// The innermost loop of sprite drawing: one clipped span of one row. Private to the renderer; the
// tests reach it to check that every kernel draws the same bytes.
#include <cstdint>
#include <vector>

#include "polar/math.h"
#include "polar/render/canvas.h"
#include "polar/render/image.h"
#include "polar/render/sprite.h"

namespace polar::render::detail {

// One span: `count` pixels from the destination pointer on, the texel coordinates (32.32 fixed
// point) of the first one and their steps per pixel. Every (u, v) of the span lies inside the image.
struct SpanParams {
    const std::uint32_t* texels = nullptr;  // premultiplied, row-major
    int texelsPerRow = 0;
    int count = 0;
    int roomAfter = 0;  // canvas pixels after the span in the same row (a kernel may rewrite them unchanged)
    std::int64_t u = 0, v = 0, dux = 0, dvx = 0;
    bool modulate = false;  // multiply each texel by (fa, fr, fg, fb) before blending
    std::uint32_t fa = 255, fr = 255, fg = 255, fb = 255;
};

using SpanKernel = void (*)(std::uint32_t* dst, const SpanParams& p);

struct NamedKernel {
    const char* name;
    SpanKernel kernel;
};

// The plain C++ kernel: the reference every other kernel must match byte for byte.
void scalarSpanKernel(std::uint32_t* dst, const SpanParams& p);
// Every kernel this build has, slowest first: scalar, then SSE2 on x86-64.
std::vector<NamedKernel> spanKernels();
// The fastest of them.
SpanKernel bestSpanKernel();

// drawSprite with a chosen kernel.
void drawSpriteWith(Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style,
                    SpanKernel kernel);

}  // namespace polar::render::detail
