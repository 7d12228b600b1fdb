#pragma once
// The AVX2 span kernels' steps on 8 pixels (sprite_span_avx2.cpp), in a header of their own so the
// render benchmark's floor kernels (tools/bench/render_floor.cpp) time the very same instructions.
// Each function is compiled for AVX2 alone: call them only from POLAR_AVX2 functions, and those
// only when the CPU has AVX2.
#if defined(__x86_64__)

#include <immintrin.h>

#include <cstdint>

#define POLAR_AVX2 [[gnu::target("avx2")]]

namespace polar::render::detail {

// The high 32 bits of the 64-bit lanes of a = pixels (0, 1, 4, 5) and b = pixels (2, 3, 6, 7):
// within each 128-bit half the shuffle takes a's two lanes then b's, so the result is pixels 0…7
// in order.
POLAR_AVX2 inline __m256i highHalves8(__m256i a, __m256i b) {
    return _mm256_castps_si256(
        _mm256_shuffle_ps(_mm256_castsi256_ps(a), _mm256_castsi256_ps(b), _MM_SHUFFLE(3, 1, 3, 1)));
}

// The texel indices v·pitch + u of 8 pixels from their 32.32 coordinates (laid out as for
// highHalves8), by one multiply-add of 16-bit pairs (u, v < 2¹⁵) with pitchPair = (pitch << 16) | 1.
POLAR_AVX2 inline __m256i texelIndex8(__m256i uA, __m256i uB, __m256i vA, __m256i vB, __m256i pitchPair) {
    const __m256i uv = _mm256_or_si256(highHalves8(uA, uB), _mm256_slli_epi32(highHalves8(vA, vB), 16));
    return _mm256_madd_epi16(uv, pitchPair);
}

// blendOver for 8 pixels: blendOver4 (sprite_span.cpp) on 256-bit registers, the same exact steps.
POLAR_AVX2 inline __m256i blendOver8(__m256i d, __m256i s) {
    const __m256i lowBytes = _mm256_set1_epi32(0x00FF00FF), c255 = _mm256_set1_epi32(255);
    const __m256i c128 = _mm256_set1_epi16(128), c257 = _mm256_set1_epi16(257);
    __m256i ia = _mm256_sub_epi32(c255, _mm256_srli_epi32(s, 24));
    ia = _mm256_or_si256(ia, _mm256_slli_epi32(ia, 16));
    __m256i rb = _mm256_mullo_epi16(_mm256_and_si256(d, lowBytes), ia);
    __m256i ag = _mm256_mullo_epi16(_mm256_srli_epi16(d, 8), ia);
    rb = _mm256_mulhi_epu16(_mm256_add_epi16(rb, c128), c257);
    ag = _mm256_mulhi_epu16(_mm256_add_epi16(ag, c128), c257);
    return _mm256_add_epi8(_mm256_or_si256(rb, _mm256_slli_epi16(ag, 8)), s);
}

// modulate() for 8 pixels: each channel round(c·f/255) as (t·257) >> 16 with t = c·f + 128. The
// unpacks and the pack work within 128-bit halves, so the pixels keep their places.
POLAR_AVX2 inline __m256i modulateChannels(__m256i c16, __m256i factors) {
    const __m256i c128 = _mm256_set1_epi16(128), c257 = _mm256_set1_epi16(257);
    return _mm256_mulhi_epu16(_mm256_add_epi16(_mm256_mullo_epi16(c16, factors), c128), c257);
}
POLAR_AVX2 inline __m256i modulate8(__m256i s, __m256i factors) {
    const __m256i zero = _mm256_setzero_si256();
    return _mm256_packus_epi16(modulateChannels(_mm256_unpacklo_epi8(s, zero), factors),
                               modulateChannels(_mm256_unpackhi_epi8(s, zero), factors));
}

// The texels at 8 indices, by one gather or by 8 scalar loads.
template <bool kGather>
POLAR_AVX2 inline __m256i fetch8(const std::uint32_t* texels, __m256i index) {
    if constexpr (kGather) {
        return _mm256_i32gather_epi32(reinterpret_cast<const int*>(texels), index, 4);
    } else {
        const __m128i lo = _mm256_castsi256_si128(index), hi = _mm256_extracti128_si256(index, 1);
        const std::uint64_t i01 = std::uint64_t(_mm_cvtsi128_si64(lo));
        const std::uint64_t i23 = std::uint64_t(_mm_extract_epi64(lo, 1));
        const std::uint64_t i45 = std::uint64_t(_mm_cvtsi128_si64(hi));
        const std::uint64_t i67 = std::uint64_t(_mm_extract_epi64(hi, 1));
        auto at = [texels](std::uint64_t i) { return int(texels[i]); };
        __m128i a = _mm_cvtsi32_si128(at(std::uint32_t(i01)));
        __m128i b = _mm_cvtsi32_si128(at(std::uint32_t(i45)));
        a = _mm_insert_epi32(a, at(i01 >> 32), 1);
        b = _mm_insert_epi32(b, at(i45 >> 32), 1);
        a = _mm_insert_epi32(a, at(std::uint32_t(i23)), 2);
        b = _mm_insert_epi32(b, at(std::uint32_t(i67)), 2);
        a = _mm_insert_epi32(a, at(i23 >> 32), 3);
        b = _mm_insert_epi32(b, at(i67 >> 32), 3);
        return _mm256_inserti128_si256(_mm256_castsi128_si256(a), b, 1);
    }
}

}  // namespace polar::render::detail

#endif
