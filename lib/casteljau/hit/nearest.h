// Nearest point on a curve, with its parameter.
//
// For C(t) = P(t) / W(t) (bernstein_poly.h, coordinates relative to the query
// point q), the squared distance |C|^2 is stationary where
//   g(t) = (P - q W) . (P' W - P W') = 0,
// since C' = (P' W - P W') / W^2 and C - q = (P - q W) / W with W > 0: the
// numerator of C . C' up to the positive factor W^3. g has degree 3n - 1 (5
// for conics); where every weight is 1 (lines, quadratics, cubics) W = 1 and
// g = P . P' has degree 2n - 1 (1, 3 and 5). Every local minimum in (0, 1) is
// a root of g, so the nearest point is at one of g's roots (to 2^-40, roots.h)
// or an end point: all are evaluated and the closest wins. This finds the
// global minimum however many local minima there are, which Newton's method
// from a few starting points does not promise.
#pragma once

#include "casteljau/curve/path.h"

#include <cstddef>
#include <limits>

namespace casteljau {

/// A point on a segment closest to a query point.
struct NearestPoint {
    double t = 0; ///< parameter on the segment, in [0, 1]
    Point point;  ///< the segment at t
    double distance = std::numeric_limits<double>::infinity(); ///< from the query point
};

/// A point on a path closest to a query point, and where it lies.
struct PathNearestPoint {
    std::size_t subpath = 0; ///< index into Path::subpaths()
    std::size_t segment = 0; ///< index into the subpath's segments
    NearestPoint nearest;    ///< its parameter, position and distance
};

/// The point of `s` closest to `q`: the global minimum over [0, 1].
NearestPoint nearest_point(const Segment& s, Point q);

/// The point of the path's segments closest to `q`; distance is infinite for an empty path.
PathNearestPoint nearest_point(const Path& path, Point q);

} // namespace casteljau
