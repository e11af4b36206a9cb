#include "casteljau/paint/mask.h"

#include <cmath>

namespace casteljau {

namespace {

// sRGB's decoding (IEC 61966-2-1): linear below 0.04045, a 2.4 power above.
float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

Premul scaled(const Premul& p, float k) { return {p.r * k, p.g * k, p.b * k, p.a * k}; }

} // namespace

float mask_value(const Premul& p, MaskKind kind) {
    constexpr float kr = 0.2125f, kg = 0.7154f, kb = 0.0721f; // luminanceToAlpha's weights
    switch (kind) {
    case MaskKind::Alpha:
        return p.a;
    case MaskKind::Luminance:
        return std::clamp(kr * p.r + kg * p.g + kb * p.b, 0.0f, 1.0f);
    case MaskKind::LuminanceLinear:
        if (!(p.a > 0)) return 0;
        const float inv = 1.0f / p.a;
        return std::clamp(p.a * (kr * srgb_to_linear(p.r * inv) + kg * srgb_to_linear(p.g * inv) +
                                 kb * srgb_to_linear(p.b * inv)),
                          0.0f, 1.0f);
    }
    return 0;
}

template <class Pixel>
void apply_mask(BasicCanvas<Pixel>& layer, const BasicCanvas<Pixel>& mask, MaskKind kind) {
    for (int y = 0; y < layer.height(); ++y) {
        Pixel* d = layer.row(y);
        const Pixel* m = mask.row(y);
        for (int x = 0; x < layer.width(); ++x)
            d[x] = pixel_of<Pixel>(scaled(to_premul(d[x]), mask_value(to_premul(m[x]), kind)));
    }
}

template void apply_mask(Canvas&, const Canvas&, MaskKind);
template void apply_mask(Canvas8&, const Canvas8&, MaskKind);

} // namespace casteljau
