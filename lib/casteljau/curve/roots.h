// Real roots of polynomials, as the curve code needs them.
//
// solve_quadratic: the numerically stable form (Numerical Recipes 3rd ed. 5.6):
//   q = -(b + sign(b) sqrt(b^2 - 4ac)) / 2,  roots q/a and c/q,
// which never subtracts nearly equal numbers. A vanishing leading coefficient
// degrades gracefully to the linear root.
//
// bernstein_roots: roots in [0, 1] of a polynomial given by its Bernstein
// coefficients, by subdivision. The variation-diminishing property says a piece
// whose coefficients do not change sign has no root, so only pieces with a sign
// change are split (at the middle, by de Casteljau) until they are narrower than
// kRootWidth; their midpoint is reported. Runs over a fixed stack; each piece
// at most halves per level and the depth is capped at kRootDepth, so the work is
// bounded even for roots of high multiplicity.
#pragma once

#include <cstddef>
#include <span>

namespace casteljau {

/// Writes the real roots (0, 1 or 2) into `roots`, ascending; returns how many.
int solve_quadratic(double a, double b, double c, double roots[2]) noexcept;

/// Parameters are resolved to 2^-40 (about 1e-12): far below what a double
/// coordinate of a curve can distinguish at the sizes this library draws.
inline constexpr int kRootDepth = 40;

/// Roots of sum_i coeff[i] B_i^n(t) in [0, 1], ascending, at most out.size()
/// (a degree-n polynomial has at most n); returns how many were written.
/// Precondition: coeff.size() <= kMaxPoints (see decasteljau.h).
int bernstein_roots(std::span<const double> coeff, std::span<double> out) noexcept;

} // namespace casteljau
