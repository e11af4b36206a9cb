// The color family of filter primitives: feColorMatrix and
// feComponentTransfer (Filter Effects 1, 15.6 and 15.11), and the CSS
// filter functions built from them (brightness(), contrast(), grayscale(),
// hue-rotate(), invert(), opacity(), saturate(), sepia(); 12.1).
#pragma once

#include "casteljau/filter/graph.h"

namespace casteljau {

/// feColorMatrix on straight colors: out = M (R, G, B, A, 1), clamped to
/// [0, 1], premultiplied again. Transparent pixels are (0, 0, 0, 0) and
/// transformed as well (a matrix may make them visible).
void color_matrix(const FilterImage& in, FilterImage& out, const Subregion& sub,
                  const ColorMatrix& m);

/// feComponentTransfer: each straight channel through its function, clamped.
void component_transfer(const FilterImage& in, FilterImage& out, const Subregion& sub,
                        const ComponentTransfer& t);

/// The matrices of feColorMatrix's shorthand types (15.6): saturate(s),
/// hueRotate(degrees), luminanceToAlpha.
ColorMatrix saturate_matrix(float s);
ColorMatrix hue_rotate_matrix(double degrees);
ColorMatrix luminance_to_alpha_matrix();

} // namespace casteljau
