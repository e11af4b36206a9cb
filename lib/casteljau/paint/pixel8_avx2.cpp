// pixel8.h's blend runs, eight pixels at a time with AVX2.
//
// The four-pixel SSE2 form's arithmetic, twice over: each 256-bit register
// holds pixel j of the eight in its low 128 bits and pixel j + 4 in its high
// ones, because AVX2's unpacks, shuffles and packs work within each 128-bit
// half. Every pixel so goes through the same multiplies, add and rounding
// as in the SSE2 form (no fused multiply-add: this file's target is AVX2
// alone), and the bytes are the same (tests/paint/pixel8_test.cpp). Measured
// against the SSE2 form: bench/README.md, 2026-11-29.
#include "casteljau/paint/pixel8.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#include <type_traits>

namespace casteljau::detail {

namespace {

// Pixels i to i + 7's coverage, per pixel or one for all.
[[gnu::target("avx2")]] __m256 eight(const float* k, int i) { return _mm256_loadu_ps(k + i); }
[[gnu::target("avx2")]] __m256 eight(float k, int) { return _mm256_set1_ps(k); }

// Pixel J (low half) and J + 4 (high half) of the eight: blend_lane's
// arithmetic on both.
template <int J>
[[gnu::target("avx2")]] __m256i blend_pair(__m256 src, __m256 k255, __m256 inv, __m256i lanes) {
    constexpr int pick = _MM_SHUFFLE(J, J, J, J);
    const __m256 scaled = _mm256_mul_ps(src, _mm256_shuffle_ps(k255, k255, pick));
    const __m256 kept = _mm256_mul_ps(_mm256_cvtepi32_ps(lanes), _mm256_shuffle_ps(inv, inv, pick));
    return _mm256_cvtps_epi32(_mm256_add_ps(scaled, kept));
}

// Pixel i + J's source (low half) and i + J + 4's (high half), and the
// eight pixels' source alphas: one color or a color per pixel.
template <int J>
[[gnu::target("avx2")]] __m256 pair_color(const Premul& s, int) {
    return _mm256_setr_ps(s.r, s.g, s.b, s.a, s.r, s.g, s.b, s.a);
}
template <int J>
[[gnu::target("avx2")]] __m256 pair_color(const Premul* s, int i) {
    return _mm256_set_m128(_mm_loadu_ps(&s[i + J + 4].r), _mm_loadu_ps(&s[i + J].r));
}
[[gnu::target("avx2")]] __m256 eight_alpha(const Premul& s, int) { return _mm256_set1_ps(s.a); }
[[gnu::target("avx2")]] __m256 eight_alpha(const Premul* s, int i) {
    return _mm256_setr_ps(s[i].a, s[i + 1].a, s[i + 2].a, s[i + 3].a, s[i + 4].a, s[i + 5].a,
                          s[i + 6].a, s[i + 7].a);
}

// The tail, to the four-pixel form.
void blend_tail(Premul8* d, int n, const Premul& s, float k) { blend_run(d, n, s, Constant{k}); }
void blend_tail(Premul8* d, int n, const Premul& s, const float* k) {
    blend_run(d, n, s, PerPixel{k});
}
void blend_tail(Premul8* d, int n, const Premul* s, float k) {
    blend_run(d, n, Colors{s}, Constant{k});
}
void blend_tail(Premul8* d, int n, const Premul* s, const float* k) {
    blend_run(d, n, Colors{s}, PerPixel{k});
}

template <class S, class K>
[[gnu::target("avx2")]] void blend8(Premul8* d, int n, S s, K k) noexcept {
    const __m256i zero = _mm256_setzero_si256();
    const __m256 one = _mm256_set1_ps(1.0f), scale = _mm256_set1_ps(255.0f);
    int i = 0;
    for (; i + 8 <= n; i += 8) {
        const __m256 kk = eight(k, i);
        const __m256 k255 = _mm256_mul_ps(kk, scale);
        const __m256 inv = _mm256_sub_ps(one, _mm256_mul_ps(kk, eight_alpha(s, i)));
        const __m256i bytes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(d + i));
        const __m256i lo = _mm256_unpacklo_epi8(bytes, zero),
                      hi = _mm256_unpackhi_epi8(bytes, zero);
        const __m256i q0 =
            blend_pair<0>(pair_color<0>(s, i), k255, inv, _mm256_unpacklo_epi16(lo, zero));
        const __m256i q1 =
            blend_pair<1>(pair_color<1>(s, i), k255, inv, _mm256_unpackhi_epi16(lo, zero));
        const __m256i q2 =
            blend_pair<2>(pair_color<2>(s, i), k255, inv, _mm256_unpacklo_epi16(hi, zero));
        const __m256i q3 =
            blend_pair<3>(pair_color<3>(s, i), k255, inv, _mm256_unpackhi_epi16(hi, zero));
        const __m256i packed =
            _mm256_packus_epi16(_mm256_packs_epi32(q0, q1), _mm256_packs_epi32(q2, q3));
        _mm256_storeu_si256(reinterpret_cast<__m256i*>(d + i), packed);
    }
    if constexpr (std::is_pointer_v<S>) {
        if constexpr (std::is_pointer_v<K>)
            blend_tail(d + i, n - i, s + i, k + i);
        else
            blend_tail(d + i, n - i, s + i, k);
    } else if constexpr (std::is_pointer_v<K>) {
        blend_tail(d + i, n - i, s, k + i);
    } else {
        blend_tail(d + i, n - i, s, k);
    }
}

} // namespace

void blend_run_avx2(Premul8* d, int n, const Premul& s, const float* k) noexcept {
    blend8<const Premul&>(d, n, s, k);
}

void blend_run_avx2(Premul8* d, int n, const Premul& s, float k) noexcept {
    blend8<const Premul&>(d, n, s, k);
}

void blend_run_avx2(Premul8* d, int n, const Premul* s, const float* k) noexcept {
    blend8(d, n, s, k);
}

void blend_run_avx2(Premul8* d, int n, const Premul* s, float k) noexcept { blend8(d, n, s, k); }

} // namespace casteljau::detail

#else

namespace casteljau::detail {

void blend_run_avx2(Premul8* d, int n, const Premul& s, const float* k) noexcept {
    blend_run(d, n, s, PerPixel{k});
}

void blend_run_avx2(Premul8* d, int n, const Premul& s, float k) noexcept {
    blend_run(d, n, s, Constant{k});
}

void blend_run_avx2(Premul8* d, int n, const Premul* s, const float* k) noexcept {
    blend_run(d, n, Colors{s}, PerPixel{k});
}

void blend_run_avx2(Premul8* d, int n, const Premul* s, float k) noexcept {
    blend_run(d, n, Colors{s}, Constant{k});
}

} // namespace casteljau::detail

#endif
