// Scalar polynomials in the Bernstein basis on [0, 1], and any path segment as
// such polynomials, for the hit tests' exact questions about curves.
//
// A segment of degree n with control points P_i and weights w_i (1 for the
// polynomial curves) is the projection of the homogeneous polynomial curve
//   X(t) = sum B_i^n(t) w_i (x_i - o.x),  Y(t) likewise,  W(t) = sum B_i^n(t) w_i,
// with W > 0 on [0, 1] (positive weights). Coordinates are taken relative to
// an origin o, the query point, so that the coefficients are small near it.
// "The curve crosses the line x = c" is then "X - (c - o.x) W has a root",
// whose Bernstein coefficients are w_i (x_i - c): no basis change, and the
// variation-diminishing property makes "all coefficients of one sign" a
// proof that there is no root.
//
// Products use  B_i^m B_j^n = C(m,i) C(n,j) / C(m+n,i+j) B_{i+j}^{m+n}  and
// derivatives  d/dt sum b_i B_i^n = n sum (b_{i+1} - b_i) B_i^{n-1}  (Farin,
// "Curves and Surfaces for CAGD", 5.3 and 10.4). Degrees stay below
// kMaxPoints, which bernstein_roots requires.
#pragma once

#include "casteljau/curve/decasteljau.h"
#include "casteljau/curve/path.h"

#include <array>
#include <span>

namespace casteljau {

/// A polynomial of degree <= 8 given by its Bernstein coefficients on [0, 1].
struct BernsteinPoly {
    /// 8 = 3n - 1: room for the rational nearest-point equation of a cubic
    /// (nearest.h; conics need 5, polynomial segments 2n - 1).
    static constexpr int kMaxDegree = 8;
    int degree = 0;
    std::array<double, kMaxDegree + 1> c{};

    /// The coefficients in use, c[0..degree].
    std::span<const double> coefficients() const { return {c.data(), std::size_t(degree) + 1}; }
    /// Value at t, by de Casteljau.
    double eval(double t) const;
};

/// Product of two polynomials (degrees add; their sum must be <= kMaxDegree).
BernsteinPoly operator*(const BernsteinPoly& a, const BernsteinPoly& b);
/// Difference of two polynomials of the same degree.
BernsteinPoly operator-(const BernsteinPoly& a, const BernsteinPoly& b);
/// Sum of two polynomials of the same degree.
BernsteinPoly operator+(const BernsteinPoly& a, const BernsteinPoly& b);
/// The derivative (degree one less; a constant's derivative is the zero constant).
BernsteinPoly derivative(const BernsteinPoly& a);

/// A segment as the homogeneous polynomials X, Y, W, relative to an origin.
struct HomogeneousSegment {
    BernsteinPoly x, y, w;

    /// Lines, quadratics, cubics and conics alike; `origin` is subtracted first.
    static HomogeneousSegment from(const Segment& s, Point origin);
    /// Bernstein coefficients of X - c W: the curve's signed x-distance to x = c + origin.x.
    BernsteinPoly x_minus(double c) const;
    /// Bernstein coefficients of Y - c W.
    BernsteinPoly y_minus(double c) const;
};

/// Roots of `p` in [0, 1], ascending, at most out.size(); returns how many.
int roots_in_unit_interval(const BernsteinPoly& p, std::span<double> out);

} // namespace casteljau
