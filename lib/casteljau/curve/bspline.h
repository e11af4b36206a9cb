// B-spline and NURBS curves of any degree with any valid knot vector.
//
// A degree-p curve with control points P_0..P_{n-1} and knots t_0..t_{n+p}
// (nondecreasing) is defined on the domain [t_p, t_n]. Evaluation is de Boor's
// algorithm (de Boor 1972; Piegl & Tiller, "The NURBS Book", A3.1 in its
// triangular form): in the knot span [t_k, t_{k+1}) the p+1 points
// P_{k-p}..P_k are blended by p rounds of affine interpolation. Knot insertion
// is Boehm's algorithm (NURBS Book 5.2). Conversion to Bezier pieces inserts
// every knot of the domain until its multiplicity is p; then the p+1 points of
// each nonempty span are that span's Bezier control points (by the blossom:
// P_i = f(t_{i+1}, ..., t_{i+p})). NURBS do all of this on homogeneous points
// (w x, w y, w), which makes them polynomial B-splines in 3D.
//
// Validity (checked by validate(), assumed by everything else): 1 <= p <=
// kMaxDegree, n >= p + 1, knots.size() == n + p + 1, all values finite, knots
// nondecreasing, t_p < t_n, no interior knot of multiplicity above p + 1,
// and for NURBS one weight per point, each > 0.
#pragma once

#include "casteljau/curve/bezier.h"
#include "casteljau/curve/rational.h"

#include <string>
#include <vector>

namespace casteljau {

/// A polynomial B-spline curve of any degree and any valid knot vector.
struct BSpline {
    int degree = 3;
    std::vector<Point> points;
    std::vector<double> knots;

    /// Empty when valid; otherwise what is wrong, in words.
    std::string validate() const;
    /// Start of the parameter domain, the knot t_p.
    double domain_start() const { return knots[std::size_t(degree)]; }
    /// End of the parameter domain, the knot t_n.
    double domain_end() const { return knots[points.size()]; }
    /// u is clamped to the domain.
    Point eval(double u) const;
    /// Inserts u once (domain_start <= u <= domain_end); the curve is unchanged.
    void insert_knot(double u);
    /// The curve as Bezier pieces, one per nonempty knot span.
    std::vector<Bezier> to_beziers() const;
};

/// A rational B-spline (NURBS) curve: a B-spline of homogeneous points.
struct Nurbs {
    int degree = 2;
    std::vector<Point> points;
    std::vector<double> weights;
    std::vector<double> knots;

    /// The exact circle as nine control points of degree 2 (NURBS Book 7.5).
    static Nurbs circle(Point center, double radius);

    /// Empty when valid; otherwise what is wrong, in words.
    std::string validate() const;
    /// Start of the parameter domain, the knot t_p.
    double domain_start() const { return knots[std::size_t(degree)]; }
    /// End of the parameter domain, the knot t_n.
    double domain_end() const { return knots[points.size()]; }
    /// The point at parameter u, clamped to the domain (de Boor).
    Point eval(double u) const;
    /// Inserts the knot u once (Boehm); the curve is unchanged.
    void insert_knot(double u);
    /// The curve as Bezier pieces, one per nonempty knot span.
    std::vector<RationalBezier> to_beziers() const;
};

/// Knot vector t_0..t_{n+p} with p+1 equal knots at each end (so the curve
/// interpolates its end points) and uniform interior knots on [0, 1].
std::vector<double> clamped_uniform_knots(int degree, std::size_t point_count);

} // namespace casteljau
