// Blend modes (Compositing and Blending Level 1, 5.8 and 10).
#pragma once

#include "casteljau/paint/canvas.h"

#include <optional>
#include <string_view>

namespace casteljau {

/// mix-blend-mode: the 12 separable and 4 non-separable modes of
/// Compositing and Blending Level 1, normal (plain source-over), and
/// Level 2's plus-lighter (mix-blend-mode only: not a <blend-mode>, so not
/// feBlend's).
enum class BlendMode : unsigned char {
    Normal,
    Multiply,
    Screen,
    Overlay,
    Darken,
    Lighten,
    ColorDodge,
    ColorBurn,
    HardLight,
    SoftLight,
    Difference,
    Exclusion,
    Hue,
    Saturation,
    Color,
    Luminosity,
    PlusLighter, ///< the clamped sum: co = min(1, cs + cb), ao = min(1, as + ab)
};

/// The composite of premultiplied `source` (already scaled by coverage or
/// opacity) onto premultiplied `backdrop`, blended with `mode`: source-over
/// with the blended color where both are present,
///   co = cs (1 - ab) + cb (1 - as) + as ab B(Cb, Cs),  ao = as + ab (1 - as),
/// B taken on the straight colors (Cs = cs / as, Cb = cb / ab); for
/// plus-lighter the clamped sum. Normal is exactly blend_over with coverage
/// 1. The color channels come out in [0, ao].
Premul blend(const Premul& backdrop, const Premul& source, BlendMode mode);

/// BasicCanvas::composite_layer with a blend mode: the layer, placed at its
/// origin relative to the target's origin, is scaled by `opacity` (each
/// channel) and blended onto the target pixel by pixel as by blend(); its
/// parts outside the target are dropped. Normal is target.composite_layer
/// itself. 8-bit pixels are blended in float and rounded once.
template <class Pixel>
void composite_layer(BasicCanvas<Pixel>& target, const BasicCanvas<Pixel>& layer, float opacity,
                     BlendMode mode);

extern template void composite_layer(Canvas&, const Canvas&, float, BlendMode);
extern template void composite_layer(Canvas8&, const Canvas8&, float, BlendMode);

/// The mode a CSS <blend-mode> keyword names ("normal", "multiply", ...,
/// "color-dodge", ..., "luminosity"; ASCII case-insensitive, as CSS keywords
/// are), or nothing for any other text: feBlend's mode.
std::optional<BlendMode> parse_blend_mode(std::string_view css_keyword);

/// The mode a mix-blend-mode value names: a <blend-mode>, or plus-lighter.
std::optional<BlendMode> parse_mix_blend_mode(std::string_view css_keyword);

} // namespace casteljau
