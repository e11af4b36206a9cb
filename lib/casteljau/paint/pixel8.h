// 8-bit premultiplied pixels: the storage of Canvas8, and source-over onto them.
//
// A Premul8 holds round(255 v) for each premultiplied channel v in [0, 1],
// bytes in the order R, G, B, A (OpenImageIO's and PNG's order; Cairo's
// ARGB32 and Skia's N32 are this with the channels in another order).
// Source-over with coverage k of a premultiplied float source S is computed
// in float from the stored bytes D and rounded once:
//   D' = round(255 k S + (1 - k S.a) D),
// so each composite is within half a step (0.5/255) of the float canvas's
// result from the same starting pixel, and a pixel composited m times is
// within m/2 steps of it. Coverage 0 leaves the bytes as they are; coverage
// 1 of an opaque source stores round(255 S). Rounding is to nearest, ties to
// even (the SSE conversion's default mode; the portable path uses the same).
// Pixels are 4 bytes against the float canvas's 16: a quarter of the memory
// traffic per composited pixel, which is what large covered areas and
// several threads are limited by (bench/README.md).
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/paint/cpu.h"

#include <bit>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#else
#include <algorithm>
#include <cmath>
#endif

namespace casteljau {

/// A premultiplied color at 8 bits a channel, R, G, B, A in memory.
struct Premul8 {
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
    /// Exact equality of every channel.
    constexpr bool operator==(const Premul8&) const = default;
};

/// The float color a pixel holds (channels / 255).
inline Premul to_premul(Premul8 p) {
    constexpr float s = 1.0f / 255.0f;
    return {float(p.r) * s, float(p.g) * s, float(p.b) * s, float(p.a) * s};
}

#if defined(__SSE2__)
namespace detail {
// Four channels already scaled to [0, 255], rounded to nearest (even) and
// saturated to bytes.
inline Premul8 pack8(__m128 v) {
    const __m128i q = _mm_cvtps_epi32(v);
    const __m128i b = _mm_packus_epi16(_mm_packs_epi32(q, q), q);
    return std::bit_cast<Premul8>(std::uint32_t(_mm_cvtsi128_si32(b)));
}
} // namespace detail
#endif

/// The nearest 8-bit pixel to a premultiplied color (channels clamped to [0, 1]).
inline Premul8 quantize(const Premul& c) {
#if defined(__SSE2__)
    return detail::pack8(_mm_mul_ps(_mm_setr_ps(c.r, c.g, c.b, c.a), _mm_set1_ps(255.0f)));
#else
    const auto q = [](float v) {
        return std::uint8_t(std::nearbyint(std::clamp(v * 255.0f, 0.0f, 255.0f)));
    };
    return {q(c.r), q(c.g), q(c.b), q(c.a)};
#endif
}

/// Source-over of premultiplied `s` scaled by coverage k onto the 8-bit pixel d.
inline void blend_over(Premul8& d, const Premul& s, float k) {
    const float inv = 1.0f - k * s.a;
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    const __m128i bytes = _mm_cvtsi32_si128(int(std::bit_cast<std::uint32_t>(d)));
    const __m128i lanes = _mm_unpacklo_epi16(_mm_unpacklo_epi8(bytes, zero), zero);
    const __m128 src = _mm_mul_ps(_mm_setr_ps(s.r, s.g, s.b, s.a), _mm_set1_ps(255.0f * k));
    d = detail::pack8(_mm_add_ps(src, _mm_mul_ps(_mm_cvtepi32_ps(lanes), _mm_set1_ps(inv))));
#else
    const float k255 = 255.0f * k;
    const auto q = [&](float sv, std::uint8_t dv) {
        return std::uint8_t(std::nearbyint(std::clamp(sv * k255 + float(dv) * inv, 0.0f, 255.0f)));
    };
    d = {q(s.r, d.r), q(s.g, d.g), q(s.b, d.b), q(s.a, d.a)};
#endif
}

#if defined(__SSE2__)
namespace detail {
// Source-over of the pixel with channels `lanes` (32-bit integers) under
// lane J of the four pixels' 255 k and 1 - k S.a: blend_over's arithmetic,
// rounded to integers, not yet packed.
template <int J>
__m128i blend_lane(__m128 src, __m128 k255, __m128 inv, __m128i lanes) {
    constexpr int pick = _MM_SHUFFLE(J, J, J, J);
    const __m128 scaled = _mm_mul_ps(src, _mm_shuffle_ps(k255, k255, pick));
    const __m128 kept = _mm_mul_ps(_mm_cvtepi32_ps(lanes), _mm_shuffle_ps(inv, inv, pick));
    return _mm_cvtps_epi32(_mm_add_ps(scaled, kept));
}
} // namespace detail
#endif

namespace detail {
/// Coverage per pixel, as blend_run reads it: one pixel or four at a time.
struct PerPixel {
    const float* k; ///< the run's coverage values
    /// Pixel i's coverage.
    float at(int i) const { return k[i]; }
#if defined(__SSE2__)
    /// Pixels i to i + 3's coverage.
    __m128 four(int i) const { return _mm_loadu_ps(k + i); }
#endif
};
/// One coverage for the whole run, as blend_run reads it.
struct Constant {
    float k; ///< every pixel's coverage
    /// Pixel i's coverage.
    float at(int) const { return k; }
#if defined(__SSE2__)
    /// Pixels i to i + 3's coverage.
    __m128 four(int) const { return _mm_set1_ps(k); }
#endif
};

/// One source color for the whole run, as blend_run reads it.
struct OneColor {
    /// Every pixel's source is `c`.
    explicit OneColor(const Premul& c) : s(c) {}
    Premul s; ///< every pixel's source
    /// Pixel i's source.
    const Premul& at(int) const { return s; }
#if defined(__SSE2__)
    /// Pixel i + J's source as four lanes (the same for every pixel).
    template <int J>
    __m128 color(int) const {
        return src;
    }
    /// The source alpha of the four pixels whose colors are c.
    __m128 four_alpha(const __m128*) const { return alpha; }
    __m128 src = _mm_setr_ps(s.r, s.g, s.b, s.a); ///< the source's lanes, made once
    __m128 alpha = _mm_set1_ps(s.a);              ///< its alpha in every lane
#endif
};
/// A source color per pixel (a shader's), as blend_run reads it.
struct Colors {
    const Premul* s; ///< the run's source colors
    /// Pixel i's source.
    const Premul& at(int i) const { return s[i]; }
#if defined(__SSE2__)
    /// Pixel i + J's source as four lanes.
    template <int J>
    __m128 color(int i) const {
        return _mm_loadu_ps(&s[i + J].r);
    }
    /// The source alphas of the four pixels whose colors are c[0] to c[3]:
    /// lane 3 of each, by two unpacks and a shuffle (four scalar loads and
    /// inserts cost more).
    __m128 four_alpha(const __m128* c) const {
        const __m128 a01 = _mm_unpackhi_ps(c[0], c[1]); // [b0 b1 a0 a1]
        const __m128 a23 = _mm_unpackhi_ps(c[2], c[3]); // [b2 b3 a2 a3]
        return _mm_shuffle_ps(a01, a23, _MM_SHUFFLE(3, 2, 3, 2));
    }
#endif
};

// blend_over of `source` onto d[from, n) through `coverage`: the same bits
// as the loop of blend_over, four pixels at a time (one 16-byte load and
// store, the coverage-dependent factors computed for four at once). `from`
// lets the eight-pixel AVX2 form finish its run here.
template <class Source, class Coverage>
void blend_run(Premul8* d, int n, const Source& source, Coverage coverage, int from = 0) {
    int i = from;
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    const __m128 one = _mm_set1_ps(1.0f), scale = _mm_set1_ps(255.0f);
    for (; i + 4 <= n; i += 4) {
        const __m128 kk = coverage.four(i);
        const __m128 k255 = _mm_mul_ps(kk, scale);
        const __m128 colors[4] = {source.template color<0>(i), source.template color<1>(i),
                                  source.template color<2>(i), source.template color<3>(i)};
        const __m128 inv = _mm_sub_ps(one, _mm_mul_ps(kk, source.four_alpha(colors)));
        const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(d + i));
        const __m128i lo = _mm_unpacklo_epi8(bytes, zero), hi = _mm_unpackhi_epi8(bytes, zero);
        const __m128i q0 = blend_lane<0>(colors[0], k255, inv, _mm_unpacklo_epi16(lo, zero));
        const __m128i q1 = blend_lane<1>(colors[1], k255, inv, _mm_unpackhi_epi16(lo, zero));
        const __m128i q2 = blend_lane<2>(colors[2], k255, inv, _mm_unpacklo_epi16(hi, zero));
        const __m128i q3 = blend_lane<3>(colors[3], k255, inv, _mm_unpackhi_epi16(hi, zero));
        const __m128i packed = _mm_packus_epi16(_mm_packs_epi32(q0, q1), _mm_packs_epi32(q2, q3));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(d + i), packed);
    }
#endif
    for (; i < n; ++i) blend_over(d[i], source.at(i), coverage.at(i));
}

// The policies of a run's arguments: one color or a color per pixel, one
// coverage or a coverage per pixel.
inline OneColor source_of(const Premul& s) { return OneColor{s}; }
inline Colors source_of(const Premul* s) { return Colors{s}; }
inline Constant coverage_of(float k) { return Constant{k}; }
inline PerPixel coverage_of(const float* k) { return PerPixel{k}; }

/// blend_run eight pixels at a time (AVX2: two pixels to a register, each
/// with the four-pixel form's arithmetic, so the same bits); only where
/// cpu_has_avx2() (cpu.h). S is one color (Premul) or a color per pixel
/// (const Premul*), K one coverage (float) or one per pixel (const float*):
/// those four are instantiated in pixel8_avx2.cpp.
template <class S, class K>
void blend_run_avx2(Premul8* d, int n, S s, K k) noexcept;

// The form this CPU runs best: runs shorter than eight pixels have no
// eight-pixel body, and go to the four-pixel form directly.
template <class S, class K>
void blend_chosen(Premul8* d, int n, S s, K k) {
    if (use_avx2 && n >= 8)
        blend_run_avx2(d, n, s, k);
    else
        blend_run(d, n, source_of(s), coverage_of(k));
}
} // namespace detail

/// blend_over of `s` onto d[0, n), pixel i through coverage k[i]. An opaque
/// source needs no run-by-run test for full coverage: k = 1 gives inv = 0
/// and round(255 S + 0 D) = quantize(S), the store's bits.
inline void blend_span_over(Premul8* d, int n, const Premul& s, const float* k) {
    detail::blend_chosen(d, n, s, k);
}

/// blend_over of `s` onto d[0, n), every pixel through coverage k.
inline void blend_span_over(Premul8* d, int n, const Premul& s, float k) {
    detail::blend_chosen(d, n, s, k);
}

/// blend_over of shaded colors s[i] onto d[0, n), pixel i through coverage
/// k[i] (ShadedSpanPainter's run).
inline void blend_shaded_over(Premul8* d, int n, const Premul* s, const float* k) {
    detail::blend_chosen(d, n, s, k);
}

/// blend_over of shaded colors s[i] onto d[0, n), every pixel through coverage k.
inline void blend_shaded_over(Premul8* d, int n, const Premul* s, float k) {
    detail::blend_chosen(d, n, s, k);
}

} // namespace casteljau
