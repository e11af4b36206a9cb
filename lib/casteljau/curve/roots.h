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
// change are split (at the middle, by de Casteljau). A piece whose nonzero
// coefficients change sign exactly once holds exactly one root, a simple one
// (the number of roots in the piece is at most the sign changes and of the same
// parity: Descartes' rule in the Bernstein basis, Farin, "Curves and Surfaces
// for CAGD", 5.6): that root is found by bracketed_root below. Other pieces are
// split until they are 2^-kRootDepth wide (roots of high multiplicity, or
// clustered closer than rounding separates), and their midpoint is reported.
// Runs over a fixed stack; each piece at most halves per level and the depth is
// capped at kRootDepth, so the work is bounded whatever the input.
// (Subdividing every root down to 2^-40 took 48% of a point-in-fill test's
// time: 40 splits a root, where isolation takes a few and the bracketed search
// some 8 evaluations.)
//
// bracketed_root: the Illinois variant of regula falsi (Dowell and Jarratt,
// BIT 11, 1971): the secant through the bracket's ends, whose end that stays
// twice in a row has its value halved, so that both ends close in
// (superlinearly, order about 1.44 at a simple root). A step that leaves the
// bracket bisects, and so does every third step when the last three did not
// halve it: the bracket at least halves every three steps, so the worst case
// is three times bisection's (12.5 steps on average in the tests, against
// bisection's 53 to 60). Sides are told by the sign of f(a) as given, never
// by the halved values (a halved denormal becomes -0, which reads as
// positive).
#pragma once

#include <cstddef>
#include <span>

namespace casteljau {

/// Writes the real roots (0, 1 or 2) into `roots`, ascending; returns how many.
int solve_quadratic(double a, double b, double c, double roots[2]) noexcept;

/// Parameters are resolved to 2^-40 (about 1e-12): far below what a double
/// coordinate of a curve can distinguish at the sizes this library draws.
inline constexpr int kRootDepth = 40;

/// The parameter in [a, b] where f changes sign, given fa = f(a) and fb = f(b)
/// on opposite sides of it (a value v >= 0 counts as positive), to within
/// `width` (0: until a and b are neighbouring doubles); a t with f(t) = 0 is
/// returned as found (top of the file).
template <class F>
double bracketed_root(F&& f, double a, double b, double fa, double fb, double width) noexcept {
    int side = 0;          // which end moved last: -1 a, +1 b
    double halved = b - a; // the bracket three steps ago
    const bool a_positive = fa >= 0;
    // At most 256 steps, a guard: the bracket has then halved at least 85
    // times, below any width the callers ask for but 0 (neighbouring doubles,
    // which near 0 can take over a thousand halvings).
    for (int step = 1; step <= 256 && b - a > width; ++step) {
        double t = a - fa * ((b - a) / (fb - fa));
        if (step % 3 == 0) {
            if (b - a > 0.5 * halved) t = 0.5 * (a + b);
            halved = b - a;
        }
        if (!(t > a && t < b)) t = 0.5 * (a + b);
        if (!(t > a && t < b)) break; // a and b are neighbours
        const double ft = f(t);
        if (ft == 0) return t;
        if ((ft >= 0) == a_positive) {
            a = t, fa = ft;
            if (side < 0) fb *= 0.5;
            side = -1;
        } else {
            b = t, fb = ft;
            if (side > 0) fa *= 0.5;
            side = 1;
        }
    }
    return 0.5 * (a + b);
}

/// sum_i c[i] B_i^n(t), by de Casteljau's algorithm (lerps (1 - t) a + t b);
/// 0 for no coefficients. Precondition: c.size() <= kMaxPoints (decasteljau.h).
double bernstein_value(std::span<const double> c, double t) noexcept;

/// Roots of sum_i coeff[i] B_i^n(t) in [0, 1], ascending, at most out.size()
/// (a degree-n polynomial has at most n); returns how many were written.
/// Precondition: coeff.size() <= kMaxPoints (see decasteljau.h).
int bernstein_roots(std::span<const double> coeff, std::span<double> out) noexcept;

} // namespace casteljau
