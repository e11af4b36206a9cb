// Where markers go on a path and which way they point (SVG 2, 13.7.3
// "Rendering markers" and 9.4 "Path directionality").
//
// Every vertex gets one: a subpath's start and each segment's end. The
// path's first vertex takes marker-start, its last marker-end, all others
// marker-mid. A vertex's direction has an in and an out part: the end
// tangent of the segment arriving and the start tangent of the one leaving.
// At a subpath's start the in direction is the closing segment's (closed
// subpath) or the out direction itself; at its end the out direction is the
// first segment's (closed) or the in direction itself. A segment of zero
// length (all its control points equal) takes its direction from the
// nearest segment of nonzero length before it (for in) or after it (for
// out) in its subpath, as the spec says for zero-length path segments.
// orient="auto" points the marker along the bisector of in and out: the mean
// of their angles, taken across the smaller of the two arcs between them.
#pragma once

#include "casteljau/curve/path.h"

#include <vector>

namespace casteljau {

/// Which marker property a vertex takes.
enum class MarkerSlot { Start, Mid, End };

/// One marker position.
struct MarkerVertex {
    Point at;
    double angle_deg = 0; ///< orient="auto": the bisector of in and out, degrees from +x
    MarkerSlot slot = MarkerSlot::Mid;
};

/// The marker positions of `path`, in path order.
std::vector<MarkerVertex> marker_vertices(const Path& path);

} // namespace casteljau
