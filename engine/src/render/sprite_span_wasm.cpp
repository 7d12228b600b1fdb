// The WebAssembly SIMD128 span kernel: 4 pixels per step, the SSE2 kernel's plan in WebAssembly's
// vector instructions. Only this file is compiled with -msimd128 (engine/cmake/PolarWeb.cmake), so
// the scalar kernel stays the plain code the browser would run without it.
#include "render/sprite_span.h"

#if defined(__wasm_simd128__)

#include <wasm_simd128.h>

#include "render/blend.h"

namespace polar::render::detail {

namespace {

// round(x·y / 255) on 8 16-bit lanes from t = x·y + 128 ≤ 65153: (t + (t >> 8)) >> 8, mul255's
// formula itself (t + (t >> 8) ≤ 65407 stays within 16 bits).
inline v128_t divide255(v128_t product) {
    const v128_t t = wasm_i16x8_add(product, wasm_i16x8_splat(128));
    return wasm_u16x8_shr(wasm_i16x8_add(t, wasm_u16x8_shr(t, 8)), 8);
}

// blendOver for 4 pixels: two channels share each 32-bit lane as 16-bit halves, as in blendOver.
inline v128_t blendOver4(v128_t d, v128_t s) {
    v128_t ia = wasm_i32x4_sub(wasm_i32x4_splat(255), wasm_u32x4_shr(s, 24));
    ia = wasm_v128_or(ia, wasm_i32x4_shl(ia, 16));  // 255 − a in both 16-bit halves
    const v128_t rb = divide255(wasm_i16x8_mul(wasm_v128_and(d, wasm_i32x4_splat(0x00FF00FF)), ia));
    const v128_t ag = divide255(wasm_i16x8_mul(wasm_u16x8_shr(d, 8), ia));
    return wasm_i8x16_add(wasm_v128_or(rb, wasm_i16x8_shl(ag, 8)), s);
}

// modulate() for 4 pixels: each channel round(c·f/255).
inline v128_t modulate4(v128_t s, v128_t factors) {
    const v128_t low = divide255(wasm_i16x8_mul(wasm_u16x8_extend_low_u8x16(s), factors));
    const v128_t high = divide255(wasm_i16x8_mul(wasm_u16x8_extend_high_u8x16(s), factors));
    return wasm_u8x16_narrow_i16x8(low, high);
}

// As sse2Spans (sprite_span.cpp): coordinates in 64-bit lanes, index v·pitch + u by one dot product
// of 16-bit pairs, texels fetched one by one, a branchless blend, and a last group of 1–3 pixels
// padded with transparent texels when the row has room, else drawn one by one.
template <bool kModulate>
void wasmSpans(const SpanBatch& b) {
    const std::uint32_t* texels = b.texels;
    const int pitch = b.texelsPerRow;
    const v128_t factors = wasm_i16x8_make(short(b.fb), short(b.fg), short(b.fr), short(b.fa), short(b.fb),
                                           short(b.fg), short(b.fr), short(b.fa));
    const v128_t du01 = wasm_i64x2_make(0, b.dux), du23 = wasm_i64x2_make(2 * b.dux, 3 * b.dux);
    const v128_t dv01 = wasm_i64x2_make(0, b.dvx), dv23 = wasm_i64x2_make(2 * b.dvx, 3 * b.dvx);
    const v128_t du4 = wasm_i64x2_splat(4 * b.dux), dv4 = wasm_i64x2_splat(4 * b.dvx);
    const v128_t pitchPair = wasm_i32x4_splat((pitch << 16) | 1);
    for (int n = 0; n < b.spanCount; ++n) {
        const Span& span = b.spans[n];
        std::uint32_t* dst = span.dst;
        const v128_t u0 = wasm_i64x2_splat(span.u), v0 = wasm_i64x2_splat(span.v);
        v128_t u01 = wasm_i64x2_add(u0, du01), u23 = wasm_i64x2_add(u0, du23);
        v128_t v01 = wasm_i64x2_add(v0, dv01), v23 = wasm_i64x2_add(v0, dv23);
        const int count = span.count;
        int i = 0;
        for (; i + 4 <= count; i += 4) {
            const v128_t uHigh = wasm_i32x4_shuffle(u01, u23, 1, 3, 5, 7);
            const v128_t vHigh = wasm_i32x4_shuffle(v01, v23, 1, 3, 5, 7);
            const v128_t index =
                wasm_i32x4_dot_i16x8(wasm_v128_or(uHigh, wasm_i32x4_shl(vHigh, 16)), pitchPair);
            u01 = wasm_i64x2_add(u01, du4);
            u23 = wasm_i64x2_add(u23, du4);
            v01 = wasm_i64x2_add(v01, dv4);
            v23 = wasm_i64x2_add(v23, dv4);
            v128_t s = wasm_u32x4_make(
                texels[wasm_u32x4_extract_lane(index, 0)], texels[wasm_u32x4_extract_lane(index, 1)],
                texels[wasm_u32x4_extract_lane(index, 2)], texels[wasm_u32x4_extract_lane(index, 3)]);
            if constexpr (kModulate) s = modulate4(s, factors);
            std::uint32_t* out = dst + i;
            wasm_v128_store(out, blendOver4(wasm_v128_load(out), s));
        }
        const int left = count - i;
        if (left == 0) continue;
        std::int64_t u = span.u + i * b.dux, v = span.v + i * b.dvx;
        if (left + span.roomAfter >= 4) {
            std::uint32_t tail[4] = {0, 0, 0, 0};
            for (int k = 0; k < left; ++k, u += b.dux, v += b.dvx)
                tail[k] = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
            v128_t s = wasm_v128_load(tail);
            if constexpr (kModulate) s = modulate4(s, factors);
            std::uint32_t* out = dst + i;
            wasm_v128_store(out, blendOver4(wasm_v128_load(out), s));
            continue;
        }
        for (int k = 0; k < left; ++k, u += b.dux, v += b.dvx) {
            std::uint32_t s = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
            if constexpr (kModulate) s = modulate(s, b.fa, b.fr, b.fg, b.fb);
            blendInto(dst + i + k, s);
        }
    }
}

}  // namespace

void wasmSimdSpanKernel(const SpanBatch& b) {
    if (b.modulate)
        wasmSpans<true>(b);
    else
        wasmSpans<false>(b);
}

}  // namespace polar::render::detail

#endif
