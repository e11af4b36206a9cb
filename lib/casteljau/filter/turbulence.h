// feTurbulence (Filter Effects 1, "Filter primitive feTurbulence",
// #feTurbulenceElement): Perlin noise and turbulence.
#pragma once

#include "casteljau/filter/filter_image.h"
#include "casteljau/geom/affine.h"
#include "casteljau/geom/rect.h"

namespace casteljau {

/// The attributes of feTurbulence.
struct Turbulence {
    double base_x = 0, base_y = 0; ///< baseFrequency, in user units (>= 0)
    int octaves = 1;               ///< numOctaves: <= 0 gives transparent black
    double seed = 0;               ///< seed, truncated towards zero as the spec says
    bool fractal_noise = false;    ///< type="fractalNoise", else "turbulence"
    bool stitch = false;           ///< stitchTiles="stitch"
};

/// Fills `out` over `sub` with the spec's noise, evaluated for each pixel at
/// device_to_user applied to its device coordinates (its top-left corner);
/// `tile_user` is the primitive subregion in user space, the tile stitching
/// works on. The channels are straight color and alpha in the filter's
/// operating color space, clamped to [0, 1], then premultiplied.
/// Precondition: `out` is transparent black.
void turbulence(FilterImage& out, const Subregion& sub, const Turbulence& t,
                const Affine& device_to_user, const Rect& tile_user) noexcept;

} // namespace casteljau
