// C2 piecewise cubics: uniform cubic B-splines as Bezier pieces, and the C2
// cubic through given points.
//
// A uniform cubic B-spline with control points D_k is, on its k-th span, the
// cubic Bezier (Boehm; Farin, "Curves and Surfaces for CAGD", 7.2)
//   b0 = (D_k + 4 D_{k+1} + D_{k+2}) / 6,  b1 = (2 D_{k+1} + D_{k+2}) / 3,
//   b2 = (D_{k+1} + 2 D_{k+2}) / 3,        b3 = (D_{k+1} + 4 D_{k+2} + D_{k+3}) / 6,
// and consecutive spans meet with equal first and second derivatives (C2).
//
// Interpolation: the spline through p_0..p_n (one span per pair, uniform
// parameters) has junctions (D_{i-1} + 4 D_i + D_{i+1}) / 6 = p_i, a
// tridiagonal system. Open curves take natural ends (zero second derivative:
// D_{-1} - 2 D_0 + D_1 = 0, whence D_0 = p_0 and D_n = p_n); closed curves
// are periodic, a cyclic system solved by Sherman-Morrison (Numerical Recipes
// 3rd ed., 2.7.2). The matrix is strictly diagonally dominant (4 against
// 1 + 1), so elimination without pivoting is stable.
#pragma once

#include "casteljau/curve/path.h"

#include <span>
#include <vector>

namespace casteljau {

/// The spans of the uniform cubic B-spline with control points `d`, as cubic
/// Beziers: d.size() - 3 of them when open, d.size() when closed (periodic).
std::vector<CubicBez> uniform_bspline_to_beziers(std::span<const Point> d, bool closed);

/// The C2 piecewise cubic through `points` (one cubic per consecutive pair;
/// natural ends when open, periodic when closed), as a subpath. Fewer than two
/// points give a subpath without segments; a closed pair, the open curve there and back.
Subpath interpolate_c2(std::span<const Point> points, bool closed = false);

} // namespace casteljau
