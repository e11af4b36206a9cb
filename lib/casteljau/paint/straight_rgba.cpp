#include "casteljau/paint/straight_rgba.h"

#include <cstddef>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace casteljau {

template <class Pixel>
void straight_rgba(const BasicCanvas<Pixel>& canvas, std::span<float> out) {
    const int w = canvas.width(), h = canvas.height();
    for (int y = 0; y < h; ++y) {
        const Pixel* src = canvas.row(y);
        float* dst = out.data() + std::size_t(y) * std::size_t(w) * 4;
        for (int x = 0; x < w; ++x, dst += 4) {
            const Rgba c = straight_of(to_premul(src[x]));
            dst[0] = c.r, dst[1] = c.g, dst[2] = c.b, dst[3] = c.a;
        }
    }
}

namespace {

/// straight_of and channel_to_u8 of one pixel, to 4 bytes at `dst`.
inline void straight_bytes(const Premul& p, std::uint8_t* dst) {
#if defined(__SSE2__)
    // The same operations on the four channels at once, each giving the
    // scalar code's bits: the one division, the products by 1 / a (alpha
    // kept), then minps(1, v) = (1 < v ? 1 : v), which is std::min(v, 1)
    // NaN included; maxps(s, 0) = (s > 0 ? s : 0) sends NaN to 0; then
    // truncation plus one where the fraction is at least 1/2.
    const float inv = p.a > 0 ? 1.0f / p.a : 0.0f;
    const __m128 v = _mm_setr_ps(p.r, p.g, p.b, p.a);
    const __m128 alpha_lane = _mm_castsi128_ps(_mm_setr_epi32(0, 0, 0, -1));
    const __m128 scaled = _mm_or_ps(_mm_and_ps(alpha_lane, v),
                                    _mm_andnot_ps(alpha_lane, _mm_mul_ps(v, _mm_set1_ps(inv))));
    const __m128 c = _mm_min_ps(_mm_set1_ps(1.0f), scaled);
    __m128 s = _mm_mul_ps(c, _mm_set1_ps(255.0f));
    s = _mm_min_ps(_mm_max_ps(s, _mm_setzero_ps()), _mm_set1_ps(255.0f));
    const __m128i t = _mm_cvttps_epi32(s);
    const __m128 half_up = _mm_cmpge_ps(_mm_sub_ps(s, _mm_cvtepi32_ps(t)), _mm_set1_ps(0.5f));
    const __m128i q = _mm_sub_epi32(t, _mm_castps_si128(half_up)); // the mask is -1
    const __m128i b = _mm_packus_epi16(_mm_packs_epi32(q, q), q);
    const auto bytes = std::uint32_t(_mm_cvtsi128_si32(b));
    std::memcpy(dst, &bytes, 4);
#else
    const Rgba c = straight_of(p);
    dst[0] = channel_to_u8(c.r), dst[1] = channel_to_u8(c.g);
    dst[2] = channel_to_u8(c.b), dst[3] = channel_to_u8(c.a);
#endif
}

} // namespace

template <class Pixel>
void straight_row8(const Pixel* src, int width, std::uint8_t* dst, bool onto_white) {
    for (int x = 0; x < width; ++x, dst += 4) {
        Premul p = to_premul(src[x]);
        // Transparent: straight_of gives 0 (and NaN, rounded, 0) in every
        // channel. Most of a drawing's background is.
        if (!(p.a > 0) && !onto_white) {
            std::memset(dst, 0, 4);
            continue;
        }
        if (onto_white) {
            const float k = 1.0f - p.a;
            p = {p.r + k, p.g + k, p.b + k, 1.0f};
        }
        straight_bytes(p, dst);
    }
}

template <class Pixel>
void straight_rgba8(const BasicCanvas<Pixel>& canvas, std::span<std::uint8_t> out,
                    bool onto_white) {
    const int w = canvas.width(), h = canvas.height();
    for (int y = 0; y < h; ++y)
        straight_row8(canvas.row(y), w, out.data() + std::size_t(y) * std::size_t(w) * 4,
                      onto_white);
}

template void straight_rgba(const Canvas&, std::span<float>);
template void straight_rgba(const Canvas8&, std::span<float>);
template void straight_rgba8(const Canvas&, std::span<std::uint8_t>, bool);
template void straight_rgba8(const Canvas8&, std::span<std::uint8_t>, bool);
template void straight_row8(const Premul*, int, std::uint8_t*, bool);
template void straight_row8(const Premul8*, int, std::uint8_t*, bool);

} // namespace casteljau
