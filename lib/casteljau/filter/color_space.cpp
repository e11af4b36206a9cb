// sRGB <-> linear light on premultiplied float pixels.
//
// IEC 61966-2-1: linear = v / 12.92 for v <= 0.04045, else ((v + 0.055) /
// 1.055)^2.4; the encoding is its inverse (12.92 l for l <= 0.0031308, else
// 1.055 l^(1/2.4) - 0.055). A filter converts whole layers (a million
// pixels, three channels each, once or twice per primitive), where std::pow
// would cost some 60 ms; the curves are read from tables of kSteps + 1
// samples with linear interpolation instead. The curves are smooth away
// from 0, and linear near 0 where the encoding is steepest (slope 12.92 at
// 0.0031), so the interpolation error is below 2e-5 over [0, 1] (tested
// against the exact curve): a tenth of a 16-bit step. Colors are divided by
// alpha first: the curves act on straight colors (the spec converts
// "unpremultiplied color values").
#include "casteljau/filter/color_space.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : float(std::pow((double(v) + 0.055) / 1.055, 2.4));
}

float linear_to_srgb(float v) {
    return v <= 0.0031308f ? v * 12.92f : float(1.055 * std::pow(double(v), 1.0 / 2.4) - 0.055);
}

namespace {

constexpr int kSteps = 4096;

struct Curve {
    std::array<float, kSteps + 2> y; // one past the end, so v = 1 interpolates without a branch
    explicit Curve(float (*f)(float)) {
        for (int i = 0; i <= kSteps; ++i) y[std::size_t(i)] = f(float(i) / kSteps);
        y[kSteps + 1] = y[kSteps];
    }
    float operator()(float v) const {
        const float t = unit_clamp(v) * kSteps;
        const int i = int(t);
        return y[std::size_t(i)] + (y[std::size_t(i) + 1] - y[std::size_t(i)]) * (t - float(i));
    }
};

const Curve& decode_curve() {
    static const Curve c(srgb_to_linear);
    return c;
}
const Curve& encode_curve() {
    static const Curve c(linear_to_srgb);
    return c;
}

} // namespace

void convert_space(FilterImage& img, bool linear) {
    if (img.linear == linear) return;
    img.linear = linear;
    const Curve& f = linear ? decode_curve() : encode_curve();
    for (Premul& p : img.px) {
        if (!(p.a > 0.0f)) continue;
        const float inv = 1.0f / p.a;
        p.r = f(p.r * inv) * p.a;
        p.g = f(p.g * inv) * p.a;
        p.b = f(p.b * inv) * p.a;
    }
}

Premul color_in_space(Rgba c, bool linear) {
    if (linear) c = {srgb_to_linear(c.r), srgb_to_linear(c.g), srgb_to_linear(c.b), c.a};
    return premultiply(c);
}

} // namespace casteljau
