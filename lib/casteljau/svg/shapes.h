// The SVG basic shapes (SVG 1.1, chapter 9) as paths. Each is the path the
// spec gives as its equivalent: rect (9.2, with the rx/ry defaulting and
// clamping rules), circle and ellipse (as four exact conic quarter arcs),
// line, polyline and polygon.
#pragma once

#include "casteljau/curve/path.h"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace casteljau {

/// rx, ry: negative means "not given" (auto); both are then resolved per 9.2.
Path rect_path(double x, double y, double w, double h, double rx, double ry);
Path ellipse_path(double cx, double cy, double rx, double ry);
Path line_path(Point a, Point b);
Path poly_path(const std::vector<Point>& points, bool close);

/// A distance along a shape in the units of its pathLength attribute (SVG 2,
/// 9.1.4: dashes, textPath's startOffset) in user units: d scaled by
/// length / path_length for the shape's computed `length`. A pathLength of 0
/// is a factor of infinity: 0 stays 0, any other distance goes to infinity.
double from_path_length(double d, double length, double path_length);

/// The `points` attribute: coordinate pairs separated by whitespace and/or
/// commas. On malformed input or an odd count, `points` holds the pairs before
/// the error (SVG 1.1 F.2: render up to it) and `error` says what is wrong.
struct PointList {
    std::vector<Point> points;
    std::string error;
};
PointList parse_point_list(std::string_view text);

} // namespace casteljau
