#include "casteljau/paint/image_shader.h"

#include "casteljau/geom/pixel_index.h"
#include "casteljau/paint/cpu.h"

#include <algorithm>
#include <cmath>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#define CASTELJAU_X86_DISPATCH 1
#include <immintrin.h>
#endif

namespace casteljau {

namespace {

/// Truncated value v as an index into [0, n): NaN gives 0, anything beyond
/// the range its end. For v >= 0 truncation is floor; below 0 the index is 0
/// anyway. Compared in double, so no out-of-range value meets int.
int clamp_index(double v, int n) { return v >= 0 ? (v < n ? int(v) : n - 1) : 0; }

/// v reduced to [0, n] by floor-mod, with the reciprocal 1 / n: the quotient
/// may round to the neighbouring integer, which one step corrects. The
/// bound n itself (rounding again) and NaN are left to clamp_index.
[[gnu::always_inline]] inline double wrap(double v, int n, double inv_n) {
    double r = v - n * floor_whole(v * inv_n);
    if (r < 0) r += n;
    if (r >= n) r -= n;
    return r;
}

using Axis = ImageShader::Axis;

/// The pixels and weight of a bilinear sample at v along an axis of n pixels.
[[gnu::always_inline]] inline Axis bilinear_axis(double v, int n, double inv_n, bool repeat) {
    double u = v - 0.5; // pixel centres at integers
    u = repeat ? wrap(u, n, inv_n) : (u >= 0 ? std::min(u, n - 1.0) : 0.0);
    const int i = clamp_index(u, n);
    const double t = u - i; // in [0, 1] but for NaN, or rounding at huge u
    return {i, i + 1 < n ? i + 1 : (repeat ? 0 : n - 1), float(t >= 0 ? std::min(t, 1.0) : 0.0)};
}

#if defined(__SSE2__)
/// bilinear_axis(v, n, ., false) of two coordinates at once, operation for
/// operation: maxpd gives 0 for NaN, as the scalar form's test does, and -0
/// for +0 beside it, which weighs a sample the same.
struct PadAxes {
    PadAxes(__m128d v, int n) {
        const __m128d u = _mm_min_pd(_mm_max_pd(_mm_sub_pd(v, _mm_set1_pd(0.5)), _mm_setzero_pd()),
                                     _mm_set1_pd(n - 1.0));
        const __m128i i = _mm_cvttpd_epi32(u);
        const __m128 t = _mm_cvtpd_ps(_mm_sub_pd(u, _mm_cvtepi32_pd(i)));
        i0[0] = _mm_cvtsi128_si32(i), i0[1] = _mm_cvtsi128_si32(_mm_shuffle_epi32(i, 1));
        _mm_storel_pi(reinterpret_cast<__m64*>(weight), t);
        last = n - 1;
    }
    Axis lane(int k) const { return {i0[k], i0[k] < last ? i0[k] + 1 : last, weight[k]}; }
    int i0[2];
    float weight[2];
    int last;
};
#endif

Premul lerp(const Premul& a, const Premul& b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
            a.a + (b.a - a.a) * t};
}

/// A color times the opacity k (inlined by force: once a pixel).
[[gnu::always_inline]] inline Premul scaled(const Premul& c, float k) {
    return {c.r * k, c.g * k, c.b * k, c.a * k};
}

/// out[i] = lerp(top[i], bottom[i], t) times `opacity`, for i in [0, n):
/// the vertical half of a level row's samples (a pixel a vector).
void lerp_rows(const Premul* top, const Premul* bottom, float t, float opacity, int n,
               Premul* out) {
    for (int i = 0; i < n; ++i) out[i] = scaled(lerp(top[i], bottom[i], t), opacity);
}

/// out[c] = lerp(row[i0], row[i1], t) of column c's axis, for c in
/// [from, to): an image row sampled along the tabulated columns. Returns
/// whether every sample's alpha is exactly 1.
bool lerp_columns(const Premul* row, const Axis* columns, int from, int to, Premul* out) {
    bool opaque = true;
    for (int c = from; c < to; ++c) {
        const Axis& ax = columns[c];
        out[c] = lerp(row[ax.i0], row[ax.i1], ax.t);
        opaque = opaque && out[c].a == 1.0f;
    }
    return opaque;
}

/// out[i] = quantize(lerp(top[i], bottom[i], t)), for i in [0, n): opaque
/// samples at opacity 1 as source-over at coverage 1 stores them
/// (ImageShader::store_opaque).
void quantize_rows(const Premul* top, const Premul* bottom, float t, int n, Premul8* out) {
    for (int i = 0; i < n; ++i) out[i] = quantize(lerp(top[i], bottom[i], t));
}

#if defined(CASTELJAU_X86_DISPATCH)
// The AVX forms. GCC does not compile AVX intrinsics in lambdas of a
// function that has the target, hence small functions.

/// Pixels *p (low half) and *q (high half) in one vector.
[[gnu::target("avx2")]] __m256 pixel_pair(const Premul* p, const Premul* q) {
    return _mm256_set_m128(_mm_loadu_ps(&q->r), _mm_loadu_ps(&p->r));
}
/// Weight a in the low half, b in the high half.
[[gnu::target("avx2")]] __m256 weight_pair(float a, float b) {
    return _mm256_set_m128(_mm_set1_ps(b), _mm_set1_ps(a));
}
/// lerp() of two pixels a vector: each lane the scalar form's operations,
/// and no multiply-add (these functions' target is AVX2 alone), so the
/// same bits.
[[gnu::target("avx2")]] __m256 lerp2(__m256 a, __m256 b, __m256 t) {
    return _mm256_add_ps(a, _mm256_mul_ps(_mm256_sub_ps(b, a), t));
}

/// lerp_columns two columns a vector, the alphas compared with 1 as they
/// are stored; the last odd column goes to the form above.
[[gnu::target("avx2")]] bool lerp_columns_avx2(const Premul* row, const Axis* columns, int from,
                                               int to, Premul* out) {
    const __m256 one = _mm256_set1_ps(1.0f);
    __m256 ones = _mm256_castsi256_ps(_mm256_set1_epi32(-1)); // lanes equal to 1 so far
    int c = from;
    for (; c + 2 <= to; c += 2) {
        const Axis &x0 = columns[c], &x1 = columns[c + 1];
        const __m256 v = lerp2(pixel_pair(row + x0.i0, row + x1.i0),
                               pixel_pair(row + x0.i1, row + x1.i1), weight_pair(x0.t, x1.t));
        _mm256_storeu_ps(&out[c].r, v);
        ones = _mm256_and_ps(ones, _mm256_cmp_ps(v, one, _CMP_EQ_OQ));
    }
    // Lanes 3 and 7: the two pixels' alphas.
    const bool opaque = (_mm256_movemask_ps(ones) & 0x88) == 0x88;
    return lerp_columns(row, columns, c, to, out) && opaque;
}

/// PadAxes of four coordinates: the pixels and weights along one axis.
[[gnu::target("avx2")]] void pad_axes4(__m256d v, int size, int* i0, int* i1, float* t) {
    const __m256d u =
        _mm256_min_pd(_mm256_max_pd(_mm256_sub_pd(v, _mm256_set1_pd(0.5)), _mm256_setzero_pd()),
                      _mm256_set1_pd(size - 1.0));
    const __m128i i = _mm256_cvttpd_epi32(u);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(i0), i);
    _mm_storeu_si128(reinterpret_cast<__m128i*>(i1),
                     _mm_min_epi32(_mm_add_epi32(i, _mm_set1_epi32(1)), _mm_set1_epi32(size - 1)));
    _mm_storeu_ps(t, _mm256_cvtpd_ps(_mm256_sub_pd(u, _mm256_cvtepi32_pd(i))));
}
/// a cx + c_cy + e, c_cy being c cy.
[[gnu::target("avx2")]] __m256d mapped4(__m256d cx, double a, double c_cy, double e) {
    return _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(_mm256_set1_pd(a), cx), _mm256_set1_pd(c_cy)),
                         _mm256_set1_pd(e));
}

/// The padded bilinear samples of a turned map (PadAxes and the sample of
/// shade()'s SSE2 loop) four device pixels a pass, from pixel x of row cy:
/// the four sample points in one vector of doubles, each pair of pixels'
/// lerps in one vector of floats, lane by lane the same operations, so the
/// same bits. Returns how many of the n pixels it shaded (a multiple of 4).
[[gnu::target("avx2")]] int shade_turned_avx2(const RasterImage& im, const Affine& m, int x,
                                              double cy, int n, float opacity, Premul* out) {
    const Premul* px = im.pixels.data();
    const std::size_t w = std::size_t(im.width);
    const __m256 o = _mm256_set1_ps(opacity);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        const __m256d cx = _mm256_add_pd(
            _mm256_cvtepi32_pd(_mm_add_epi32(_mm_set1_epi32(x + i), _mm_setr_epi32(0, 1, 2, 3))),
            _mm256_set1_pd(0.5));
        alignas(16) int x0[4], x1[4], y0[4], y1[4];
        alignas(16) float tx[4], ty[4];
        pad_axes4(mapped4(cx, m.a, m.c * cy, m.e), im.width, x0, x1, tx);
        pad_axes4(mapped4(cx, m.b, m.d * cy, m.f), im.height, y0, y1, ty);
        for (int k = 0; k < 4; k += 2) {
            const Premul* r0 = px + std::size_t(y0[k]) * w;
            const Premul* r1 = px + std::size_t(y0[k + 1]) * w;
            const Premul* s0 = px + std::size_t(y1[k]) * w;
            const Premul* s1 = px + std::size_t(y1[k + 1]) * w;
            const __m256 wx = weight_pair(tx[k], tx[k + 1]);
            const __m256 top = lerp2(pixel_pair(r0 + x0[k], r1 + x0[k + 1]),
                                     pixel_pair(r0 + x1[k], r1 + x1[k + 1]), wx);
            const __m256 bottom = lerp2(pixel_pair(s0 + x0[k], s1 + x0[k + 1]),
                                        pixel_pair(s0 + x1[k], s1 + x1[k + 1]), wx);
            _mm256_storeu_ps(&out[i + k].r,
                             _mm256_mul_ps(lerp2(top, bottom, weight_pair(ty[k], ty[k + 1])), o));
        }
    }
    return i;
}

/// lerp_rows two pixels a vector; the last odd pixel goes to the form
/// above. Measured: bench/README.md, 2026-11-29.
[[gnu::target("avx2")]] void lerp_rows_avx2(const Premul* top, const Premul* bottom, float t,
                                            float opacity, int n, Premul* out) {
    const __m256 tt = _mm256_set1_ps(t), o = _mm256_set1_ps(opacity);
    int i = 0;
    for (; i + 2 <= n; i += 2) {
        const __m256 c = lerp2(_mm256_loadu_ps(&top[i].r), _mm256_loadu_ps(&bottom[i].r), tt);
        _mm256_storeu_ps(&out[i].r, _mm256_mul_ps(c, o));
    }
    lerp_rows(top + i, bottom + i, t, opacity, n - i, out + i);
}

/// quantize_rows four pixels a pass: lerp_rows_avx2's lerps, then
/// quantize's product, rounding and saturating packs, four pixels at once.
[[gnu::target("avx2")]] void quantize_rows_avx2(const Premul* top, const Premul* bottom, float t,
                                                int n, Premul8* out) {
    const __m256 tt = _mm256_set1_ps(t), s = _mm256_set1_ps(255.0f);
    int i = 0;
    for (; i + 4 <= n; i += 4) {
        __m256i q[2];
        for (int k = 0; k < 2; ++k) {
            const __m256 c = lerp2(_mm256_loadu_ps(&top[i + 2 * k].r),
                                   _mm256_loadu_ps(&bottom[i + 2 * k].r), tt);
            q[k] = _mm256_cvtps_epi32(_mm256_mul_ps(c, s));
        }
        const __m128i p01 =
            _mm_packs_epi32(_mm256_castsi256_si128(q[0]), _mm256_extracti128_si256(q[0], 1));
        const __m128i p23 =
            _mm_packs_epi32(_mm256_castsi256_si128(q[1]), _mm256_extracti128_si256(q[1], 1));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm_packus_epi16(p01, p23));
    }
    quantize_rows(top + i, bottom + i, t, n - i, out + i);
}
#endif

} // namespace

bool ImageShader::prepare(const RasterImage& image, const Affine& to_device, float opacity,
                          bool smooth, bool repeat) {
    if (image.width <= 0 || image.height <= 0) return false;
    // Singular only where the inverse is not finite: a pattern of 1e-6 px
    // tiles has a determinant of 1e-12 and is fine.
    const double det = to_device.determinant();
    if (det == 0 || !std::isfinite(det) || !to_device.is_finite()) return false;
    const Affine inverse = to_device.inverse();
    if (!inverse.is_finite()) return false;
    image_ = &image;
    inverse_ = inverse;
    inv_w_ = 1.0 / image.width;
    inv_h_ = 1.0 / image.height;
    opacity_ = opacity;
    smooth_ = smooth;
    repeat_ = repeat;
    // 2^40: far past any image side and frame coordinate, and below 2^52,
    // where every double is whole: x + shift stays exact in long long.
    const auto whole = [](double v) { return std::fabs(v) < 0x1p40 && v == floor_whole(v); };
    aligned_ = inverse.a == 1 && inverse.b == 0 && inverse.c == 0 && inverse.d == 1 &&
               whole(inverse.e) && whole(inverse.f);
    shift_x_ = aligned_ ? static_cast<long long>(inverse.e) : 0;
    shift_y_ = aligned_ ? static_cast<long long>(inverse.f) : 0;
    columns_.clear();
    return true;
}

void ImageShader::tabulate(int x0, int x1) {
    columns_.clear();
    const Affine& m = inverse_;
    if (!image_ || !smooth_ || aligned_ || m.b != 0 || m.c != 0 || x1 <= x0) return;
    // p.x = a (x + 0.5) + c cy + e with c = 0 is the same for every row cy
    // (c cy is +-0, and any contraction into multiply-adds adds it exactly),
    // so row 0's expression gives each row's value.
    columns_x0_ = x0;
    columns_.resize(std::size_t(x1 - x0));
    for (Along& a : along_) a.row = -1;
    for (int x = x0; x < x1; ++x)
        columns_[std::size_t(x - x0)] =
            bilinear_axis((m * Point{x + 0.5, 0.5}).x, image_->width, inv_w_, repeat_);
}

const ImageShader::Along& ImageShader::along(int j, int keep, int lo, int hi) const {
    // The slot holding row j, else the one not holding `keep`, the row
    // sampled beside it.
    const std::size_t k = along_[0].row == j      ? 0
                          : along_[1].row == j    ? 1
                          : along_[0].row == keep ? 1
                                                  : 0;
    Along& a = along_[k];
    const std::size_t size = columns_.size();
    if (a.pixels.size() < size) a.pixels.resize(size);
    const Premul* row = image_->pixels.data() + std::size_t(j) * std::size_t(image_->width);
    const auto fill = [&](int from, int to) {
#if defined(CASTELJAU_X86_DISPATCH)
        if (use_avx2) return lerp_columns_avx2(row, columns_.data(), from, to, a.pixels.data());
#endif
        return lerp_columns(row, columns_.data(), from, to, a.pixels.data());
    };
    if (a.row != j || hi < a.lo || lo > a.hi) { // another row, or columns apart from those held
        a.opaque = fill(lo, hi);
        a.row = j, a.lo = lo, a.hi = hi;
    } else { // the same row: the columns on either side of those held
        if (lo < a.lo) a.opaque = fill(lo, a.lo) && a.opaque, a.lo = lo;
        if (hi > a.hi) a.opaque = fill(a.hi, hi) && a.opaque, a.hi = hi;
    }
    return a;
}

bool ImageShader::level_rows(int x, int y, int n, LevelRows& r) const {
    // b == 0: p.y = b (x + 0.5) + d cy + f is the same for every x (b x is
    // +-0, and adding a zero changes no value but a zero's sign, which no
    // sample below tells apart). Taken from the same expression as each
    // pixel's p.y (not d cy + f), so that a build that fuses multiply-adds
    // rounds it the same way.
    const Affine& m = inverse_;
    if (m.b != 0) return false;
    // In long long: x + n may be past int's range (x is any pixel at()).
    const long long first = static_cast<long long>(x) - columns_x0_;
    if (first < 0 || first + n > static_cast<long long>(columns_.size())) return false;
    const Axis row_axis =
        bilinear_axis((m * Point{x + 0.5, y + 0.5}).y, image_->height, inv_h_, repeat_);
    const int lo = int(first), hi = lo + n;
    const Along& top = along(row_axis.i0, row_axis.i1, lo, hi);
    const Along& bottom = along(row_axis.i1, row_axis.i0, lo, hi);
    r = {top.pixels.data() + lo, bottom.pixels.data() + lo, row_axis.t,
         top.opaque && bottom.opaque};
    return true;
}

Premul ImageShader::at(int x, int y) const {
    Premul c;
    shade(x, y, 1, &c);
    return c;
}

template <class P, class Copy>
void ImageShader::copy_stretches(const std::vector<P>& pixels, int x, int y, int n,
                                 Copy&& copy) const {
    const RasterImage& im = *image_;
    const int w = im.width;
    // The index of column or row k: tiled by floor-mod, or padded.
    const auto index = [&](long long k, int size) {
        return int(repeat_ ? (k % size + size) % size : std::clamp<long long>(k, 0, size - 1));
    };
    const P* row = pixels.data() + std::size_t(index(y + shift_y_, im.height)) * std::size_t(w);
    // Whole stretches of the row, not a pixel and an index test at a time (a
    // pattern's tiles are copied rows: a third of the 2k-patterns frame went
    // to that loop).
    const long long first = x + shift_x_;
    if (repeat_) {
        for (int k = 0, i = index(first, w); k < n; k += w - i, i = 0)
            copy(row + i, std::min(n - k, w - i), k);
        return;
    }
    // Padded: the first column left of the image, the last right of it, the
    // row between (in long long: first + n may be past int's range).
    const int left = int(std::clamp<long long>(-first, 0, n));
    const int right = int(std::clamp<long long>(first + n - w, 0, n - left));
    for (int k = 0; k < left; ++k) copy(row, 1, k);
    if (n - left - right > 0) copy(row + (first + left), n - left - right, left);
    for (int k = n - right; k < n; ++k) copy(row + (w - 1), 1, k);
}

void ImageShader::copy_row(int x, int y, int n, Premul* out) const {
    // At opacity 1 a plain copy: c * 1 is c, bit for bit.
    copy_stretches(image_->pixels, x, y, n, [&](const Premul* from, int m, int k) {
        if (opacity_ == 1)
            std::copy(from, from + m, out + k);
        else
            for (int j = 0; j < m; ++j) out[k + j] = scaled(from[j], opacity_);
    });
}

bool ImageShader::store_opaque(int x, int y, int n, Premul8* out) const {
    if (opacity_ != 1) return false;
    if (aligned_) {
        if (image_->opaque8.empty()) return false;
        copy_stretches(image_->opaque8, x, y, n, [&](const Premul8* from, int m, int k) {
            std::copy(from, from + m, out + k);
        });
        return true;
    }
    LevelRows r;
    if (!smooth_ || !level_rows(x, y, n, r) || !r.opaque) return false;
#if defined(CASTELJAU_X86_DISPATCH)
    if (use_avx2) {
        quantize_rows_avx2(r.top, r.bottom, r.t, n, out);
        return true;
    }
#endif
    quantize_rows(r.top, r.bottom, r.t, n, out);
    return true;
}

void ImageShader::shade(int x, int y, int n, Premul* out) const {
    if (aligned_) return copy_row(x, y, n, out);
    const RasterImage& im = *image_;
    const Affine& m = inverse_;
    const double cy = y + 0.5;
    const Premul* px = im.pixels.data();
    const auto pixel = [&](int i, int j) { return px[std::size_t(j) * std::size_t(im.width) + i]; };
    if (!smooth_) {
        for (int i = 0; i < n; ++i) {
            const Point p = m * Point{x + i + 0.5, cy};
            const double u = repeat_ ? wrap(p.x, im.width, inv_w_) : p.x;
            const double v = repeat_ ? wrap(p.y, im.height, inv_h_) : p.y;
            out[i] = scaled(pixel(clamp_index(u, im.width), clamp_index(v, im.height)), opacity_);
        }
        return;
    }
    if (LevelRows r; level_rows(x, y, n, r)) {
#if defined(CASTELJAU_X86_DISPATCH)
        if (use_avx2) return lerp_rows_avx2(r.top, r.bottom, r.t, opacity_, n, out);
#endif
        return lerp_rows(r.top, r.bottom, r.t, opacity_, n, out);
    }
    // Level (b == 0): the row's vertical half of the sample is the same for
    // every pixel (level_rows).
    const bool level = m.b == 0;
    const Axis row_axis =
        level ? bilinear_axis((m * Point{x + 0.5, cy}).y, im.height, inv_h_, repeat_) : Axis{};
    int i = 0;
#if defined(__SSE2__)
    // Padded and turned: two pixels' axes at a time (the turned image's
    // frame 1.07 -> 0.84x Cairo's time); tiling's floor-mod has no SSE2 form.
    if (!repeat_ && !level) {
#if defined(CASTELJAU_X86_DISPATCH)
        if (use_avx2) i = shade_turned_avx2(im, m, x, cy, n, opacity_, out);
#endif
        const auto sample = [&](const Axis& ax, const Axis& ay) {
            return scaled(lerp(lerp(pixel(ax.i0, ay.i0), pixel(ax.i1, ay.i0), ax.t),
                               lerp(pixel(ax.i0, ay.i1), pixel(ax.i1, ay.i1), ax.t), ay.t),
                          opacity_);
        };
        for (; i + 2 <= n; i += 2) {
            const __m128d cx = _mm_add_pd(_mm_cvtepi32_pd(_mm_setr_epi32(x + i, x + i + 1, 0, 0)),
                                          _mm_set1_pd(0.5));
            const auto mapped = [&](double a, double c, double e) { // a cx + c cy + e
                return _mm_add_pd(_mm_add_pd(_mm_mul_pd(_mm_set1_pd(a), cx), _mm_set1_pd(c * cy)),
                                  _mm_set1_pd(e));
            };
            PadAxes ax(mapped(m.a, m.c, m.e), im.width), ay(mapped(m.b, m.d, m.f), im.height);
            out[i] = sample(ax.lane(0), ay.lane(0));
            out[i + 1] = sample(ax.lane(1), ay.lane(1));
        }
    }
#endif
    for (; i < n; ++i) {
        const Point p = m * Point{x + i + 0.5, cy};
        const Axis ax = bilinear_axis(p.x, im.width, inv_w_, repeat_);
        const Axis ay = level ? row_axis : bilinear_axis(p.y, im.height, inv_h_, repeat_);
        out[i] = scaled(lerp(lerp(pixel(ax.i0, ay.i0), pixel(ax.i1, ay.i0), ax.t),
                             lerp(pixel(ax.i0, ay.i1), pixel(ax.i1, ay.i1), ax.t), ay.t),
                        opacity_);
    }
}

} // namespace casteljau
