// feMorphology (Filter Effects 1, "Filter primitive feMorphology",
// #feMorphologyElement): erode and dilate.
#pragma once

#include "casteljau/filter/filter_image.h"

namespace casteljau {

/// The per-channel minimum (erode) or maximum (`dilate`) of the premultiplied
/// input over the (2 rx + 1) x (2 ry + 1) rectangle centred on each pixel,
/// written to `out` over `sub`. rx, ry >= 0 (device px); a radius of 0 leaves
/// that direction unchanged. Pixels beyond the window count as transparent
/// black. Precondition: `out` has `in`'s box and is transparent black.
void morphology(const FilterImage& in, FilterImage& out, const Subregion& sub, bool dilate, int rx,
                int ry);

} // namespace casteljau
