#include "casteljau/paint/image_shader.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace casteljau {

namespace {

/// Truncated value v as an index into [0, n): NaN gives 0, anything beyond
/// the range its end. For v >= 0 truncation is floor; below 0 the index is 0
/// anyway. Compared in double, so no out-of-range value meets int.
int clamp_index(double v, int n) { return v >= 0 ? (v < n ? int(v) : n - 1) : 0; }

/// floor(x), inline: baseline x86-64 has no rounding instruction (SSE4.1
/// brings one), so std::floor is a libm call, twice per repeated sample.
/// Beyond 2^52 every double is whole; NaN and infinities pass through.
double floor_of(double x) {
    if (!(std::fabs(x) < 0x1p52)) return x;
    const double t = double(std::int64_t(x));
    return t > x ? t - 1 : t;
}

/// v reduced to [0, n] by floor-mod, with the reciprocal 1 / n: the quotient
/// may round to the neighbouring integer, which one step corrects. The
/// bound n itself (rounding again) and NaN are left to clamp_index.
double wrap(double v, int n, double inv_n) {
    double r = v - n * floor_of(v * inv_n);
    if (r < 0) r += n;
    if (r >= n) r -= n;
    return r;
}

/// The two pixels a bilinear sample lies between along one axis of n
/// pixels, and the weight of the second.
struct Axis {
    int i0, i1;
    float t;
};

Axis bilinear_axis(double v, int n, double inv_n, bool repeat) {
    double u = v - 0.5; // pixel centres at integers
    u = repeat ? wrap(u, n, inv_n) : (u >= 0 ? std::min(u, n - 1.0) : 0.0);
    const int i = clamp_index(u, n);
    const double t = u - i; // in [0, 1] but for NaN, or rounding at huge u
    return {i, i + 1 < n ? i + 1 : (repeat ? 0 : n - 1), float(t >= 0 ? std::min(t, 1.0) : 0.0)};
}

Premul lerp(const Premul& a, const Premul& b, float t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t,
            a.a + (b.a - a.a) * t};
}

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
    return true;
}

Premul ImageShader::at(int x, int y) const {
    const RasterImage& im = *image_;
    const Point p = inverse_ * Point{x + 0.5, y + 0.5};
    Premul c;
    if (smooth_) {
        const Axis ax = bilinear_axis(p.x, im.width, inv_w_, repeat_);
        const Axis ay = bilinear_axis(p.y, im.height, inv_h_, repeat_);
        c = lerp(lerp(im.at(ax.i0, ay.i0), im.at(ax.i1, ay.i0), ax.t),
                 lerp(im.at(ax.i0, ay.i1), im.at(ax.i1, ay.i1), ax.t), ay.t);
    } else {
        const double u = repeat_ ? wrap(p.x, im.width, inv_w_) : p.x;
        const double v = repeat_ ? wrap(p.y, im.height, inv_h_) : p.y;
        c = im.at(clamp_index(u, im.width), clamp_index(v, im.height));
    }
    return {c.r * opacity_, c.g * opacity_, c.b * opacity_, c.a * opacity_};
}

} // namespace casteljau
