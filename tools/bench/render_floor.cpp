#include "render_floor.h"

#if defined(__x86_64__)
#include "render/span_avx2.h"
#endif

namespace polar::bench {

#if defined(__x86_64__)

namespace {

using render::detail::SpanBatch;

enum class Part { kNothing, kStore, kFetchStore, kBlend };

// The AVX2 kernel's loop over the same spans (8 pixels a step, a masked last group), doing only
// `part`: nothing; storing a constant; fetching the texels and storing them unblended; or blending
// a constant translucent texel over the canvas. The pixels they write are not the picture.
template <Part kPart>
POLAR_AVX2 void partKernel(const SpanBatch& b) {
    using namespace render::detail;
    const __m256i duA = _mm256_setr_epi64x(0, b.dux, 4 * b.dux, 5 * b.dux);
    const __m256i duB = _mm256_setr_epi64x(2 * b.dux, 3 * b.dux, 6 * b.dux, 7 * b.dux);
    const __m256i dvA = _mm256_setr_epi64x(0, b.dvx, 4 * b.dvx, 5 * b.dvx);
    const __m256i dvB = _mm256_setr_epi64x(2 * b.dvx, 3 * b.dvx, 6 * b.dvx, 7 * b.dvx);
    const __m256i du8 = _mm256_set1_epi64x(8 * b.dux), dv8 = _mm256_set1_epi64x(8 * b.dvx);
    const __m256i pitchPair = _mm256_set1_epi32((b.texelsPerRow << 16) | 1);
    const __m256i constant = _mm256_set1_epi32(int(0x80402010u));  // premultiplied, alpha 128
    const __m256i lanes = _mm256_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7);
    for (int n = 0; n < b.spanCount; ++n) {
        const render::detail::Span& span = b.spans[n];
        if constexpr (kPart == Part::kNothing) continue;
        if (n + 1 < b.spanCount) {
            const render::detail::Span& next = b.spans[n + 1];
            for (int k = 0; k < next.count; k += 16)
                _mm_prefetch(reinterpret_cast<const char*>(next.dst + k), _MM_HINT_T0);
        }
        const __m256i u0 = _mm256_set1_epi64x(span.u), v0 = _mm256_set1_epi64x(span.v);
        __m256i uA = _mm256_add_epi64(u0, duA), uB = _mm256_add_epi64(u0, duB);
        __m256i vA = _mm256_add_epi64(v0, dvA), vB = _mm256_add_epi64(v0, dvB);
        int i = 0;
        for (; i + 8 <= span.count; i += 8) {
            __m256i* out = reinterpret_cast<__m256i*>(span.dst + i);
            if constexpr (kPart == Part::kStore) {
                _mm256_storeu_si256(out, constant);
            } else if constexpr (kPart == Part::kFetchStore) {
                const __m256i index = texelIndex8(uA, uB, vA, vB, pitchPair);
                uA = _mm256_add_epi64(uA, du8);
                uB = _mm256_add_epi64(uB, du8);
                vA = _mm256_add_epi64(vA, dv8);
                vB = _mm256_add_epi64(vB, dv8);
                _mm256_storeu_si256(out, fetch8<false>(b.texels, index));
            } else {
                _mm256_storeu_si256(out, blendOver8(_mm256_loadu_si256(out), constant));
            }
        }
        if (i == span.count) continue;
        const __m256i mask = _mm256_cmpgt_epi32(_mm256_set1_epi32(span.count - i), lanes);
        int* out = reinterpret_cast<int*>(span.dst + i);
        _mm256_maskstore_epi32(out, mask, blendOver8(_mm256_maskload_epi32(out, mask), constant));
    }
}

}  // namespace

std::vector<render::detail::NamedKernel> floorKernels() {
    if (!__builtin_cpu_supports("avx2")) return {};
    return {{"row setup alone", partKernel<Part::kNothing>},
            {"stores alone", partKernel<Part::kStore>},
            {"fetch + store", partKernel<Part::kFetchStore>},
            {"blend alone", partKernel<Part::kBlend>},
            {"avx2 (all)", render::detail::avx2SpanKernel}};
}

#else

std::vector<render::detail::NamedKernel> floorKernels() {
    return {};
}

#endif

}  // namespace polar::bench
