#include "render/sprite_span.h"

#include <atomic>

#include "render/blend.h"

#if defined(__SSE2__) && defined(__x86_64__)
#include <emmintrin.h>
#include <xmmintrin.h>
#endif

namespace polar::render::detail {

void scalarSpanKernel(const SpanBatch& b) {
    const std::uint32_t* texels = b.texels;
    const int pitch = b.texelsPerRow;
    for (int n = 0; n < b.spanCount; ++n) {
        const Span& span = b.spans[n];
        std::int64_t u = span.u, v = span.v;
        for (int i = 0; i < span.count; ++i, u += b.dux, v += b.dvx) {
            const std::uint32_t s = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
            if (!b.modulate)
                blendInto(span.dst + i, s);
            else if (s != 0)
                blendInto(span.dst + i, modulate(s, b.fa, b.fr, b.fg, b.fb));
        }
    }
}

#if defined(__SSE2__) && defined(__x86_64__)

namespace {

// The high 32 bits of the four 64-bit lanes of (a, b): the integer texel coordinates of 4 pixels.
inline __m128i highHalves(__m128i a, __m128i b) {
    return _mm_castps_si128(
        _mm_shuffle_ps(_mm_castsi128_ps(a), _mm_castsi128_ps(b), _MM_SHUFFLE(3, 1, 3, 1)));
}

// blendOver for 4 pixels, the scalar formula lane by lane: two channels share each 32-bit lane as
// 16-bit halves, t = d·(255 − a) + 128, and (t·257) >> 16 (pmulhuw) equals (t + (t >> 8)) >> 8 for
// every 16-bit t, so the bytes are identical to blendOver's.
inline __m128i blendOver4(__m128i d, __m128i s) {
    const __m128i lowBytes = _mm_set1_epi32(0x00FF00FF), c255 = _mm_set1_epi32(255);
    const __m128i c128 = _mm_set1_epi16(128), c257 = _mm_set1_epi16(257);
    __m128i ia = _mm_sub_epi32(c255, _mm_srli_epi32(s, 24));
    ia = _mm_or_si128(ia, _mm_slli_epi32(ia, 16));                 // 255 − a in both 16-bit halves
    __m128i rb = _mm_mullo_epi16(_mm_and_si128(d, lowBytes), ia);  // (r, b)·(255 − a)
    __m128i ag = _mm_mullo_epi16(_mm_srli_epi16(d, 8), ia);        // (a, g)·(255 − a)
    rb = _mm_mulhi_epu16(_mm_add_epi16(rb, c128), c257);
    ag = _mm_mulhi_epu16(_mm_add_epi16(ag, c128), c257);
    return _mm_add_epi8(_mm_or_si128(rb, _mm_slli_epi16(ag, 8)), s);
}

// Four pixels per step: texel coordinates walk in 64-bit lanes, the texel index v·pitch + u comes
// from one multiply-add of 16-bit pairs (u, v < 2¹⁵), texels are fetched one by one, and the blend
// has no branch (it leaves a pixel unchanged under a transparent texel and copies an opaque one);
// a tinted or faded sprite multiplies each texel by its factors first.
// A last group of 1–3 pixels uses the same blend with transparent texels in the spare lanes when
// the row has room for them, which rewrites those pixels unchanged.
// modulate() for 4 pixels: each channel round(c·f/255), as (t·257) >> 16 with t = c·f + 128.
inline __m128i modulate4(__m128i s, __m128i factors) {
    const __m128i zero = _mm_setzero_si128(), c128 = _mm_set1_epi16(128), c257 = _mm_set1_epi16(257);
    auto half = [&](__m128i c16) {
        return _mm_mulhi_epu16(_mm_add_epi16(_mm_mullo_epi16(c16, factors), c128), c257);
    };
    return _mm_packus_epi16(half(_mm_unpacklo_epi8(s, zero)), half(_mm_unpackhi_epi8(s, zero)));
}

template <bool kModulate>
void sse2Spans(const SpanBatch& b) {
    const std::uint32_t* texels = b.texels;
    // (b, g, r, a) factors for the 16-bit channels of two pixels.
    const __m128i factors = _mm_set_epi16(short(b.fa), short(b.fr), short(b.fg), short(b.fb), short(b.fa),
                                          short(b.fr), short(b.fg), short(b.fb));
    const int pitch = b.texelsPerRow;
    const __m128i du01 = _mm_set_epi64x(b.dux, 0), du23 = _mm_set_epi64x(3 * b.dux, 2 * b.dux);
    const __m128i dv01 = _mm_set_epi64x(b.dvx, 0), dv23 = _mm_set_epi64x(3 * b.dvx, 2 * b.dvx);
    const __m128i du4 = _mm_set1_epi64x(4 * b.dux), dv4 = _mm_set1_epi64x(4 * b.dvx);
    const __m128i pitchPair = _mm_set1_epi32((pitch << 16) | 1);
    for (int n = 0; n < b.spanCount; ++n) {
        const Span& span = b.spans[n];
        std::uint32_t* dst = span.dst;
        if (n + 1 < b.spanCount) {
            // Ask for the next row's pixels now, one cache line (16 pixels) at a time, so they
            // arrive while this row is drawn.
            const Span& next = b.spans[n + 1];
            for (int k = 0; k < next.count; k += 16)
                _mm_prefetch(reinterpret_cast<const char*>(next.dst + k), _MM_HINT_T0);
        }
        const __m128i u0 = _mm_set1_epi64x(span.u), v0 = _mm_set1_epi64x(span.v);
        __m128i u01 = _mm_add_epi64(u0, du01), u23 = _mm_add_epi64(u0, du23);
        __m128i v01 = _mm_add_epi64(v0, dv01), v23 = _mm_add_epi64(v0, dv23);
        const int count = span.count;
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
            __m128i s = _mm_unpacklo_epi64(_mm_unpacklo_epi32(t0, t1), _mm_unpacklo_epi32(t2, t3));
            if constexpr (kModulate) s = modulate4(s, factors);
            __m128i* out = reinterpret_cast<__m128i*>(dst + i);
            _mm_storeu_si128(out, blendOver4(_mm_loadu_si128(out), s));
        }
        const int left = count - i;
        if (left == 0) continue;
        std::int64_t u = span.u + i * b.dux, v = span.v + i * b.dvx;
        if (left + span.roomAfter >= 4) {
            // 1–3 pixels, padded with transparent texels that rewrite the next pixels unchanged.
            alignas(16) std::uint32_t tail[4] = {0, 0, 0, 0};
            for (int k = 0; k < left; ++k, u += b.dux, v += b.dvx)
                tail[k] = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
            __m128i s = _mm_load_si128(reinterpret_cast<const __m128i*>(tail));
            if constexpr (kModulate) s = modulate4(s, factors);
            __m128i* out = reinterpret_cast<__m128i*>(dst + i);
            _mm_storeu_si128(out, blendOver4(_mm_loadu_si128(out), s));
            continue;
        }
        for (int k = 0; k < left; ++k, u += b.dux, v += b.dvx) {
            std::uint32_t s = texels[std::int32_t(v >> 32) * pitch + std::int32_t(u >> 32)];
            if constexpr (kModulate) s = modulate(s, b.fa, b.fr, b.fg, b.fb);
            blendInto(dst + i + k, s);
        }
    }
}

void sse2SpanKernel(const SpanBatch& b) {
    if (b.modulate)
        sse2Spans<true>(b);
    else
        sse2Spans<false>(b);
}

}  // namespace

std::vector<NamedKernel> spanKernels() {
    std::vector<NamedKernel> kernels{{"scalar", scalarSpanKernel}, {"sse2", sse2SpanKernel}};
    if (__builtin_cpu_supports("avx2")) {
        kernels.push_back({"avx2", avx2SpanKernel});
        kernels.push_back({"avx2-gather", avx2GatherSpanKernel});
        kernels.push_back({"avx2-runs", avx2RunsSpanKernel});
    }
    return kernels;
}

namespace {
NamedKernel fastestSpanKernel() {
    if (__builtin_cpu_supports("avx2")) return {"avx2", avx2SpanKernel};
    return {"sse2", sse2SpanKernel};
}
}  // namespace

#elif defined(POLAR_WASM_SIMD)

// A WebAssembly module either validates with its SIMD instructions or does not load at all, so the
// choice is made when building (POLAR_WEB_SIMD), not here.
std::vector<NamedKernel> spanKernels() {
    return {{"scalar", scalarSpanKernel}, {"simd128", wasmSimdSpanKernel}};
}

namespace {
NamedKernel fastestSpanKernel() {
    return {"simd128", wasmSimdSpanKernel};
}
}  // namespace

#else

std::vector<NamedKernel> spanKernels() {
    return {{"scalar", scalarSpanKernel}};
}

namespace {
NamedKernel fastestSpanKernel() {
    return {"scalar", scalarSpanKernel};
}
}  // namespace

#endif

namespace {
// The active kernel and its name; set together before drawing, so relaxed atomics suffice (a
// task system's start orders them before every worker's reads).
struct Active {
    std::atomic<SpanKernel> kernel{fastestSpanKernel().kernel};
    std::atomic<const char*> name{fastestSpanKernel().name};
};
Active& active() {
    static Active a;
    return a;
}
}  // namespace

NamedKernel activeSpanKernel() {
    Active& a = active();
    return {a.name.load(std::memory_order_relaxed), a.kernel.load(std::memory_order_relaxed)};
}

void useSpanKernel(NamedKernel kernel) {
    Active& a = active();
    a.kernel.store(kernel.kernel, std::memory_order_relaxed);
    a.name.store(kernel.name, std::memory_order_relaxed);
}

bool chooseSpanKernel(std::string_view name) {
    for (const NamedKernel& k : spanKernels())
        if (name == k.name) {
            useSpanKernel(k);
            return true;
        }
    return false;
}

}  // namespace polar::render::detail
