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
        // Bernstein coefficients of prod (t - r_k): c_i = blossom at (0^(n-i), 1^i),
        // which for a product of linear factors is prod over factors of the
        // factor's value at 0 or 1, symmetrised over positions.
        std::array<double, 7> coeff{};
        for (int j = 0; j <= n; ++j) {
            // Average over all subsets of size j of factors evaluated at 1.
            double sum = 0;
            int count = 0;
            for (int mask = 0; mask < (1 << n); ++mask) {
                if (__builtin_popcount(unsigned(mask)) != j) continue;
                double prod = 1;
                for (int k = 0; k < n; ++k) prod *= (mask >> k & 1) ? 1 - roots[k] : -roots[k];
                sum += prod;
                ++count;
            }
            coeff[j] = sum / count;
        }
        std::array<double, 6> found{};
        const int k =
            bernstein_roots(std::span<const double>(coeff.data(), std::size_t(n) + 1), found);
        ASSERT_EQ(k, n) << "case " << i;
        for (int j = 0; j < n; ++j) EXPECT_NEAR(found[j], roots[j], 1e-9) << "case " << i;
    }
}

TEST(Roots, ZeroPolynomialHasNoIsolatedRoots) {
    const std::array<double, 4> zero{};
    std::array<double, 3> out{};
    EXPECT_EQ(bernstein_roots(zero, out), 0);
}

} // namespace
} // namespace casteljau
