// The parabola integral's closed forms (flatten/parabola.h) against the
// integral itself, computed here by Simpson's rule.
#include "casteljau/flatten/parabola.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace casteljau {
namespace {

// G(x) = integral_0^x (1 + s^2)^(-1/4) ds = integral_0^asinh(x) sqrt(cosh u) du
// (s = sinh u), whose integrand is smooth: Simpson's rule on 4000 panels is
// exact to ~1e-12 relative over the range tested.
double reference_integral(double x) {
    const double end = std::asinh(std::fabs(x));
    const int n = 4000;
    double sum = 0;
    for (int i = 0; i <= n; ++i) {
        const double f = std::sqrt(std::cosh(end * i / n));
        sum += f * (i == 0 || i == n ? 1 : i % 2 ? 4 : 2);
    }
    return std::copysign(sum * end / n / 3, x);
}

// The inverse's derivative, exactly: d G^-1 / dg = 1 / G'(x) = (1 + x^2)^(1/4).
double reference_inverse_slope(double x) { return std::pow(1 + x * x, 0.25); }

TEST(Parabola, TailConstantIsTheLimitOfTheIntegralMinusItsAsymptote) {
    EXPECT_NEAR(kParabolaTail,
                -std::sqrt(std::numbers::pi) * std::tgamma(-0.25) / (2 * std::tgamma(0.25)), 1e-15);
    // G(x) - 2 sqrt(x) + kParabolaTail = O(x^-3/2).
    for (double x : {1e4, 1e6})
        EXPECT_NEAR(reference_integral(x) - 2 * std::sqrt(x), -kParabolaTail, 2 / std::pow(x, 1.5))
            << x;
}

TEST(Parabola, InverseIsWithinItsStatedErrorOfTheTrueInverse) {
    double worst = 0, worst_slope = 0;
    for (double x = 1e-6; x < 1e6; x *= 1.07) {
        for (double sx : {x, -x}) {
            const double g = reference_integral(sx);
            const double rel = std::fabs(parabola_integral_inverse(g) / sx - 1);
            // The slope by a central difference, relative step 1e-6.
            const double h = 1e-6 * std::max(std::fabs(g), 1e-3);
            const double slope =
                (parabola_integral_inverse(g + h) - parabola_integral_inverse(g - h)) / (2 * h);
            const double rel_slope = std::fabs(slope / reference_inverse_slope(sx) - 1);
            EXPECT_LT(rel, 0.0022) << "x " << sx;
            EXPECT_LT(rel_slope, 0.0029) << "x " << sx;
            worst = std::max(worst, rel), worst_slope = std::max(worst_slope, rel_slope);
        }
    }
    // The fit's worst cases, so that the bounds above are its own and tight.
    EXPECT_GT(worst, 0.0015);
    EXPECT_GT(worst_slope, 0.0020);
}

TEST(Parabola, IntegralIsTheInverseOfTheInverse) {
    for (double x = 1e-9; x < 1e12; x *= 1.13) {
        for (double sx : {x, -x}) {
            const double g = parabola_integral(sx);
            EXPECT_NEAR(parabola_integral_inverse(g), sx, 1e-9 * std::fabs(sx)) << sx;
            // And within the inverse's error of the true integral.
            if (std::fabs(sx) < 1e6) {
                EXPECT_NEAR(g, reference_integral(sx), 0.0025 * std::fabs(reference_integral(sx)))
                    << sx;
            }
        }
    }
    EXPECT_EQ(parabola_integral(0.0), 0.0);
    EXPECT_EQ(parabola_integral_inverse(0.0), 0.0);
}

} // namespace
} // namespace casteljau
