#include "casteljau/curve/roots.h"
#include "corpus.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace casteljau {
namespace {

TEST(Roots, QuadraticIsStableForWidelySeparatedRoots) {
    double r[2];
    // Roots 1e-8 and 1e8: the textbook formula loses the small one entirely.
    ASSERT_EQ(solve_quadratic(1, -(1e8 + 1e-8), 1, r), 2);
    EXPECT_NEAR(r[0], 1e-8, 1e-22);
    EXPECT_NEAR(r[1], 1e8, 1e-6);
    EXPECT_EQ(solve_quadratic(1, 0, 1, r), 0);
    ASSERT_EQ(solve_quadratic(0, 2, -1, r), 1);
    EXPECT_EQ(r[0], 0.5);
}

// The Bernstein coefficients of prod (t - r_k): c_j is the blossom at
// (0^(n-j), 1^j), which for a product of linear factors is the product of the
// factors' values at 0 or 1, averaged over the subsets of j factors taken at 1.
std::vector<double> bernstein_of_roots(const std::vector<double>& roots) {
    const int n = int(roots.size());
    std::vector<double> coeff(std::size_t(n) + 1);
    for (int j = 0; j <= n; ++j) {
        double sum = 0;
        int count = 0;
        for (int mask = 0; mask < (1 << n); ++mask) {
            if (__builtin_popcount(unsigned(mask)) != j) continue;
            double prod = 1;
            for (int k = 0; k < n; ++k) prod *= (mask >> k & 1) ? 1 - roots[k] : -roots[k];
            sum += prod;
            ++count;
        }
        coeff[std::size_t(j)] = sum / count;
    }
    return coeff;
}

TEST(Roots, BernsteinRootsFindEveryRootOfRandomPolynomials) {
    testing::Rng rng(31);
    for (int i = 0; i < 200; ++i) {
        // The product of (t - r_k) for known roots r_k in (0, 1).
        const int n = rng.integer(1, 5);
        std::vector<double> roots(std::size_t(n), 0.0);
        for (double& r : roots) r = rng.uniform(0.02, 0.98);
        std::sort(roots.begin(), roots.end());
        bool separated = true;
        for (int k = 1; k < n; ++k) separated &= roots[k] - roots[k - 1] > 1e-3;
        if (!separated) continue;
        std::array<double, 6> found{};
        const int k = bernstein_roots(bernstein_of_roots(roots), found);
        ASSERT_EQ(k, n) << "case " << i;
        for (int j = 0; j < n; ++j) EXPECT_NEAR(found[j], roots[j], 1e-9) << "case " << i;
    }
}

// The reference: bisection down to neighbouring doubles.
template <class F>
double bisected_root(F&& f, double a, double b) {
    const bool a_above = f(a) >= 0;
    for (;;) {
        const double m = 0.5 * (a + b);
        if (!(m > a && m < b)) return m;
        (((f(m) >= 0) == a_above) ? a : b) = m;
    }
}

TEST(Roots, BracketedRootMatchesBisectionInFewerSteps) {
    // Polynomials with one simple root in the bracket, some flat there
    // (t^k near 0), where regula falsi alone would crawl from one side.
    testing::Rng rng(5);
    int total_steps = 0;
    for (int i = 0; i < 500; ++i) {
        const double r = rng.uniform(0.01, 0.99), s = rng.uniform(0.5, 4);
        const int k = 1 + 2 * rng.integer(0, 4); // odd: a sign change at r
        const auto f = [&](double t) { return s * std::pow(t - r, k) + 1e-3 * (t - r); };
        int steps = 0;
        const auto counted = [&](double t) { return ++steps, f(t); };
        const double t = bracketed_root(counted, 0.0, 1.0, f(0.0), f(1.0), 0.0);
        EXPECT_NEAR(t, bisected_root(f, 0.0, 1.0), 1e-15) << "root " << r << " power " << k;
        // Bisection takes 53 to 60 halvings from [0, 1]; a third more at worst.
        EXPECT_LE(steps, 80) << "root " << r << " power " << k;
        total_steps += steps;
    }
    EXPECT_LT(total_steps, 500 * 20) << "no faster than bisection on average";
}

// Regression: the sides were told by the halved end values, and a negative
// denormal halved to -0, which reads as positive: the bracket was lost and
// 0.7675 came back for a sign change at 0.7.
TEST(Roots, BracketedRootKeepsItsSidesWhenAHalvedValueUnderflows) {
    const auto f = [](double t) { return t < 0.7 ? -4.94e-324 : t - 0.7; };
    EXPECT_NEAR(bracketed_root(f, 0.69, 1.0, f(0.69), f(1.0), 0.0), 0.7, 1e-15);
    EXPECT_EQ(bernstein_value({}, 0.5), 0.0);
    // Coefficients whose products underflow still isolate their root.
    const std::vector<double> tiny = {-1e-170, 1e-170};
    std::array<double, 1> found{};
    ASSERT_EQ(bernstein_roots(tiny, found), 1);
    EXPECT_NEAR(found[0], 0.5, 1e-12);
}

TEST(Roots, BernsteinRootsResolveClustersAndDoubleRoots) {
    // (t - 0.3)(t - 0.3 - 1e-7)(t - 0.7) and (t - 0.2)(t - 0.5)^2 in Bernstein
    // form (blossoms), where isolation needs deep splits or never comes.
    std::array<double, 3> found{};
    ASSERT_EQ(bernstein_roots(bernstein_of_roots({0.3, 0.3 + 1e-7, 0.7}), found), 3);
    EXPECT_NEAR(found[0], 0.3, 1e-10);
    EXPECT_NEAR(found[1], 0.3 + 1e-7, 1e-10);
    EXPECT_NEAR(found[2], 0.7, 1e-10);
    const int k = bernstein_roots(bernstein_of_roots({0.2, 0.5, 0.5}), found);
    ASSERT_GE(k, 1);
    EXPECT_NEAR(found[0], 0.2, 1e-10);
    for (int i = 1; i < k; ++i) EXPECT_NEAR(found[std::size_t(i)], 0.5, 1e-6) << i;
}

TEST(Roots, ZeroPolynomialHasNoIsolatedRoots) {
    const std::array<double, 4> zero{};
    std::array<double, 3> out{};
    EXPECT_EQ(bernstein_roots(zero, out), 0);
}

} // namespace
} // namespace casteljau
