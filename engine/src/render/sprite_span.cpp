#include "render/sprite_span.h"

#include "render/blend.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace polar::render::detail {

void scalarSpanKernel(std::uint32_t* dst, const SpanParams& p) {
    std::int64_t u = p.u, v = p.v;
    const std::uint32_t* texels = p.texels;
    const int pitch = p.texelsPerRow;
    if (!p.modulate) {
        for (int i = 0; i < p.count; ++i, u += p.dux, v += p.dvx)
            blendInto(dst + i, texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)]);
        return;
    }
    for (int i = 0; i < p.count; ++i, u += p.dux, v += p.dvx) {
        std::uint32_t s = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
        if (s != 0) blendInto(dst + i, modulate(s, p.fa, p.fr, p.fg, p.fb));
    }
}

#if defined(__SSE2__)

namespace {

// The high 32 bits of the four 64-bit lanes of (a, b): the integer texel coordinates of 4 pixels.
inline __m128i highHalves(__m128i a, __m128i b) {
    return _mm_castps_si128(_mm_shuffle_ps(_mm_castsi128_ps(a), _mm_castsi128_ps(b), _MM_SHUFFLE(3, 1, 3, 1)));
}

// blendOver for 4 pixels, the scalar formula lane by lane: two channels share each 32-bit lane as
// 16-bit halves, t = d·(255 − a) + 128, and (t·257) >> 16 (pmulhuw) equals (t + (t >> 8)) >> 8 for
// every 16-bit t, so the bytes are identical to blendOver's.
inline __m128i blendOver4(__m128i d, __m128i s) {
    const __m128i lowBytes = _mm_set1_epi32(0x00FF00FF), c255 = _mm_set1_epi32(255);
    const __m128i c128 = _mm_set1_epi16(128), c257 = _mm_set1_epi16(257);
    __m128i ia = _mm_sub_epi32(c255, _mm_srli_epi32(s, 24));
    ia = _mm_or_si128(ia, _mm_slli_epi32(ia, 16));  // 255 − a in both 16-bit halves
    __m128i rb = _mm_mullo_epi16(_mm_and_si128(d, lowBytes), ia);  // (r, b)·(255 − a)
    __m128i ag = _mm_mullo_epi16(_mm_srli_epi16(d, 8), ia);         // (a, g)·(255 − a)
    rb = _mm_mulhi_epu16(_mm_add_epi16(rb, c128), c257);
    ag = _mm_mulhi_epu16(_mm_add_epi16(ag, c128), c257);
    return _mm_add_epi8(_mm_or_si128(rb, _mm_slli_epi16(ag, 8)), s);
}

// Four pixels per step: texel coordinates walk in 64-bit lanes, the texel index v·pitch + u comes
// from one multiply-add of 16-bit pairs (u, v < 2¹⁵), texels are fetched one by one, and the blend
// has no branch (it leaves a pixel unchanged under a transparent texel and copies an opaque one).
// A last group of 1–3 pixels uses the same code with transparent texels in the spare lanes when
// the row has room for them, which rewrites those pixels unchanged.
void sse2SpanKernel(std::uint32_t* dst, const SpanParams& p) {
    if (p.modulate) return scalarSpanKernel(dst, p);
    const std::uint32_t* texels = p.texels;
    __m128i u01 = _mm_set_epi64x(p.u + p.dux, p.u), u23 = _mm_set_epi64x(p.u + 3 * p.dux, p.u + 2 * p.dux);
    __m128i v01 = _mm_set_epi64x(p.v + p.dvx, p.v), v23 = _mm_set_epi64x(p.v + 3 * p.dvx, p.v + 2 * p.dvx);
    const __m128i du4 = _mm_set1_epi64x(4 * p.dux), dv4 = _mm_set1_epi64x(4 * p.dvx);
    const __m128i pitchPair = _mm_set1_epi32((p.texelsPerRow << 16) | 1);
    const int count = p.count;  // a local: the stores below could alias p as far as the compiler knows
    int i = 0;
    for (; i + 4 <= count; i += 4) {
        const __m128i uv = _mm_or_si128(highHalves(u01, u23), _mm_slli_epi32(highHalves(v01, v23), 16));
        const __m128i index = _mm_madd_epi16(uv, pitchPair);
        u01 = _mm_add_epi64(u01, du4);
        u23 = _mm_add_epi64(u23, du4);
        v01 = _mm_add_epi64(v01, dv4);
        v23 = _mm_add_epi64(v23, dv4);
        const std::uint64_t i01 = std::uint64_t(_mm_cvtsi128_si64(index));
        const std::uint64_t i23 = std::uint64_t(_mm_cvtsi128_si64(_mm_unpackhi_epi64(index, index)));
        const __m128i t0 = _mm_cvtsi32_si128(int(texels[std::uint32_t(i01)]));
        const __m128i t1 = _mm_cvtsi32_si128(int(texels[i01 >> 32]));
        const __m128i t2 = _mm_cvtsi32_si128(int(texels[std::uint32_t(i23)]));
        const __m128i t3 = _mm_cvtsi32_si128(int(texels[i23 >> 32]));
        const __m128i s = _mm_unpacklo_epi64(_mm_unpacklo_epi32(t0, t1), _mm_unpacklo_epi32(t2, t3));
        __m128i* out = reinterpret_cast<__m128i*>(dst + i);
        _mm_storeu_si128(out, blendOver4(_mm_loadu_si128(out), s));
    }
    const int left = count - i;
    if (left == 0) return;
    std::int64_t u = p.u + i * p.dux, v = p.v + i * p.dvx;
    if (left + p.roomAfter >= 4) {
        // 1–3 pixels, padded with transparent texels that rewrite the next pixels unchanged.
        alignas(16) std::uint32_t tail[4] = {0, 0, 0, 0};
        for (int k = 0; k < left; ++k, u += p.dux, v += p.dvx)
            tail[k] = texels[std::int32_t(v >> 32) * p.texelsPerRow + std::int32_t(u >> 32)];
        __m128i* out = reinterpret_cast<__m128i*>(dst + i);
        _mm_storeu_si128(out, blendOver4(_mm_loadu_si128(out), _mm_load_si128(reinterpret_cast<const __m128i*>(tail))));
        return;
    }
    for (int k = 0; k < left; ++k, u += p.dux, v += p.dvx)
        blendInto(dst + i + k, texels[std::int32_t(v >> 32) * p.texelsPerRow + std::int32_t(u >> 32)]);
}

}  // namespace

std::vector<NamedKernel> spanKernels() {
    return {{"scalar", scalarSpanKernel}, {"sse2", sse2SpanKernel}};
}

SpanKernel bestSpanKernel() { return sse2SpanKernel; }

#else

std::vector<NamedKernel> spanKernels() { return {{"scalar", scalarSpanKernel}}; }

SpanKernel bestSpanKernel() { return scalarSpanKernel; }

#endif

}  // namespace polar::render::detail
