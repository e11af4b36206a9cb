// Rect: an axis-aligned box [x0, x1] x [y0, y1].
//
// Guarantee: a Rect built through its factories is ordered (x0 <= x1, y0 <= y1);
// finiteness is the caller's (the core assumes finite input). The empty Rect
// (`Rect::empty()`) is the identity of `united`: its bounds are inverted
// infinities, and `is_empty()` is the only query that is meaningful on it.
#pragma once

#include "casteljau/geom/point.h"

#include <algorithm>
#include <limits>

namespace casteljau {

/// An axis-aligned box [x0, x1] x [y0, y1]; empty when not x0 <= x1 and y0 <= y1.
struct Rect {
    double x0 = 0, y0 = 0, x1 = 0, y1 = 0;

    /// The smallest box holding a and b.
    static constexpr Rect from_points(Point a, Point b) {
        return {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    }
    /// The empty box: the identity of united().
    static constexpr Rect empty() {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return {inf, inf, -inf, -inf};
    }

    /// The whole plane: the identity of an intersection test.
    static constexpr Rect everything() {
        constexpr double inf = std::numeric_limits<double>::infinity();
        return {-inf, -inf, inf, inf};
    }

    /// Whether the box holds no point (NaN bounds count as empty).
    constexpr bool is_empty() const { return !(x0 <= x1 && y0 <= y1); }
    /// x1 - x0.
    constexpr double width() const { return x1 - x0; }
    /// y1 - y0.
    constexpr double height() const { return y1 - y0; }
    /// The corner (x0, y0).
    constexpr Point min() const { return {x0, y0}; }
    /// The corner (x1, y1).
    constexpr Point max() const { return {x1, y1}; }

    /// The smallest box holding this one and p.
    constexpr Rect united(Point p) const {
        return {std::min(x0, p.x), std::min(y0, p.y), std::max(x1, p.x), std::max(y1, p.y)};
    }
    /// The smallest box holding this one and r.
    constexpr Rect united(const Rect& r) const {
        return {std::min(x0, r.x0), std::min(y0, r.y0), std::max(x1, r.x1), std::max(y1, r.y1)};
    }
    /// The common part of this box and r (empty when they do not meet).
    constexpr Rect intersected(const Rect& r) const {
        return {std::max(x0, r.x0), std::max(y0, r.y0), std::min(x1, r.x1), std::min(y1, r.y1)};
    }
    /// The box grown by `by` on every side.
    constexpr Rect inflated(double by) const { return {x0 - by, y0 - by, x1 + by, y1 + by}; }
    /// Whether p lies in the closed box.
    constexpr bool contains(Point p) const {
        return p.x >= x0 && p.x <= x1 && p.y >= y0 && p.y <= y1;
    }
    /// Whether the closed boxes share a point.
    constexpr bool intersects(const Rect& r) const {
        return x0 <= r.x1 && r.x0 <= x1 && y0 <= r.y1 && r.y0 <= y1;
    }
    /// Exact equality of every member.
    constexpr bool operator==(const Rect&) const = default;
};

} // namespace casteljau
