// Chord deviation: how far a curve piece strays from the straight segment
// between its end points. The flatteners emit a piece as one line exactly when
// this is <= the tolerance, so everything they guarantee rests on this file.
//
// Definition: dev(C) = max_{t in [0,1]} dist(C(t), [C(0), C(1)]), the distance to
// the closed chord *segment*. If dev(C) <= tol the chord is within tol of the
// curve in both directions: every curve point is within tol of the chord by
// definition, and every chord point is within tol of the curve because the
// curve's projection onto the chord line is continuous from one end to the
// other, so it passes over every chord point at a distance <= tol.
//
// The values returned are upper bounds of dev(C), exact where closed forms exist:
//
// * Hull bound (any Bezier, rational or not, weights > 0): the curve lies in the
//   convex hull of its control points and the set of points within tol of a
//   segment is convex, so dev(C) <= max_i dist(P_i, [P_0, P_n]). This is the
//   textbook test (Cairo, AGG); it overestimates a cubic's deviation by up to 4/3
//   (equal offsets: 3/4) and more when the offsets have opposite signs (4/9).
//
// * Exact forms, used when every control point projects inside the chord (then
//   so does the whole curve, by the hull property, and the distance to the
//   segment is the distance to its line). With chord v = P_n - P_0 and signed
//   offsets d_i = cross(P_i - P_0, v) / |v|:
//   - quadratic: d(t) = 2 t (1-t) d_1, maximal at t = 1/2: dev = |d_1| / 2;
//   - cubic: d(t) = 3 t (1-t) ((1-t) d_1 + t d_2); its extrema are the roots of
//     d'(t)/3 = 3 (d_1 - d_2) t^2 + (2 d_2 - 4 d_1) t + d_1, and dev is the
//     largest |d(t)| there (lyon's 3/4 and 4/9 are the two special cases);
//   - conic (standard form, weight w): a conic arc is convex and its tangent at
//     t = 1/2 is parallel to the chord (the "shoulder" point), so
//     dev = |d(1/2)| = w |d_1| / (1 + w).
//   Otherwise the hull bound is used; that only happens on strongly curved
//   pieces (near cusps and loops), which are split further anyway.
//
// Precondition: finite control points; for rational curves positive weights.
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/curve/bezier.h"
#include "casteljau/curve/conic.h"
#include "casteljau/curve/rational.h"

#include <span>

namespace casteljau {

double hull_deviation(std::span<const Point> control) noexcept;

double chord_deviation(const Line& c) noexcept;
double chord_deviation(const QuadBez& c) noexcept;
double chord_deviation(const CubicBez& c) noexcept;
double chord_deviation(const Conic& c) noexcept;
double chord_deviation(const HConic& c) noexcept;
double chord_deviation(const Bezier& c) noexcept;
double chord_deviation(const RationalBezier& c) noexcept;

/// The hull bound for every curve type (the textbook flatness test).
template <int N>
double hull_deviation(const Bez<N>& c) noexcept {
    return hull_deviation(c.points());
}
double hull_deviation(const Conic& c) noexcept;
double hull_deviation(const HConic& c) noexcept;
double hull_deviation(const Bezier& c) noexcept;
double hull_deviation(const RationalBezier& c) noexcept;

} // namespace casteljau
