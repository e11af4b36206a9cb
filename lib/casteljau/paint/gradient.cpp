#include "casteljau/paint/gradient.h"

#include "casteljau/geom/pixel_index.h"

#include <algorithm>
#include <cmath>

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
    const Vec2 d = q - r.focal, e = r.center - r.focal;
    const double a = e.length_sq() - r.dr * r.dr; // < 0: the start circle inside
    const double b = d.dot(e) + r.r0 * r.dr;
    const double t = (b - std::sqrt(std::max(0.0, b * b - a * (d.length_sq() - r.r0 * r.r0)))) / a;
    return r.t0 + r.t1 * t;
}

} // namespace

GradientShader::RadialForm GradientShader::radial_form(const Gradient& g) {
    // A start circle larger than the end circle is the same family of
    // circles run the other way (SVG 2, 14.3.4's larger t over smaller t,
    // with one circle holding the other): swapped, and t read as 1 - t.
    RadialForm r{g.focal, g.center, std::max(g.focal_radius, 0.0), g.radius, 0, 1};
    double r1 = g.radius;
    if (r.r0 > r1) {
        std::swap(r.focal, r.center), std::swap(r.r0, r1);
        r.t0 = 1, r.t1 = -1;
    }
    // 13.2.3: a focal point outside the circle moves onto it; 0.999 keeps
    // the start circle inside, so that the quadratic has its single root on
    // a circle of positive radius (top of the file).
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
    if (g.kind == Gradient::Kind::Radial) radial_ = radial_form(g);
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

} // namespace

template <Spread S>
void GradientShader::shade_linear(int x, int y, int n, Premul* out) const {
    // t is affine in device space: one multiply-add a pixel, no division.
    const double row = linear_.y * (y + 0.5) + linear_.t0;
    for (int i = 0; i < n; ++i) out[i] = lut_[entry(spread(linear_.x * (x + i + 0.5) + row, S))];
}

template <Spread S, bool Ring>
void GradientShader::shade_radial(int x, int y, int n, Premul* out) const {
    const Gradient& g = *g_;
    if (g.radius <= 0) { // zero radius: the last stop (13.2.3)
        std::fill_n(out, n, lut_[entry(spread(1.0, S))]);
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
    for (int i = 0; i < n; ++i) {
        const double cx = x + i + 0.5;
        const Vec2 d{m.a * cx + row.x, m.b * cx + row.y};
        double t;
        if constexpr (Ring) {
            const double b = d.dot(e) + r0dr;
            t = r.t0 + (b - std::sqrt(std::max(0.0, b * b - a * (d.length_sq() - r0_sq)))) * scale;
        } else {
            const double b = d.dot(e);
            t = (b - std::sqrt(std::max(0.0, b * b - a * d.length_sq()))) * inv_a;
        }
        out[i] = lut_[entry(spread(t, S))];
    }
}

template <Spread S>
void GradientShader::shade_spread(int x, int y, int n, Premul* out) const {
    if (g_->kind == Gradient::Kind::Linear) return shade_linear<S>(x, y, n, out);
    if (radial_.r0 > 0 || radial_.t1 != 1) return shade_radial<S, true>(x, y, n, out);
    shade_radial<S, false>(x, y, n, out);
}

void GradientShader::shade(int x, int y, int n, Premul* out) const {
    switch (g_->spread) {
    case Spread::Pad:
        return shade_spread<Spread::Pad>(x, y, n, out);
    case Spread::Repeat:
        return shade_spread<Spread::Repeat>(x, y, n, out);
    case Spread::Reflect:
        return shade_spread<Spread::Reflect>(x, y, n, out);
    }
}

} // namespace casteljau
