#pragma once
// The innermost loops of sprite drawing: clipped spans of rows, a batch per call. Private to the
// renderer; the tests reach it to check that every kernel draws the same bytes.
#include <cstdint>
#include <string_view>
#include <vector>

#include "polar/math.h"
#include "polar/render/canvas.h"
#include "polar/render/image.h"
#include "polar/render/sprite.h"

namespace polar::render::detail {

// One row's span: `count` pixels from `dst` on, and the texel coordinates (32.32 fixed point) of
// the first; every pixel of the span maps inside the image.
// (No member initialisers: drawSprite keeps a batch of these on the stack and fills each before use.)
struct Span {
    std::uint32_t* dst;
    int count;
    int roomAfter;  // canvas pixels after the span in the same row (a kernel may rewrite them unchanged)
    std::int64_t u, v;
};

// Spans of one sprite and what they share: the image, the steps of (u, v) per pixel, and the tint.
struct SpanBatch {
    const std::uint32_t* texels = nullptr;  // premultiplied, row-major
    int texelsPerRow = 0;
    std::int64_t dux = 0, dvx = 0;
    bool modulate = false;  // multiply each texel by (fa, fr, fg, fb) before blending
    std::uint32_t fa = 255, fr = 255, fg = 255, fb = 255;
    const Span* spans = nullptr;
    int spanCount = 0;
};

using SpanKernel = void (*)(const SpanBatch& batch);

struct NamedKernel {
    const char* name;
    SpanKernel kernel;
};

// The plain C++ kernel: the reference every other kernel must match byte for byte.
void scalarSpanKernel(const SpanBatch& batch);
#if defined(__x86_64__)
// The AVX2 kernels (sprite_span_avx2.cpp), to be called only when the CPU has AVX2. The first is the
// one drawSprite uses; the others fetch texels by a gather, or skip transparent and store opaque
// groups of 8 texels, and stay so the benchmark can show why they are not used.
void avx2SpanKernel(const SpanBatch& batch);
void avx2GatherSpanKernel(const SpanBatch& batch);
void avx2RunsSpanKernel(const SpanBatch& batch);
#endif
#if defined(POLAR_WASM_SIMD)
// The WebAssembly SIMD128 kernel (sprite_span_wasm.cpp), in web builds made with POLAR_WEB_SIMD.
void wasmSimdSpanKernel(const SpanBatch& batch);
#endif
// Every kernel this build has that this CPU can run, scalar first.
std::vector<NamedKernel> spanKernels();
// The kernel drawSprite uses: the fastest this CPU runs (avx2, sse2, simd128 or scalar), unless
// chooseSpanKernel picked another.
NamedKernel activeSpanKernel();
// Makes drawSprite use the kernel called `name` (one of spanKernels()); false, and no change, when
// there is none. For benchmarks and tests; not to be called while anything draws.
bool chooseSpanKernel(std::string_view name);
// Makes drawSprite use any kernel, even one that does not draw the picture (the benchmark's floor
// kernels). Not to be called while anything draws.
void useSpanKernel(NamedKernel kernel);

struct RowClip;

// A sprite set up for drawing: everything drawSprite computes from the sprite, its image, its style
// and the canvas's size before it visits a row. Texel coordinates (32.32 fixed point) at the anchor
// pixel's centre and their steps per canvas pixel, so that at pixel (x, y)
//   U(x, y) = ua + (x − ax)·dux + (y − ay)·duy,   V(x, y) = va + (x − ax)·dvx + (y − ay)·dvy,
// all in exact 64-bit integer arithmetic; the rows that may hold its pixels; and the bands of the
// image's visible octagon that limit each row's span (see prepareSprite).
//
// Why apart from the rows? A DrawList draws a sprite in every band of rows it crosses. Set up once,
// in a pass of its own, a sprite costs its rows alone in each band, and the setup is shared out
// among the workers like any other work. The rows come out the same either way: drawSprite is this
// setup followed by drawPrepared over every row.
struct PreparedSprite {
    // One direction of the octagon: as a limit on each row's span (lowBase + rows·slope ≤ k ≤
    // highBase + rows·slope), or, for a direction along the rows, as a test that picks rows
    // (lo ≤ r0 + rows·perRow ≤ hi).
    struct Band {
        double lowBase, highBase, slope;
        std::int64_t r0, perRow, lo, hi;
    };
    std::int64_t ua, va, dux, dvx, duy, dvy;
    std::int64_t ax, ay;
    int rowBegin, rowEnd;          // rows that may hold sprite pixels, clipped to the canvas
    std::int64_t uMax, vMax;       // the largest texel coordinates inside the image
    double canvasLow, canvasHigh;  // the canvas's columns as steps from the anchor
    Band bands[4];                 // those that limit spans, then those that pick rows
    int limitCount, pickCount;
    SpanBatch batch;  // the image, the steps along a row and the tint; no spans
};

// Sets a sprite up for a canvas of `canvas`'s size; false when it draws nothing (an invisible image
// or style, or a transform that cannot be drawn).
bool prepareSprite(const Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style,
                   PreparedSprite& sprite);
// Draws a prepared sprite's rows within `rows` into a canvas of the size it was prepared for.
void drawPrepared(Canvas& canvas, RowClip rows, const PreparedSprite& sprite, SpanKernel kernel);

// drawSprite with a chosen kernel, all rows or only those of `rows`.
void drawSpriteWith(Canvas& canvas, const Image& image, const Mat3& toCanvas, const SpriteStyle& style,
                    SpanKernel kernel);
void drawSpriteWith(Canvas& canvas, RowClip rows, const Image& image, const Mat3& toCanvas,
                    const SpriteStyle& style, SpanKernel kernel);

}  // namespace polar::render::detail
