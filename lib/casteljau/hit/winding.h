// Point-in-fill on the curves themselves, not on a flattening.
//
// The winding number of a closed curve around p is the signed count of its
// crossings with the ray from p towards +x (Hormann & Agathos, "The point in
// polygon problem for arbitrary polygons", 2001, for the counting rule). For a
// segment, the crossings are the sign changes of f(t) = Y(t) - p.y W(t)
// (bernstein_poly.h) at which the curve's x is beyond p.x. Points exactly on
// the ray's line are counted as above it (a sign function with sgn(0) = +1,
// the polygon version's half-open rule), so a vertex on the ray is counted
// once by the two segments meeting there and a tangency not at all.
//
// Per segment: the roots of f in [0, 1] (roots.h) split it into pieces on
// which f keeps one sign; the sign is read at each piece's middle and at the
// end points, and each change is located on the sign (bracketed_root, to a
// double's resolution) before x is compared. Segments whose control polygon
// lies wholly above, below or left of p are skipped, and one wholly right of
// p counts by its ends' signs alone (convex hull property).
//
// A fill closes every subpath (SVG 1.1, 11.3): an open subpath counts its
// closing line too, as the rasterizer does.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/raster/sweep.h"

namespace casteljau {

/// Winding number of the path's filled outline around `p` (path coordinates).
int winding_number(const Path& path, Point p);

/// Whether `p` lies in the path's fill under `rule`; exact on the curves.
bool fill_contains(const Path& path, Point p, FillRule rule = FillRule::NonZero);

/// Signed crossings of one segment with the ray from `p` towards +x.
int segment_crossings(const Segment& s, Point p);

} // namespace casteljau
