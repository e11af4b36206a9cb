// Draws a Scene with Cairo, the peer renderer of the comparison benchmark:
// the same paths, transforms, paints, fill rules, stroke geometry and group
// opacity, issued as Cairo calls each frame as an application would.
//
// Differences, which the closing figures state: Cairo has no conics, so each
// conic is issued as two cubics (the half-arc approximation of
// edit/bezier_spline.h, within 4e-6 of a quarter circle's radius); Cairo
// composites into 8-bit premultiplied ARGB32, where Casteljau composites in
// float. Gradients, images and pattern tiles are Cairo patterns: an image
// is converted to an ARGB32 surface once and kept (an application would
// decode it once) and sampled with CAIRO_FILTER_GOOD, as librsvg draws
// images (bilinear, but a box over each pixel's footprint where the image
// is shrunk, as Casteljau's levels stand in for), a pattern's tile drawn by Cairo each time it is
// used, at the device resolution, as Casteljau draws it. Clips, masks, filters and blend modes are
// left out.
#pragma once

#include "casteljau/scene/scene.h"

#include <cairo.h>

namespace casteljau::bench {

/// Draws `scene` onto `cr` (whose surface is the scene's size), over what is there.
void draw_with_cairo(cairo_t* cr, const Scene& scene);

} // namespace casteljau::bench
