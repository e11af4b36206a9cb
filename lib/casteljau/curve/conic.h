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

namespace casteljau {

struct Conic {
    Point p0, p1, p2;
    double w = 1;

    // Circular arc of `radius` around `center` from angle a0 to a1 (radians,
    // y-down or y-up alike). Precondition: 0 < |a1 - a0| < pi.
    static Conic circular_arc(Point center, double radius, double a0, double a1);

    constexpr Point start() const { return p0; }
    constexpr Point end() const { return p2; }
    Point eval(double t) const;
    Vec2 deriv(double t) const;
    Vec2 deriv2(double t) const;
    std::array<Conic, 2> split(double t) const;
    Conic subsegment(double t0, double t1) const;
    Conic transformed(const Affine& m) const { return {m * p0, m * p1, m * p2, w}; }
    Rect bounds() const;
    RationalBezier to_rational() const;

    constexpr bool operator==(const Conic&) const = default;
};

} // namespace casteljau
