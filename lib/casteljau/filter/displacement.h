// feDisplacementMap (Filter Effects 1, "Filter primitive feDisplacementMap",
// #feDisplacementMapElement).
#pragma once

#include "casteljau/filter/filter_image.h"

namespace casteljau {

/// A channel of the displacement map (xChannelSelector, yChannelSelector).
enum class Channel : unsigned char { R, G, B, A };

/// Each pixel of `out` over `sub` takes the pixel of `in` at
///   (x + scale_x * (XC(x, y) - 0.5), y + scale_y * (YC(x, y) - 0.5)),
/// rounded to the nearest pixel, with XC and YC the channels `xc` and `yc` of
/// `map` unpremultiplied; transparent black when that pixel is outside the
/// window. Scales in device px. Precondition: `in`, `map` and `out` have the
/// same box; `out` is transparent black.
void displacement_map(const FilterImage& in, const FilterImage& map, FilterImage& out,
                      const Subregion& sub, double scale_x, double scale_y, Channel xc,
                      Channel yc) noexcept;

} // namespace casteljau
