// feColorMatrix and feComponentTransfer (Filter Effects 1, 15.6, 15.11).
//
// Both act on straight (unpremultiplied) colors: each pixel is divided by
// its alpha, transformed, clamped to [0, 1] and multiplied again.
//   feColorMatrix:  [R' G' B' A'] = M [R G B A 1], M 4 x 5, row-major.
//   saturate(s):    the spec's matrix, built on the luminance weights 0.213,
//                   0.715, 0.072 (Rec. 709 rounded); s above 1 oversaturates
//                   (allowed since Filter Effects 1, 15.6).
//   hueRotate(a):   the spec's 3 x 3 rotation about the grey axis.
//   luminanceToAlpha: A' = 0.2125 R + 0.7154 G + 0.0721 B (the spec's own,
//                   slightly different, weights), colors 0.
//   feComponentTransfer, per channel C in [0, 1] (15.11):
//     table of n values v:    k = floor(C (n - 1)), C' = v_k + (C (n - 1) - k)(v_k+1 - v_k)
//     discrete of n values:   k = floor(C n), C' = v_min(k, n - 1)
//     linear:                 slope C + intercept
//     gamma:                  amplitude C^exponent + offset
//   An empty table is the identity (15.11: "an empty list results in an
//   identity transfer function").
#include "casteljau/filter/color_transform.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace casteljau {

namespace {

float clamp01(float v) { return unit_clamp(v); }

// Runs f on the straight color of every pixel of the subregion.
template <class F>
void per_straight_pixel(const FilterImage& in, FilterImage& out, const Subregion& sub, F f) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) {
            const Premul p = in.at(x, y);
            const float inv = p.a > 0.0f ? 1.0f / p.a : 0.0f;
            Rgba c{p.r * inv, p.g * inv, p.b * inv, p.a};
            c = f(c);
            out.at(x, y) = premultiply({clamp01(c.r), clamp01(c.g), clamp01(c.b), clamp01(c.a)});
        }
}

float transfer(const TransferFunction& f, float c) {
    using T = TransferFunction::Type;
    const auto n = f.table.size();
    switch (f.type) {
    case T::Identity:
        return c;
    case T::Table: {
        if (n == 0) return c;
        if (n == 1) return f.table[0];
        const float t = clamp01(c) * float(n - 1);
        const std::size_t k = std::min(std::size_t(t), n - 2);
        return f.table[k] + (t - float(k)) * (f.table[k + 1] - f.table[k]);
    }
    case T::Discrete: {
        if (n == 0) return c;
        return f.table[std::min(std::size_t(clamp01(c) * float(n)), n - 1)];
    }
    case T::Linear:
        return f.slope * c + f.intercept;
    case T::Gamma:
        return f.amplitude * std::pow(c, f.exponent) + f.offset;
    }
    return c;
}

} // namespace

void color_matrix(const FilterImage& in, FilterImage& out, const Subregion& sub,
                  const ColorMatrix& cm) {
    const auto& m = cm.m;
    per_straight_pixel(in, out, sub, [&](Rgba c) {
        return Rgba{m[0] * c.r + m[1] * c.g + m[2] * c.b + m[3] * c.a + m[4],
                    m[5] * c.r + m[6] * c.g + m[7] * c.b + m[8] * c.a + m[9],
                    m[10] * c.r + m[11] * c.g + m[12] * c.b + m[13] * c.a + m[14],
                    m[15] * c.r + m[16] * c.g + m[17] * c.b + m[18] * c.a + m[19]};
    });
}

void component_transfer(const FilterImage& in, FilterImage& out, const Subregion& sub,
                        const ComponentTransfer& t) {
    per_straight_pixel(in, out, sub, [&](Rgba c) {
        return Rgba{transfer(t.f[0], c.r), transfer(t.f[1], c.g), transfer(t.f[2], c.b),
                    transfer(t.f[3], c.a)};
    });
}

ColorMatrix saturate_matrix(float s) {
    return {{0.213f + 0.787f * s,
             0.715f - 0.715f * s,
             0.072f - 0.072f * s,
             0,
             0, //
             0.213f - 0.213f * s,
             0.715f + 0.285f * s,
             0.072f - 0.072f * s,
             0,
             0, //
             0.213f - 0.213f * s,
             0.715f - 0.715f * s,
             0.072f + 0.928f * s,
             0,
             0, //
             0,
             0,
             0,
             1,
             0}};
}

ColorMatrix hue_rotate_matrix(double degrees) {
    const float c = float(std::cos(degrees * std::numbers::pi / 180));
    const float s = float(std::sin(degrees * std::numbers::pi / 180));
    return {{0.213f + c * 0.787f - s * 0.213f,
             0.715f - c * 0.715f - s * 0.715f,
             0.072f - c * 0.072f + s * 0.928f,
             0,
             0, //
             0.213f - c * 0.213f + s * 0.143f,
             0.715f + c * 0.285f + s * 0.140f,
             0.072f - c * 0.072f - s * 0.283f,
             0,
             0, //
             0.213f - c * 0.213f - s * 0.787f,
             0.715f - c * 0.715f + s * 0.715f,
             0.072f + c * 0.928f + s * 0.072f,
             0,
             0, //
             0,
             0,
             0,
             1,
             0}};
}

ColorMatrix luminance_to_alpha_matrix() {
    return {{0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.2125f, 0.7154f, 0.0721f, 0, 0}};
}

} // namespace casteljau
