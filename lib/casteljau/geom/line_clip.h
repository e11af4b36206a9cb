// Clipping a line segment to a box (Liang and Barsky 1984): the part of
// a + t (b - a), t in [0, 1], inside `box`, found as a parameter interval
// and evaluated with lerp.
//
// Any finite end points are handled, up to 1e308: each bound's parameter is
// a crossing_parameter (below), which never overflows, and lerp's
// (1 - t) a + t b never overflows.
// An end inside the box is kept exactly; a clipped end lies exactly on the
// bound that clipped it.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/rect.h"

#include <algorithm>
#include <array>
#include <optional>

namespace casteljau {

/// Where a coordinate running from `from` to `to` reaches v: (v - from) /
/// (to - from), computed from halved differences, so finite for any finite
/// arguments (to - from itself can overflow) and equal to the plain ratio
/// otherwise (halving is exact).
inline double crossing_parameter(double v, double from, double to) {
    return (0.5 * v - 0.5 * from) / (0.5 * to - 0.5 * from);
}

/// The part of segment ab inside `box` (borders included), or nothing.
inline std::optional<std::array<Point, 2>> clip_line(Point a, Point b, const Rect& box) {
    // Each end: its parameter and, when a bound set it, that bound's axis and
    // value, which the clipped point takes exactly. The other coordinate is
    // interpolated; its error is the ulp of t times that coordinate's own
    // span, so a nearly horizontal line from -1e100 to 1e100 still crosses
    // the box at the right height.
    struct End {
        double t;
        int axis = -1; // 0: x, 1: y
        double at = 0;
    } lo{0}, hi{1};
    const auto narrow = [&](int axis, double from, double to, double min, double max) {
        if (from == to) return from >= min && from <= max;
        End u{crossing_parameter(min, from, to), axis, min};
        End v{crossing_parameter(max, from, to), axis, max};
        if (u.t > v.t) std::swap(u, v);
        if (u.t > lo.t) lo = u;
        if (v.t < hi.t) hi = v;
        return lo.t <= hi.t;
    };
    if (!narrow(0, a.x, b.x, box.x0, box.x1) || !narrow(1, a.y, b.y, box.y0, box.y1))
        return std::nullopt;
    const auto point = [&](const End& e, Point end) {
        if (e.axis < 0) return end;
        const Point p = lerp(a, b, e.t);
        return e.axis == 0 ? Point{e.at, p.y} : Point{p.x, e.at};
    };
    return std::array<Point, 2>{point(lo, a), point(hi, b)};
}

} // namespace casteljau
