// The two color spaces of color-interpolation-filters (Filter Effects 1,
// 17.7): sRGB-encoded and linear light (linearRGB), on premultiplied pixels.
#pragma once

#include "casteljau/filter/filter_image.h"

namespace casteljau {

/// Converts `img` to linear light (`linear`) or to sRGB encoding, in place;
/// nothing when it is in that space already. Colors are unpremultiplied,
/// converted channel by channel (IEC 61966-2-1's curve), and premultiplied again.
void convert_space(FilterImage& img, bool linear);

/// A straight sRGB color as a premultiplied pixel of the given space.
Premul color_in_space(Rgba c, bool linear);

/// The sRGB curve, decoding (sRGB-encoded -> linear) and encoding; exact
/// (std::pow), for single colors. Inputs in [0, 1].
float srgb_to_linear(float v);
float linear_to_srgb(float v);

} // namespace casteljau
