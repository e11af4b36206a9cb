// Conic: a rational quadratic Bezier curve in standard form (end weights 1),
//   C(t) = ((1-t)^2 p0 + 2 w t(1-t) p1 + t^2 p2) / ((1-t)^2 + 2 w t(1-t) + t^2).
// w < 1 gives an ellipse arc, w = 1 a parabola, w > 1 a hyperbola; w = cos(a/2)
// with p1 at the intersection of the end tangents gives an exact circular arc
// of angle a (Farin, "NURBS", ch. 12). Precondition everywhere: w > 0.
//
// Splitting is the homogeneous de Casteljau construction followed by a
// renormalisation to end weights 1: a triple of weights (wa, wb, wc) is the
// same curve as (1, wb / sqrt(wa wc), 1) (reparameterisation invariance).
#pragma once

#include "casteljau/curve/rational.h"
#include "casteljau/geom/affine.h"
#include "casteljau/geom/rect.h"

#include <array>
#include <cmath>

namespace casteljau {

/// A rational quadratic Bezier in standard form (end weights 1): the exact conic sections.
struct Conic {
    Point p0, p1, p2;
    double w = 1;

    /// Circular arc of `radius` around `center` from angle a0 to a1 (radians,
    /// y-down or y-up alike). Precondition: 0 < |a1 - a0| < pi.
    static Conic circular_arc(Point center, double radius, double a0, double a1);

    /// Where the curve starts (t = 0).
    constexpr Point start() const { return p0; }
    /// Where the curve ends (t = 1).
    constexpr Point end() const { return p2; }
    /// The point at parameter t in [0, 1].
    Point eval(double t) const;
    /// First derivative at t.
    Vec2 deriv(double t) const;
    /// Second derivative at t.
    Vec2 deriv2(double t) const;
    /// The pieces over [0, t] and [t, 1], by de Casteljau.
    std::array<Conic, 2> split(double t) const;
    /// The piece over [t0, t1], as a curve over [0, 1].
    Conic subsegment(double t0, double t1) const;
    /// The curve mapped by m (its control points mapped).
    Conic transformed(const Affine& m) const { return {m * p0, m * p1, m * p2, w}; }
    /// The control points.
    constexpr std::array<Point, 3> control_points() const { return {p0, p1, p2}; }
    /// Box of the control points, which holds the curve (convex hull property).
    constexpr Rect control_bounds() const { return Rect::from_points(p0, p2).united(p1); }
    /// Tight bounding box: the end points and the extrema.
    Rect bounds() const;
    /// The same curve as a RationalBezier of degree 2.
    RationalBezier to_rational() const;

    /// Exact equality of every member.
    constexpr bool operator==(const Conic&) const = default;
};

/// A conic in homogeneous form, weights (w0, w1, w2) unnormalised. Its split is
/// the plain homogeneous de Casteljau split, which keeps the parameterisation:
/// piece [0, u] at s is the whole curve at u s. (Conic::split renormalises, which
/// reparameterises the pieces.) The flatteners work on this form so that the
/// parameters they report are the original conic's.
struct HConic {
    std::array<HPoint, 3> h{};

    /// The homogeneous form of a conic (weights 1, w, 1).
    static HConic from(const Conic& c) {
        return {{HPoint::weighted(c.p0, 1.0), HPoint::weighted(c.p1, c.w),
                 HPoint::weighted(c.p2, 1.0)}};
    }
    /// Where the curve starts (t = 0).
    Point start() const { return h[0].project(); }
    /// Where the curve ends (t = 1).
    Point end() const { return h[2].project(); }
    /// The point at parameter t in [0, 1].
    Point eval(double t) const {
        return decasteljau_eval(std::span<const HPoint, 3>(h), t).project();
    }
    /// The same curve in standard form (end weights 1).
    Conic standard() const {
        return {h[0].project(), h[1].project(), h[2].project(),
                h[1].w / std::sqrt(h[0].w * h[2].w)};
    }
    /// The pieces over [0, t] and [t, 1], by de Casteljau.
    std::array<HConic, 2> split(double t) const {
        std::array<HConic, 2> r{};
        decasteljau_split(std::span<const HPoint, 3>(h), t, std::span<HPoint, 3>(r[0].h),
                          std::span<HPoint, 3>(r[1].h));
        return r;
    }
    /// The piece over [t0, t1], as a curve over [0, 1].
    HConic subsegment(double t0, double t1) const {
        HConic s{};
        decasteljau_subsegment(std::span<const HPoint, 3>(h), t0, t1, std::span<HPoint, 3>(s.h));
        return s;
    }
};

} // namespace casteljau
