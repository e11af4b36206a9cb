// Hit-testing strokes, and their tight bounds.
//
// A stroke is the nonzero fill of its outline polygons (stroke/stroker.h),
// whose vertices lie on the true stroke (offsets are exact at every sample,
// caps and joins are sampled on their arcs, inner joins pass through the
// joint) and whose edges stay within the tolerance of its outline. So, for the outline built at
// tolerance `tol`:
// * distance: 0 inside the polygons; outside, the distance to their edges,
//   within `tol` of the distance to the true stroke;
// * bounds: the box of the polygons' vertices lies inside the true stroke's
//   box, which lies inside that box grown by `tol`; the grown box is
//   returned, so it holds the stroke and exceeds its tight box by <= tol.
// Dashes, caps, joins and miter limits are all honoured, as drawn.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/geom/rect.h"
#include "casteljau/scene/scene.h"

namespace casteljau {

/// The stroke's outline polygons as a path of closed line subpaths, whose
/// nonzero fill is the stroke (to within `tolerance`): for the exact hit tests
/// of winding.h and rect_hit.h.
Path stroke_outline_path(const Path& path, const StrokeGeometry& style, double tolerance);

/// Distance from `p` to the stroke of `path` (0 inside), within `tolerance`;
/// infinite where the stroke has no outline (a width or a tolerance that is
/// not finite and > 0, a zero-length open path with butt caps).
double stroke_distance(const Path& path, const StrokeGeometry& style, Point p,
                       double tolerance = 1e-3);

/// A box that holds the stroke and exceeds its tight bounds by at most `tolerance`.
Rect stroke_bounds(const Path& path, const StrokeGeometry& style, double tolerance = 1e-3);

/// Tight bounds of the path's fill (its curves' extrema): Path::bounds().
inline Rect fill_bounds(const Path& path) { return path.bounds(); }

} // namespace casteljau
