#include "casteljau/paint/gradient.h"

#include "casteljau/geom/pixel_index.h"
#include "casteljau/paint/cpu.h"

#include <algorithm>
#include <array>
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

float to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}
float to_srgb(float v) {
    return v <= 0.0031308f ? v * 12.92f : 1.055f * std::pow(v, 1 / 2.4f) - 0.055f;
}

Rgba lerp(Rgba a, Rgba b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
            a.a + (b.a - a.a) * t};
}

[[gnu::always_inline]] inline double spread(double t, Spread s) {
    switch (s) {
    case Spread::Pad:
        return std::clamp(t, 0.0, 1.0);
    case Spread::Repeat:
        return t - floor_whole(t);
    case Spread::Reflect: {
        const double m = t - 2.0 * floor_whole(t * 0.5); // [0, 2)
        return m > 1.0 ? 2.0 - m : m;
    }
    }
    return t;
}

/// The t of a cone's point d from the start circle's centre (top of the
/// file), or NaN outside the cone.
inline double cone_parameter(const GradientShader::RadialForm& r, Vec2 d) {
    // In units of the circles' size (t does not change), so that no square
    // overflows where the circles reach 1e300.
    const double k = r.unit;
    const Vec2 e = (r.center - r.focal) * k;
    d = d * k;
    const double r0 = r.r0 * k, dr = r.dr * k;
    const double a = e.length_sq() - dr * dr, b = d.dot(e) + r0 * dr;
    const double c = d.length_sq() - r0 * r0;
    const auto reached = [&](double t) { return r0 + t * dr >= 0; };
    // |a| this small against the terms it is the difference of: the start
    // circle touches the end one, and the quadratic is linear, -2 b t + c = 0.
    if (std::fabs(a) <= 1e-12 * (e.length_sq() + dr * dr)) {
        const double t = c / (2 * b);
        return b != 0 && reached(t) ? t : NAN;
    }
    // A discriminant below zero by rounding only (a point on the cone's
    // edge, where the root is double) is zero.
    const double disc = b * b - a * c;
    if (!(disc >= -1e-12 * (b * b + std::fabs(a * c)))) return NAN;
    const double root = std::sqrt(std::max(disc, 0.0)), t1 = (b + root) / a, t2 = (b - root) / a;
    const double hi = std::max(t1, t2), lo = std::min(t1, t2);
    return reached(hi) ? hi : reached(lo) ? lo : NAN;
}

/// The parameter before spread at gradient-space point q (the formulas above);
/// inlined by force into the radial loop of shade(), as it runs once a pixel.
[[gnu::always_inline]] inline double raw_parameter(const Gradient& g,
                                                   const GradientShader::RadialForm& r, Point q) {
    if (g.kind == Gradient::Kind::Linear) {
        const Vec2 axis = g.p2 - g.p1;
        const double len_sq = axis.length_sq();
        return len_sq > 0 ? (q - g.p1).dot(axis) / len_sq : 1.0; // coincident points: the last stop
    }
    if (g.radius <= 0) return 1.0; // zero radius: the last stop (13.2.3)
    if (r.cone) return cone_parameter(r, q - r.focal);
    const Vec2 d = q - r.focal, e = r.center - r.focal;
    const double a = e.length_sq() - r.dr * r.dr; // < 0: the start circle inside
    const double b = d.dot(e) + r.r0 * r.dr;
    const double t = (b - std::sqrt(std::max(0.0, b * b - a * (d.length_sq() - r.r0 * r.r0)))) / a;
    return r.t0 + r.t1 * t;
}

} // namespace

GradientShader::RadialForm GradientShader::radial_form(const Gradient& g) {
    // A cone (top of the file) where the start circle is not inside the end
    // circle by more than rounding: a focal point on the circle, as 0.4 - 0.1
    // and 0.7 - 0.4 put it, is one either side (the linear case).
    // (A zero radius paints the last stop, as the nested form does.)
    const double fr = std::max(g.focal_radius, 0.0);
    const Vec2 to_end = g.center - g.focal;
    if (g.radius > 0 && to_end.length() >= std::fabs(g.radius - fr) * (1 - 1e-12)) {
        const double size =
            std::max({std::fabs(to_end.x), std::fabs(to_end.y), fr, std::fabs(g.radius)});
        return RadialForm{g.focal, g.center, fr, g.radius - fr, 0, 1, true, 1 / size};
    }
    // A start circle larger than the end circle is the same family of
    // circles run the other way (SVG 2, 14.3.4's larger t over smaller t,
    // with one circle holding the other): swapped, and t read as 1 - t.
    RadialForm r{g.focal, g.center, fr, g.radius, 0, 1};
    double r1 = g.radius;
    if (r.r0 > r1) {
        std::swap(r.focal, r.center), std::swap(r.r0, r1);
        r.t0 = 1, r.t1 = -1;
    }
    // A start circle within a thousandth of the end circle's edge moves
    // that far inside, so that the quadratic has its single root on a
    // circle of positive radius, well conditioned (top of the file).
    r.r0 = std::min(r.r0, 0.999 * r1), r.dr = r1 - r.r0;
    const Vec2 e = r.focal - r.center;
    const double limit = 0.999 * r.dr;
    if (e.length() > limit) r.focal = r.center + e * (limit / e.length());
    return r;
}

bool GradientShader::prepare(const Gradient& g, const Affine& to_device, float opacity,
                             bool linear_light) {
    linear_light = linear_light || g.linear_light;
    if (g.stops.empty()) return false;
    const double det = to_device.determinant();
    if (!(std::fabs(det) > 1e-12) || !std::isfinite(det)) return false;
    g_ = &g;
    inverse_ = to_device.inverse();
    // The linear t of a device point (X, Y), the formula above expanded:
    // ((inverse (X, Y) - p1) . axis) / |axis|^2 = x X + y Y + t0.
    const Vec2 axis = g.p2 - g.p1;
    const double len_sq = axis.length_sq();
    const Affine& m = inverse_;
    linear_ = len_sq > 0 ? LinearForm{(m.a * axis.x + m.b * axis.y) / len_sq,
                                      (m.c * axis.x + m.d * axis.y) / len_sq,
                                      ((m.e - g.p1.x) * axis.x + (m.f - g.p1.y) * axis.y) / len_sq}
                         : LinearForm{0, 0, 1};
    radial_ = g.kind == Gradient::Kind::Radial ? radial_form(g) : RadialForm{};
    // The table depends on the stops, the opacity and the space only: a
    // shader asked for the same ones again (the next band, or the next shape
    // sharing the gradient) keeps its table.
    if (g.stops != lut_stops_ || opacity != lut_opacity_ || linear_light != lut_linear_) {
        build_table(g, opacity, linear_light);
        lut_stops_ = g.stops, lut_opacity_ = opacity, lut_linear_ = linear_light;
    }
    return true;
}

void GradientShader::build_table(const Gradient& g, float opacity, bool linear_light) {
    // The table: stops interpolated unpremultiplied in the chosen space, then
    // premultiplied. SVG interpolates its gradients' straight colors (a stop
    // of transparent black darkens the ramp towards it), as browsers, librsvg,
    // resvg, Cairo and Skia do; CSS gradients, not drawn here, premultiply.
    const auto space = [&](Rgba c) {
        return linear_light ? Rgba{to_linear(c.r), to_linear(c.g), to_linear(c.b), c.a} : c;
    };
    std::size_t k = 0;
    for (int i = 0; i < kGradientLut; ++i) {
        const float t = float(i) / float(kGradientLut - 1);
        while (k < g.stops.size() && g.stops[k].offset < t) ++k;
        Rgba c;
        if (k == 0)
            c = space(g.stops.front().color);
        else if (k == g.stops.size())
            c = space(g.stops.back().color);
        else {
            const GradientStop &a = g.stops[k - 1], &b = g.stops[k];
            const float span = b.offset - a.offset;
            c = lerp(space(a.color), space(b.color), span > 0 ? (t - a.offset) / span : 1.0f);
        }
        if (linear_light) c = {to_srgb(c.r), to_srgb(c.g), to_srgb(c.b), c.a};
        lut_[std::size_t(i)] = premultiply(c, opacity);
    }
    lut_opaque_ = std::all_of(lut_.begin(), lut_.end(), [](const Premul& c) { return c.a == 1; });
    if (lut_opaque_)
        std::transform(lut_.begin(), lut_.end(), lut8_.begin(),
                       [](const Premul& c) { return quantize(c); });
}

double GradientShader::parameter(Point p) const {
    return spread(raw_parameter(*g_, radial_, inverse_ * p), g_->spread);
}

Premul GradientShader::at(int x, int y) const {
    Premul c;
    shade(x, y, 1, &c);
    return c;
}

namespace {

/// The table entry nearest t, for t in [0, 1] after spread() or NaN where the
/// geometry overflows the double range (end points 1e308 apart, found by
/// fuzz_svg_render): then the first stop, never an index outside the table.
[[gnu::always_inline]] inline std::size_t entry(double t) {
    const double v = (t >= 0 ? std::min(t, 1.0) : 0.0) * (kGradientLut - 1);
    // std::lround(v) for v >= 0, without its library call: v - k is exact.
    const int k = int(v);
    return std::size_t(k + (v - k >= 0.5));
}

// Shading runs in blocks of pixels, in three passes: the block's
// parameters t (spread() not yet applied), their table entries, then the
// colors copied. The first two are plain arithmetic loops, two pixels to a
// register (the linear one so compiled, the radial one and the entries in
// SSE2); one loop doing all three a pixel at a time ran at 8 cycles a
// pixel, each pixel's chain of conversions ending in a load's address. The
// linear gradient's frame (8-bit canvas): 0.66 -> 0.44x Cairo's time; the
// radial one: 0.60 -> 0.36x. Where the CPU has AVX2 (cpu.h), the radial
// parameters and the pad entries four pixels a pass, operation for
// operation (linear 0.249 -> 0.194x, radial 0.246 -> 0.174x, on top of the
// opaque tables stored, bench/README.md).
constexpr int kBlock = 64;

#if defined(CASTELJAU_X86_DISPATCH)
/// entries_of's pad loop four entries a pass (AVX), operation for
/// operation; returns how many of the m it did (a multiple of 4).
[[gnu::target("avx2")]] int pad_entries_avx2(const double* t, int m, int* e) {
    const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
    const __m256d half = _mm256_set1_pd(0.5), last = _mm256_set1_pd(kGradientLut - 1);
    int i = 0;
    for (; i + 4 <= m; i += 4) {
        const __m256d v =
            _mm256_mul_pd(_mm256_min_pd(_mm256_max_pd(_mm256_loadu_pd(t + i), zero), one), last);
        const __m256d k = _mm256_cvtepi32_pd(_mm256_cvttpd_epi32(v));
        const __m256d up = _mm256_and_pd(_mm256_cmp_pd(_mm256_sub_pd(v, k), half, _CMP_GE_OQ), one);
        _mm_storeu_si128(reinterpret_cast<__m128i*>(e + i),
                         _mm256_cvttpd_epi32(_mm256_add_pd(k, up)));
    }
    return i;
}

/// The per-row constants of a radial gradient's parameters (shade_radial).
struct RadialRow {
    double ma, mb, rx, ry, ex, ey, a, r0dr, r0_sq, factor, t0;
};

/// shade_radial's parameter loop four pixels a pass (AVX), operation for
/// operation (vmaxpd gives 0 for NaN as maxpd does) from pixel x on;
/// returns how many of the count it did (a multiple of 4).
template <bool Ring>
[[gnu::target("avx2")]] int radial_parameters_avx2(const RadialRow& r, int x, int count,
                                                   double* t) {
    const __m256d ma = _mm256_set1_pd(r.ma), mb = _mm256_set1_pd(r.mb), rx = _mm256_set1_pd(r.rx),
                  ry = _mm256_set1_pd(r.ry);
    const __m256d ex = _mm256_set1_pd(r.ex), ey = _mm256_set1_pd(r.ey), va = _mm256_set1_pd(r.a),
                  zero = _mm256_setzero_pd();
    int i = 0;
    for (; i + 4 <= count; i += 4) {
        const __m128i k = _mm_add_epi32(_mm_set1_epi32(x + i), _mm_setr_epi32(0, 1, 2, 3));
        const __m256d cx = _mm256_add_pd(_mm256_cvtepi32_pd(k), _mm256_set1_pd(0.5));
        const __m256d dx = _mm256_add_pd(_mm256_mul_pd(ma, cx), rx);
        const __m256d dy = _mm256_add_pd(_mm256_mul_pd(mb, cx), ry);
        __m256d b = _mm256_add_pd(_mm256_mul_pd(dx, ex), _mm256_mul_pd(dy, ey));
        __m256d len = _mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy));
        if constexpr (Ring)
            b = _mm256_add_pd(b, _mm256_set1_pd(r.r0dr)),
            len = _mm256_sub_pd(len, _mm256_set1_pd(r.r0_sq));
        const __m256d q = _mm256_sub_pd(_mm256_mul_pd(b, b), _mm256_mul_pd(va, len));
        const __m256d root = _mm256_sqrt_pd(_mm256_max_pd(q, zero));
        __m256d v = _mm256_mul_pd(_mm256_sub_pd(b, root), _mm256_set1_pd(r.factor));
        if constexpr (Ring) v = _mm256_add_pd(_mm256_set1_pd(r.t0), v);
        _mm256_storeu_pd(t + i, v);
    }
    return i;
}
#endif

/// e[i] = entry(spread(t[i], S)) for i in [0, m): for pad, two at a time
/// with the same arithmetic (maxpd gives 0 for NaN, the first stop, as
/// entry() does), or four (pad_entries_avx2).
template <Spread S>
void entries_of(const double* t, int m, int* e) {
    int i = 0;
#if defined(CASTELJAU_X86_DISPATCH)
    if constexpr (S == Spread::Pad)
        if (use_avx2) i = pad_entries_avx2(t, m, e);
#endif
#if defined(__SSE2__)
    if constexpr (S == Spread::Pad) {
        const __m128d zero = _mm_setzero_pd(), one = _mm_set1_pd(1.0), half = _mm_set1_pd(0.5);
        const __m128d last = _mm_set1_pd(kGradientLut - 1);
        for (; i + 2 <= m; i += 2) {
            const __m128d v =
                _mm_mul_pd(_mm_min_pd(_mm_max_pd(_mm_loadu_pd(t + i), zero), one), last);
            const __m128d k = _mm_cvtepi32_pd(_mm_cvttpd_epi32(v));
            const __m128d up = _mm_and_pd(_mm_cmpge_pd(_mm_sub_pd(v, k), half), one);
            _mm_storel_epi64(reinterpret_cast<__m128i*>(e + i),
                             _mm_cvttpd_epi32(_mm_add_pd(k, up)));
        }
    }
#endif
    for (; i < m; ++i) e[i] = int(entry(spread(t[i], S)));
}

/// out[i] = the color at parameter t_i for i in [0, n), params(i0, m, t)
/// giving t_i0 to t_(i0 + m - 1) into t.
template <Spread S, class P, class Params>
[[gnu::always_inline]] inline void look_up(const P* lut, int n, P* out, Params params) {
    std::array<double, kBlock> t;
    std::array<int, kBlock> e;
    for (int i0 = 0; i0 < n; i0 += kBlock) {
        const int m = std::min(kBlock, n - i0);
        params(i0, m, t.data());
        entries_of<S>(t.data(), m, e.data());
        for (int i = 0; i < m; ++i) out[i0 + i] = lut[e[std::size_t(i)]];
    }
}

} // namespace

template <Spread S, class P>
void GradientShader::shade_linear(int x, int y, int n, const P* lut, P* out) const {
    // t is affine in device space: one multiply-add a pixel, no division.
    const double row = linear_.y * (y + 0.5) + linear_.t0, dx = linear_.x;
    look_up<S>(lut, n, out, [&](int i0, int m, double* t) {
        for (int i = 0; i < m; ++i) t[i] = dx * (x + i0 + i + 0.5) + row;
    });
}

template <Spread S, bool Ring, class P>
void GradientShader::shade_radial(int x, int y, int n, const P* lut, P* out) const {
    const Gradient& g = *g_;
    if (g.radius <= 0) { // zero radius: the last stop (13.2.3)
        std::fill_n(out, n, lut[entry(spread(1.0, S))]);
        return;
    }
    // The formulas above with d = inverse (X, Y) - f: along a row d is
    // (m.a X, m.b X) plus a row constant, and the per-shader constants
    // (e, a and 1 / a) leave the loop. Without a start circle (Ring false:
    // r0 = 0, t0 = 0, t1 = 1) the terms of r0 and t0 drop out: 10% of the
    // radial scene's frame.
    const Affine& m = inverse_;
    const RadialForm& r = radial_;
    const Vec2 e = r.center - r.focal;
    const double a = e.length_sq() - r.dr * r.dr, inv_a = 1 / a;
    const double r0dr = r.r0 * r.dr, r0_sq = r.r0 * r.r0, scale = r.t1 * inv_a;
    const double cy = y + 0.5;
    const Vec2 row{m.c * cy + m.e - r.focal.x, m.d * cy + m.f - r.focal.y};
#if defined(CASTELJAU_X86_DISPATCH)
    const RadialRow rr{m.a, m.b, row.x, row.y, e.x, e.y, a, r0dr, r0_sq, Ring ? scale : inv_a,
                       r.t0};
#endif
    look_up<S>(lut, n, out, [&](int i0, int count, double* t) {
        int i = 0;
#if defined(CASTELJAU_X86_DISPATCH)
        if (use_avx2) i = radial_parameters_avx2<Ring>(rr, x + i0, count, t);
#endif
#if defined(__SSE2__)
        // The loop below two pixels at a time, operation for operation (maxpd
        // gives 0 for NaN, as std::max(0.0, v) does).
        const auto all = [](double v) { return _mm_set1_pd(v); };
        const __m128d ma = all(m.a), mb = all(m.b), rx = all(row.x), ry = all(row.y);
        const __m128d ex = all(e.x), ey = all(e.y), va = all(a), zero = _mm_setzero_pd();
        for (; i + 2 <= count; i += 2) {
            const __m128i k = _mm_setr_epi32(x + i0 + i, x + i0 + i + 1, 0, 0);
            const __m128d cx = _mm_add_pd(_mm_cvtepi32_pd(k), all(0.5));
            const __m128d dx = _mm_add_pd(_mm_mul_pd(ma, cx), rx);
            const __m128d dy = _mm_add_pd(_mm_mul_pd(mb, cx), ry);
            __m128d b = _mm_add_pd(_mm_mul_pd(dx, ex), _mm_mul_pd(dy, ey));
            __m128d len = _mm_add_pd(_mm_mul_pd(dx, dx), _mm_mul_pd(dy, dy));
            if constexpr (Ring) b = _mm_add_pd(b, all(r0dr)), len = _mm_sub_pd(len, all(r0_sq));
            const __m128d q = _mm_sub_pd(_mm_mul_pd(b, b), _mm_mul_pd(va, len));
            const __m128d root = _mm_sqrt_pd(_mm_max_pd(q, zero));
            __m128d v = _mm_mul_pd(_mm_sub_pd(b, root), all(Ring ? scale : inv_a));
            if constexpr (Ring) v = _mm_add_pd(all(r.t0), v);
            _mm_storeu_pd(t + i, v);
        }
#endif
        for (; i < count; ++i) {
            const double cx = x + i0 + i + 0.5;
            const Vec2 d{m.a * cx + row.x, m.b * cx + row.y};
            if constexpr (Ring) {
                const double b = d.dot(e) + r0dr;
                t[i] = r.t0 +
                       (b - std::sqrt(std::max(0.0, b * b - a * (d.length_sq() - r0_sq)))) * scale;
            } else {
                const double b = d.dot(e);
                t[i] = (b - std::sqrt(std::max(0.0, b * b - a * d.length_sq()))) * inv_a;
            }
        }
    });
}

template <Spread S, class P>
void GradientShader::shade_cone(int x, int y, int n, const P* lut, P* out) const {
    // A pixel at a time: cones are rare (a focal point outside the circle),
    // and a pixel outside the cone is transparent, not a table entry.
    const Affine& m = inverse_;
    const double cy = y + 0.5;
    const Vec2 row{m.c * cy + m.e - radial_.focal.x, m.d * cy + m.f - radial_.focal.y};
    for (int i = 0; i < n; ++i) {
        const double cx = x + i + 0.5;
        const double t = cone_parameter(radial_, {m.a * cx + row.x, m.b * cx + row.y});
        out[i] = std::isnan(t) ? P{} : lut[entry(spread(t, S))];
    }
}

template <Spread S, class P>
void GradientShader::shade_spread(int x, int y, int n, const P* lut, P* out) const {
    if (g_->kind == Gradient::Kind::Linear) return shade_linear<S>(x, y, n, lut, out);
    if (radial_.cone) return shade_cone<S>(x, y, n, lut, out);
    if (radial_.r0 > 0 || radial_.t1 != 1) return shade_radial<S, true>(x, y, n, lut, out);
    shade_radial<S, false>(x, y, n, lut, out);
}

template <class P>
void GradientShader::shade_from(int x, int y, int n, const P* lut, P* out) const {
    switch (g_->spread) {
    case Spread::Pad:
        return shade_spread<Spread::Pad>(x, y, n, lut, out);
    case Spread::Repeat:
        return shade_spread<Spread::Repeat>(x, y, n, lut, out);
    case Spread::Reflect:
        return shade_spread<Spread::Reflect>(x, y, n, lut, out);
    }
}

void GradientShader::shade(int x, int y, int n, Premul* out) const {
    shade_from(x, y, n, lut_.data(), out);
}

bool GradientShader::store_opaque(int x, int y, int n, Premul8* out) const {
    if (!lut_opaque_ || radial_.cone) return false; // a cone leaves pixels transparent
    shade_from(x, y, n, lut8_.data(), out);
    return true;
}

} // namespace casteljau
