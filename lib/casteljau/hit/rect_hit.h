// Curve-rectangle intersection, for rubber-band selection.
//
// A segment meets a closed rectangle iff an end point lies in it or the curve
// crosses one of its four sides. Side x = c, y in [y0, y1]: the curve crosses
// the line where X - c W = 0 (bernstein_poly.h), found by subdivision to
// 2^-40, and the crossing counts when its y lies in [y0, y1]. A segment whose
// control box misses the rectangle is rejected first (convex hull property),
// one whose control box lies inside it accepted. Exact on the curve: nothing
// is flattened.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/geom/rect.h"
#include "casteljau/raster/sweep.h"

namespace casteljau {

/// Whether the segment and the closed rectangle `r` have a point in common.
bool segment_intersects_rect(const Segment& s, const Rect& r);

/// Whether any segment of the path (its outline, as stroked) meets `r`.
bool outline_intersects_rect(const Path& path, const Rect& r);

/// Whether the path's fill under `rule` meets `r`: the outline (with the
/// closing lines of open subpaths) meets it, or `r` lies inside the fill.
bool fill_intersects_rect(const Path& path, const Rect& r, FillRule rule = FillRule::NonZero);

} // namespace casteljau
