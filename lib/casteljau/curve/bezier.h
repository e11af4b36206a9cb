// Bezier: a Bezier curve of any degree 1..kMaxDegree chosen at run time,
// stored inline (no allocation), with the same operations as Bez<N>.
// It is what B-splines convert to and what a user of higher degrees builds.
#pragma once

#include "casteljau/curve/decasteljau.h"
#include "casteljau/geom/affine.h"
#include "casteljau/geom/rect.h"

#include <array>
#include <span>

namespace casteljau {

/// Power-basis form of a runtime-degree curve: c0 + sum_j c[j-1] t^j.
struct PowerForm {
    Point c0;
    std::array<Vec2, kMaxDegree> c{};
    int degree = 0;
    /// The point at parameter t in [0, 1].
    constexpr Point eval(double t) const {
        return horner_eval(c0, std::span<const Vec2>(c.data(), std::size_t(degree)), t);
    }
};

/// A Bezier curve of run-time degree 1..kMaxDegree, stored inline.
struct Bezier {
    int degree = 1;
    std::array<Point, kMaxPoints> p{};

    /// Precondition: 2 <= pts.size() <= kMaxPoints.
    static Bezier from(std::span<const Point> pts);

    /// Where the curve starts (t = 0).
    Point start() const { return p[0]; }
    /// Where the curve ends (t = 1).
    Point end() const { return p[std::size_t(degree)]; }
    /// The control points as a span.
    std::span<const Point> points() const { return {p.data(), std::size_t(degree) + 1}; }

    /// The point at parameter t in [0, 1].
    Point eval(double t) const { return decasteljau_eval(points(), t); }
    /// The point at t by the direct Bernstein sum (the reference for eval).
    Point eval_bernstein(double t) const { return bernstein_eval(points(), t); }
    /// The same curve in the power basis (for cheap uniform sampling).
    PowerForm power() const;
    /// First derivative at t.
    Vec2 deriv(double t) const;
    /// Second derivative at t.
    Vec2 deriv2(double t) const;

    /// The pieces over [0, t] and [t, 1], by de Casteljau.
    std::array<Bezier, 2> split(double t) const;
    /// The piece over [t0, t1], as a curve over [0, 1].
    Bezier subsegment(double t0, double t1) const;
    /// Precondition: degree < kMaxDegree.
    Bezier elevate() const;
    /// The curve mapped by m (its control points mapped).
    Bezier transformed(const Affine& m) const;
    /// Box of the control points, which holds the curve (convex hull property).
    Rect control_bounds() const;
    /// Tight bounding box: the end points and the extrema.
    Rect bounds() const;

    /// Exact equality of every member.
    bool operator==(const Bezier& o) const;
};

} // namespace casteljau
