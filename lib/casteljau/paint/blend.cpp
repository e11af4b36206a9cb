// Blend modes: W3C Compositing and Blending Level 1, 5.8 (blending), 10.1
// (separable blend modes) and 10.2 (non-separable blend modes), composited
// as its simple alpha compositing (source-over) with the blended color:
//   co = cs (1 - ab) + cb (1 - as) + as ab B(Cb, Cs),   ao = as + ab (1 - as)
// for premultiplied cs, cb and straight Cs = cs / as, Cb = cb / ab. Where an
// alpha is 0 its straight color is undefined; it is taken as 0, as it only
// ever meets that alpha as a factor.
// The separable modes apply B to each channel (10.1):
//   multiply     Cb Cs
//   screen       Cb + Cs - Cb Cs
//   overlay      hard-light(Cs, Cb)
//   darken       min(Cb, Cs)
//   lighten      max(Cb, Cs)
//   color-dodge  0 if Cb = 0, else 1 if Cs = 1, else min(1, Cb / (1 - Cs))
//   color-burn   1 if Cb = 1, else 0 if Cs = 0, else 1 - min(1, (1 - Cb) / Cs)
//   hard-light   multiply(Cb, 2 Cs) if Cs <= 1/2, else screen(Cb, 2 Cs - 1)
//   soft-light   Cb - (1 - 2 Cs) Cb (1 - Cb) if Cs <= 1/2, else
//                Cb + (2 Cs - 1) (D(Cb) - Cb), with
//                D(x) = ((16 x - 12) x + 4) x if x <= 1/4, else sqrt(x)
//   difference   |Cb - Cs|
//   exclusion    Cb + Cs - 2 Cb Cs
// The non-separable modes (10.2) trade hue, saturation and luminosity:
//   Lum(C) = 0.3 R + 0.59 G + 0.11 B,   Sat(C) = max(C) - min(C)
//   SetLum(C, l) = ClipColor(C + (l - Lum(C))), ClipColor moving the channels
//     toward L = Lum(C) until they fit in [0, 1]: with n = min(C), x = max(C),
//     if n < 0, C = L + (C - L) L / (L - n); if x > 1, C = L + (C - L) (1 - L) / (x - L)
//   SetSat(C, s): the largest channel to s, the smallest to 0 and the middle
//     one to (mid - min) s / (max - min), all 0 for a gray; that is
//     (C - min) s / (max - min) for every channel, with no sorting.
//   hue         SetLum(SetSat(Cs, Sat(Cb)), Lum(Cb))
//   saturation  SetLum(SetSat(Cb, Sat(Cs)), Lum(Cb))
//   color       SetLum(Cs, Lum(Cb))
//   luminosity  SetLum(Cb, Lum(Cs))
// plus-lighter (Compositing and Blending Level 2, 9.1.14) is no blend
// function but its own composite, the premultiplied sum clamped to 1:
//   co = min(1, cs + cb),   ao = min(1, as + ab)
// (each co stays within its ao, as cs <= as and cb <= ab).
// Colors are blended as they are encoded (sRGB), as browsers do.
#include "casteljau/paint/blend.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>

namespace casteljau {

namespace {

struct Rgb {
    float r, g, b;
};

// The separable modes on one channel: backdrop b, source s, both in [0, 1].
float multiply(float b, float s) { return b * s; }
float screen(float b, float s) { return b + s - b * s; }
float hard_light(float b, float s) { return s <= 0.5f ? multiply(b, 2 * s) : screen(b, 2 * s - 1); }
float overlay(float b, float s) { return hard_light(s, b); }
float darken(float b, float s) { return std::min(b, s); }
float lighten(float b, float s) { return std::max(b, s); }
float color_dodge(float b, float s) {
    if (b == 0) return 0;
    if (s == 1) return 1;
    return std::min(1.0f, b / (1 - s));
}
float color_burn(float b, float s) {
    if (b == 1) return 1;
    if (s == 0) return 0;
    return 1 - std::min(1.0f, (1 - b) / s); // a denormal s's infinite quotient clips too
}
float soft_light(float b, float s) {
    if (s <= 0.5f) return b - (1 - 2 * s) * b * (1 - b);
    const float d = b <= 0.25f ? ((16 * b - 12) * b + 4) * b : std::sqrt(b);
    return b + (2 * s - 1) * (d - b);
}
float difference(float b, float s) { return std::fabs(b - s); }
float exclusion(float b, float s) { return b + s - 2 * b * s; }

template <float (*F)(float, float)>
Rgb separable(const Rgb& b, const Rgb& s) {
    return {F(b.r, s.r), F(b.g, s.g), F(b.b, s.b)};
}

float lum(const Rgb& c) { return 0.3f * c.r + 0.59f * c.g + 0.11f * c.b; }
float min3(const Rgb& c) { return std::min({c.r, c.g, c.b}); }
float max3(const Rgb& c) { return std::max({c.r, c.g, c.b}); }
float sat(const Rgb& c) { return max3(c) - min3(c); }

// L + (C - L) k.
Rgb scale_about(const Rgb& c, float l, float k) {
    return {l + (c.r - l) * k, l + (c.g - l) * k, l + (c.b - l) * k};
}

Rgb clip_color(Rgb c) {
    const float l = lum(c), n = min3(c), x = max3(c);
    // The guards l > n and x > l spare a gray its 0 / 0: a gray lands off
    // [0, 1] only by rounding, and the composite clamps that.
    if (n < 0 && l > n) c = scale_about(c, l, l / (l - n));
    if (x > 1 && x > l) c = scale_about(c, l, (1 - l) / (x - l));
    return c;
}

Rgb set_lum(const Rgb& c, float l) {
    const float d = l - lum(c);
    return clip_color({c.r + d, c.g + d, c.b + d});
}

Rgb set_sat(const Rgb& c, float s) {
    const float n = min3(c), x = max3(c);
    if (x == n) return {0, 0, 0}; // a gray: no hue to give saturation to
    // Multiplied before dividing: s / (x - n) first could overflow for a
    // nearly gray C, and the smallest channel then be 0 times infinity.
    const float w = x - n;
    return {(c.r - n) * s / w, (c.g - n) * s / w, (c.b - n) * s / w};
}

Rgb hue(const Rgb& b, const Rgb& s) { return set_lum(set_sat(s, sat(b)), lum(b)); }
Rgb saturation(const Rgb& b, const Rgb& s) { return set_lum(set_sat(b, sat(s)), lum(b)); }
Rgb color(const Rgb& b, const Rgb& s) { return set_lum(s, lum(b)); }
Rgb luminosity(const Rgb& b, const Rgb& s) { return set_lum(b, lum(s)); }

// A premultiplied channel's straight value: 0 where alpha is 0, and kept in
// [0, 1] where rounding left c a little above a (the modes' formulas assume
// it, and color-dodge would divide by a negative 1 - Cs).
float straight(float c, float a) { return a > 0 ? std::clamp(c / a, 0.0f, 1.0f) : 0.0f; }

using BlendFunction = Rgb (*)(const Rgb& backdrop, const Rgb& source);

// The composite with blend function B. The alpha is computed as blend_over
// computes it, so every mode gives Normal's alpha; the channels are clamped
// to [0, ao], where they lie exactly, against rounding.
template <BlendFunction B>
Premul mix(const Premul& d, const Premul& s) {
    const Rgb m = B({straight(d.r, d.a), straight(d.g, d.a), straight(d.b, d.a)},
                    {straight(s.r, s.a), straight(s.g, s.a), straight(s.b, s.a)});
    const float ks = 1 - d.a, kb = 1 - s.a, km = s.a * d.a;
    const float ao = s.a + kb * d.a;
    const auto channel = [&](float cs, float cb, float mixed) {
        return std::min(std::max(cs * ks + cb * kb + km * mixed, 0.0f), ao);
    };
    return {channel(s.r, d.r, m.r), channel(s.g, d.g, m.g), channel(s.b, d.b, m.b), ao};
}

Premul plus_lighter(const Premul& d, const Premul& s) {
    return {std::min(1.0f, d.r + s.r), std::min(1.0f, d.g + s.g), std::min(1.0f, d.b + s.b),
            std::min(1.0f, d.a + s.a)};
}

Premul over(const Premul& d, const Premul& s) {
    Premul o = d;
    blend_over(o, s, 1.0f);
    return o;
}

using Kernel = Premul (*)(const Premul& backdrop, const Premul& source);

// Returns f.operator()<K>() for the mode's per-pixel composite K: the one
// switch on the mode, outside the pixel loops, which get K inlined.
template <class F>
decltype(auto) with_kernel(BlendMode mode, F&& f) {
    switch (mode) {
    case BlendMode::Normal:
        return f.template operator()<over>();
    case BlendMode::Multiply:
        return f.template operator()<mix<separable<multiply>>>();
    case BlendMode::Screen:
        return f.template operator()<mix<separable<screen>>>();
    case BlendMode::Overlay:
        return f.template operator()<mix<separable<overlay>>>();
    case BlendMode::Darken:
        return f.template operator()<mix<separable<darken>>>();
    case BlendMode::Lighten:
        return f.template operator()<mix<separable<lighten>>>();
    case BlendMode::ColorDodge:
        return f.template operator()<mix<separable<color_dodge>>>();
    case BlendMode::ColorBurn:
        return f.template operator()<mix<separable<color_burn>>>();
    case BlendMode::HardLight:
        return f.template operator()<mix<separable<hard_light>>>();
    case BlendMode::SoftLight:
        return f.template operator()<mix<separable<soft_light>>>();
    case BlendMode::Difference:
        return f.template operator()<mix<separable<difference>>>();
    case BlendMode::Exclusion:
        return f.template operator()<mix<separable<exclusion>>>();
    case BlendMode::Hue:
        return f.template operator()<mix<hue>>();
    case BlendMode::Saturation:
        return f.template operator()<mix<saturation>>();
    case BlendMode::Color:
        return f.template operator()<mix<color>>();
    case BlendMode::Luminosity:
        return f.template operator()<mix<luminosity>>();
    case BlendMode::PlusLighter:
        return f.template operator()<plus_lighter>();
    }
    return f.template operator()<over>(); // a value outside the enum: plain source-over
}

// The CSS keywords, in the order of BlendMode's enumerators.
constexpr std::array<std::string_view, 16> kKeywords = {
    "normal",      "multiply",   "screen",     "overlay",    "darken",     "lighten",
    "color-dodge", "color-burn", "hard-light", "soft-light", "difference", "exclusion",
    "hue",         "saturation", "color",      "luminosity"};
static_assert(kKeywords.size() == std::size_t(BlendMode::Luminosity) + 1);

// Whether `text` is `lower` (a lowercase keyword) ignoring ASCII case.
bool equals_ascii_ci(std::string_view text, std::string_view lower) {
    return std::equal(text.begin(), text.end(), lower.begin(), lower.end(), [](char c, char l) {
        return (c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c) == l;
    });
}

} // namespace

Premul blend(const Premul& backdrop, const Premul& source, BlendMode mode) {
    return with_kernel(mode, [&]<Kernel K>() { return K(backdrop, source); });
}

template <class Pixel>
void composite_layer(BasicCanvas<Pixel>& target, const BasicCanvas<Pixel>& layer, float opacity,
                     BlendMode mode) {
    // The canvas's own loop: bit for bit what the caller got before modes
    // (for 8-bit pixels it rounds differently from a float composite).
    if (mode == BlendMode::Normal) {
        target.composite_layer(layer, opacity);
        return;
    }
    const int dx = layer.origin_x() - target.origin_x(), dy = layer.origin_y() - target.origin_y();
    const int x0 = std::max(0, dx), x1 = std::min(target.width(), dx + layer.width());
    const int y0 = std::max(0, dy), y1 = std::min(target.height(), dy + layer.height());
    with_kernel(mode, [&]<Kernel K>() {
        for (int y = y0; y < y1; ++y) {
            const Pixel* s = layer.row(y - dy) + (x0 - dx);
            Pixel* d = target.row(y) + x0;
            for (int i = 0; i < x1 - x0; ++i) {
                const Premul c = to_premul(s[i]);
                const Premul scaled{opacity * c.r, opacity * c.g, opacity * c.b, opacity * c.a};
                d[i] = pixel_of<Pixel>(K(to_premul(d[i]), scaled));
            }
        }
    });
}

template void composite_layer(Canvas&, const Canvas&, float, BlendMode);
template void composite_layer(Canvas8&, const Canvas8&, float, BlendMode);

std::optional<BlendMode> parse_blend_mode(std::string_view css_keyword) {
    for (std::size_t i = 0; i < kKeywords.size(); ++i)
        if (equals_ascii_ci(css_keyword, kKeywords[i])) return BlendMode(i);
    return std::nullopt;
}

std::optional<BlendMode> parse_mix_blend_mode(std::string_view css_keyword) {
    if (equals_ascii_ci(css_keyword, "plus-lighter")) return BlendMode::PlusLighter;
    return parse_blend_mode(css_keyword);
}

} // namespace casteljau
