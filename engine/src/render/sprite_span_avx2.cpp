// The AVX2 span kernels: 8 pixels per step, the SSE2 kernel's arithmetic on twice the lanes.
// Compiled for AVX2 function by function (the rest of the program stays x86-64), and chosen at run
// time (activeSpanKernel) when the CPU has AVX2.
#include "render/sprite_span.h"

#if defined(__x86_64__)

#include "render/blend.h"
#include "render/span_avx2.h"

namespace polar::render::detail {

namespace {

// Eight pixels per step. Texel coordinates walk in 64-bit lanes (pixels 0, 1, 4, 5 in one register
// and 2, 3, 6, 7 in the other, so that taking their high halves lists the pixels in order), the
// index v·pitch + u comes from one multiply-add of 16-bit pairs (u, v < 2¹⁵), and the blend has no
// branch. With kRuns, 8 transparent texels leave the pixels unread and 8 opaque ones are stored
// without reading them, exactly what the blend would give. A last group of 1–7 pixels fetches its
// texels one by one, and reads and writes only its own pixels (masked load and store).
template <bool kModulate, bool kGather, bool kRuns>
POLAR_AVX2 void avx2Spans(const SpanBatch& b) {
    const std::uint32_t* texels = b.texels;
    const int pitch = b.texelsPerRow;
    const __m256i factors =
        _mm256_setr_epi16(short(b.fb), short(b.fg), short(b.fr), short(b.fa), short(b.fb), short(b.fg),
                          short(b.fr), short(b.fa), short(b.fb), short(b.fg), short(b.fr), short(b.fa),
                          short(b.fb), short(b.fg), short(b.fr), short(b.fa));
    const __m256i duA = _mm256_setr_epi64x(0, b.dux, 4 * b.dux, 5 * b.dux);
    const __m256i duB = _mm256_setr_epi64x(2 * b.dux, 3 * b.dux, 6 * b.dux, 7 * b.dux);
    const __m256i dvA = _mm256_setr_epi64x(0, b.dvx, 4 * b.dvx, 5 * b.dvx);
    const __m256i dvB = _mm256_setr_epi64x(2 * b.dvx, 3 * b.dvx, 6 * b.dvx, 7 * b.dvx);
    const __m256i du8 = _mm256_set1_epi64x(8 * b.dux), dv8 = _mm256_set1_epi64x(8 * b.dvx);
    const __m256i pitchPair = _mm256_set1_epi32((pitch << 16) | 1);
    const __m256i alphaBits = _mm256_set1_epi32(int(0xFF000000u));
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int n = 0; n < b.spanCount; ++n) {
        const Span& span = b.spans[n];
        std::uint32_t* dst = span.dst;
        if (n + 1 < b.spanCount) {
            // The next row's pixels, one cache line (16 pixels) at a time, while this row is drawn.
            const Span& next = b.spans[n + 1];
            for (int k = 0; k < next.count; k += 16)
                _mm_prefetch(reinterpret_cast<const char*>(next.dst + k), _MM_HINT_T0);
        }
        const __m256i u0 = _mm256_set1_epi64x(span.u), v0 = _mm256_set1_epi64x(span.v);
        __m256i uA = _mm256_add_epi64(u0, duA), uB = _mm256_add_epi64(u0, duB);
        __m256i vA = _mm256_add_epi64(v0, dvA), vB = _mm256_add_epi64(v0, dvB);
        const int count = span.count;
        int i = 0;
        for (; i + 8 <= count; i += 8) {
            const __m256i index = texelIndex8(uA, uB, vA, vB, pitchPair);
            uA = _mm256_add_epi64(uA, du8);
            uB = _mm256_add_epi64(uB, du8);
            vA = _mm256_add_epi64(vA, dv8);
            vB = _mm256_add_epi64(vB, dv8);
            __m256i s = fetch8<kGather>(texels, index);
            if constexpr (kModulate) s = modulate8(s, factors);
            __m256i* out = reinterpret_cast<__m256i*>(dst + i);
            if constexpr (kRuns) {
                if (_mm256_testz_si256(s, alphaBits)) continue;
                const __m256i opaque = _mm256_cmpeq_epi32(_mm256_or_si256(s, _mm256_set1_epi32(0x00FFFFFF)),
                                                          _mm256_set1_epi32(-1));
                if (_mm256_movemask_ps(_mm256_castsi256_ps(opaque)) == 0xFF) {
                    _mm256_storeu_si256(out, s);
                    continue;
                }
            }
            _mm256_storeu_si256(out, blendOver8(_mm256_loadu_si256(out), s));
        }
        const int left = count - i;
        if (left == 0) continue;
        std::int64_t u = span.u + i * b.dux, v = span.v + i * b.dvx;
        alignas(32) std::uint32_t tail[8] = {0, 0, 0, 0, 0, 0, 0, 0};
        for (int k = 0; k < left; ++k, u += b.dux, v += b.dvx)
            tail[k] = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
        __m256i s = _mm256_load_si256(reinterpret_cast<const __m256i*>(tail));
        if constexpr (kModulate) s = modulate8(s, factors);
        const __m256i mask = _mm256_cmpgt_epi32(_mm256_set1_epi32(left), lanes);
        int* out = reinterpret_cast<int*>(dst + i);
        _mm256_maskstore_epi32(out, mask, blendOver8(_mm256_maskload_epi32(out, mask), s));
    }
}

template <bool kGather, bool kRuns>
POLAR_AVX2 void avx2Kernel(const SpanBatch& b) {
    if (b.modulate)
        avx2Spans<true, kGather, kRuns>(b);
    else
        avx2Spans<false, kGather, kRuns>(b);
}

}  // namespace

void avx2SpanKernel(const SpanBatch& b) {
    avx2Kernel<false, false>(b);
}
void avx2GatherSpanKernel(const SpanBatch& b) {
    avx2Kernel<true, false>(b);
}
void avx2RunsSpanKernel(const SpanBatch& b) {
    avx2Kernel<false, true>(b);
}

}  // namespace polar::render::detail

#endif
