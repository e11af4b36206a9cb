// Masking a layer: each pixel scaled by a value taken from another layer's
// pixel at the same place (CSS Masking 1, 7.1 "mask processing"; SVG 1.1, 14.4).
//
// Clip paths are masks too: their content is drawn as opaque shapes with
// the same rasterizer, so the clip's antialiased coverage is that layer's
// alpha, exact at the edges (not a stencil).
//
// Luminance of a premultiplied sRGB-encoded pixel (r, g, b, a), weighted as
// feColorMatrix's luminanceToAlpha (Filter Effects 1, 9.6), which masks use:
//   m = 0.2125 r + 0.7154 g + 0.0721 b.
// Premultiplied channels are colour times alpha, so this is the luminance
// of the straight colour times its alpha, as the spec's definition asks.
// With color-interpolation: linearRGB on the mask, the straight colour is
// first decoded to linear light (sRGB's transfer function, IEC 61966-2-1).
#pragma once

#include "casteljau/paint/canvas.h"

namespace casteljau {

/// What a mask takes from its drawn content: each pixel's alpha (clip
/// paths, mask-type: alpha) or its luminance, from sRGB-encoded values or
/// from linear-light ones.
enum class MaskKind { Alpha, Luminance, LuminanceLinear };

/// The mask value of one pixel of drawn mask content.
float mask_value(const Premul& p, MaskKind kind);

/// Scales each pixel of `layer` by mask_value of the pixel of `mask` at the
/// same place. Both have the same size and origin.
template <class Pixel>
void apply_mask(BasicCanvas<Pixel>& layer, const BasicCanvas<Pixel>& mask, MaskKind kind);

} // namespace casteljau
