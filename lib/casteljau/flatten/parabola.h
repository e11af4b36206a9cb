// The parabola integral G(x) = integral_0^x (1 + s^2)^(-1/4) ds and its
// inverse, in closed forms cheap enough to run once per flattened vertex.
//
// Why this integral (Levien, "Flattening quadratic Beziers", 2019). A chord of
// a curve over arc length s where the curvature is k deviates from the curve
// by about k s^2 / 8, so a polyline whose chords all deviate by tol has about
//   integral of sqrt(k / (8 tol)) ds
// chords, the fewest possible, and its vertices are evenly spaced in that
// integral. For a quadratic Bezier Q(u), with Q'(u) = a + b u and the constant
// c = b x a, the integrand in the parameter is sqrt(|c| / (8 tol |Q'(u)|)), and
// |Q'(u)| = (|c| / |b|) sqrt(1 + x^2) with the parabola's own coordinate
// x(u) = b . Q'(u) / |c| (0 at its apex, linear in u). So the count over [u0, u1] is
//   |c| / (|b|^(3/2) sqrt(8 tol)) (G(x(u1)) - G(x(u0)))
// and every parabola shares the one function G (density.h uses it).
//
// The forms. G is odd, G(x) = x - x^3 / 12 + ... near 0, and
// G(x) = 2 sqrt(x) - kParabolaTail + O(x^(-3/2)) for large x, where
//   kParabolaTail = -integral_0^inf ((1 + s^2)^(-1/4) - s^(-1/2)) ds
//                 = -sqrt(pi) Gamma(-1/4) / (2 Gamma(1/4))
// (the Beta integral continued to exponent 1/4). The inverse is taken as
//   H(g) = g (A + sqrt(B + C1 |g| + g^2 / 16)),
// the shape Levien uses, with constants of its own: g^2 / 16 and
// A + 2 C1 = kParabolaTail / 2 give H(g) = (g + kParabolaTail)^2 / 4 + O(1)
// for large g, the inverse of the tail; A + sqrt(B) = 1 gives H'(0) = 1; the
// one free constant C1 = 0.0068 minimises the largest relative error of H'
// (searched on a grid of 0.0001 against G by Simpson's rule on 4000 panels).
// Measured over |G^-1(g)| in [1e-6, 1e6]: H is within 0.21% of G^-1 and H' within
// 0.28% of (G^-1)' (tests/flatten/parabola_test.cpp), so chords placed by H
// deviate within 0.6% of what the exact G predicts. H' matters more than H:
// it is the local chord length.
//
// G itself is H's exact inverse up to rounding, so that vertices placed by H
// between two ends found by G land on those ends: a start of the same shape,
//   x / (kParabolaTail / 4 + (B' + D |x| + x^2 / 16)^(1/4))
// (the same two limits; D = 0.06 fitted the same way, within 1.2% of G), then
// two Newton steps on H(g) = x (relative mismatch 8e-10, measured).
#pragma once

#include <cmath>

namespace casteljau {

/// -integral_0^inf ((1 + s^2)^(-1/4) - s^(-1/2)) ds: G(x) - 2 sqrt(x) tends to minus this.
inline constexpr double kParabolaTail = 1.1981402347355918;

namespace parabola_detail {
inline constexpr double kC1 = 0.0068; // the fitted constant of H
inline constexpr double kA = kParabolaTail / 2 - 2 * kC1;
inline constexpr double kB = (1 - kA) * (1 - kA);
inline constexpr double kStartA = kParabolaTail / 4; // the start of G: the same limits
inline constexpr double kStartB = (1 - kStartA) * (1 - kStartA) * (1 - kStartA) * (1 - kStartA);
inline constexpr double kStartD = 0.06; // its fitted constant
} // namespace parabola_detail

/// H(g), within 0.21% of G^-1(g) (top of the file).
inline double parabola_integral_inverse(double g) noexcept {
    using namespace parabola_detail;
    const double m = std::fabs(g);
    return g * (kA + std::sqrt(kB + m * (kC1 + m * (1.0 / 16))));
}

/// G(x), the inverse of parabola_integral_inverse to 1e-9 relative.
inline double parabola_integral(double x) noexcept {
    using namespace parabola_detail;
    const double ax = std::fabs(x);
    double g = x / (kStartA + std::sqrt(std::sqrt(kStartB + ax * (kStartD + ax * (1.0 / 16)))));
    for (int step = 0; step < 2; ++step) {
        const double m = std::fabs(g);
        const double r = std::sqrt(kB + m * (kC1 + m * (1.0 / 16)));
        const double h = g * (kA + r);
        const double dh = kA + r + m * (kC1 + m * (1.0 / 8)) / (2 * r); // H'(g) > 0
        g -= (h - x) / dh;
    }
    return g;
}

} // namespace casteljau
