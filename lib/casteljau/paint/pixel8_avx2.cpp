// pixel8.h's blend runs, eight pixels at a time with AVX2.
//
// The four-pixel SSE2 form's arithmetic, twice over: each 256-bit register
// holds pixel j of the eight in its low 128 bits and pixel j + 4 in its high
// ones, because AVX2's unpacks, shuffles and packs work within each 128-bit
// half. Every pixel so goes through the same multiplies, add and rounding
// as in the SSE2 form (no fused multiply-add: this file's target is AVX2
// alone), and the bytes are the same (tests/paint/pixel8_test.cpp). The
// run's last n mod 8 pixels go to the SSE2 form. Measured against it:
// bench/README.md, 2026-11-29.
#include "casteljau/paint/pixel8.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>

namespace casteljau::detail {

namespace {

// The SSE2 form's policies (pixel8.h) read eight pixels at a time: the
// coverage of pixels i to i + 7; the source of pixel i + J (low half) and
// i + J + 4 (high half); the sources' alphas of pixels i to i + 7.
[[gnu::target("avx2")]] __m256 eight(const PerPixel& k, int i) { return _mm256_loadu_ps(k.k + i); }
[[gnu::target("avx2")]] __m256 eight(const Constant& k, int) { return _mm256_set1_ps(k.k); }
template <int J>
[[gnu::target("avx2")]] __m256 pair_color(const OneColor& s, int) {
    return _mm256_set_m128(s.src, s.src);
}
template <int J>
[[gnu::target("avx2")]] __m256 pair_color(const Colors& s, int i) {
    return _mm256_set_m128(s.template color<J + 4>(i), s.template color<J>(i));
}
// The alphas, from the four pair_colors already loaded: for a color per
// pixel, Colors::four_alpha's unpacks and shuffle in each half, where eight
// scalar loads and inserts took 4% of a shaded frame.
[[gnu::target("avx2")]] __m256 eight_alpha(const OneColor& s, const __m256*) {
    return _mm256_set1_ps(s.s.a);
}
[[gnu::target("avx2")]] __m256 eight_alpha(const Colors&, const __m256* pairs) {
    const __m256 a01 = _mm256_unpackhi_ps(pairs[0], pairs[1]); // [b0 b1 a0 a1]
    const __m256 a23 = _mm256_unpackhi_ps(pairs[2], pairs[3]); // [b2 b3 a2 a3]
    return _mm256_shuffle_ps(a01, a23, _MM_SHUFFLE(3, 2, 3, 2));
}

// Pixel J (low half) and J + 4 (high half) of the eight: blend_lane's
// arithmetic on both.
template <int J>
[[gnu::target("avx2")]] __m256i blend_pair(__m256 src, __m256 k255, __m256 inv, __m256i lanes) {
    constexpr int pick = _MM_SHUFFLE(J, J, J, J);
    const __m256 scaled = _mm256_mul_ps(src, _mm256_shuffle_ps(k255, k255, pick));
    const __m256 kept = _mm256_mul_ps(_mm256_cvtepi32_ps(lanes), _mm256_shuffle_ps(inv, inv, pick));
    return _mm256_cvtps_epi32(_mm256_add_ps(scaled, kept));
}

template <class Source, class Coverage>
[[gnu::target("avx2")]] void blend8(Premul8* d, int n, const Source& s, Coverage k) noexcept {
    const __m256i zero = _mm256_setzero_si256();
    const __m256 one = _mm256_set1_ps(1.0f), scale = _mm256_set1_ps(255.0f);
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256 pairs[4] = {pair_color<0>(s, i), pair_color<1>(s, i), pair_color<2>(s, i),
                                 pair_color<3>(s, i)};
        const __m256 kk = eight(k, i);
        const __m256 k255 = _mm256_mul_ps(kk, scale);
        const __m256 inv = _mm256_sub_ps(one, _mm256_mul_ps(kk, eight_alpha(s, pairs)));
        const __m256i bytes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(d + i));
        const __m256i lo = _mm256_unpacklo_epi8(bytes, zero),
                      hi = _mm256_unpackhi_epi8(bytes, zero);
        const __m256i q0 = blend_pair<0>(pairs[0], k255, inv, _mm256_unpacklo_epi16(lo, zero));
        const __m256i q1 = blend_pair<1>(pairs[1], k255, inv, _mm256_unpackhi_epi16(lo, zero));
        const __m256i q2 = blend_pair<2>(pairs[2], k255, inv, _mm256_unpacklo_epi16(hi, zero));
        const __m256i q3 = blend_pair<3>(pairs[3], k255, inv, _mm256_unpackhi_epi16(hi, zero));
        const __m256i packed =
            _mm256_packus_epi16(_mm256_packs_epi32(q0, q1), _mm256_packs_epi32(q2, q3));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(d + i), packed);
    }
    blend_run(d, n, s, k, i);
}

} // namespace

} // namespace casteljau::detail

#endif

namespace casteljau::detail {

template <class S, class K>
void blend_run_avx2(Premul8* d, int n, S s, K k) noexcept {
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
    blend8(d, n, source_of(s), coverage_of(k));
#else
    // No AVX2 here: use_avx2 is false and this is never called; defined
    // for the link, as the baseline form.
    blend_run(d, n, source_of(s), coverage_of(k));
#endif
}

template void blend_run_avx2(Premul8*, int, Premul, const float*) noexcept;
template void blend_run_avx2(Premul8*, int, Premul, float) noexcept;
template void blend_run_avx2(Premul8*, int, const Premul*, const float*) noexcept;
template void blend_run_avx2(Premul8*, int, const Premul*, float) noexcept;

} // namespace casteljau::detail
