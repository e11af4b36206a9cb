// The matrix (power) form of tensor-product patches: g(u, v) = V M G M^T U^T.
//
// With T(t) = [t^n, t^(n-1), ..., 1] and M the basis matrix, the row vector
// T(t) M holds the n + 1 basis function values at t, so the patch point is
// sum_r sum_k (V M)_r (U M)_k G[r][k]: the formula x = S M G M^T T of the
// issue, with S in v (rows of the control grid) and T in u (its columns).
//
// Bernstein: B_i(t) = C(n,i) t^i (1-t)^(n-i) = sum_j C(n,i) C(n-i,j-i)
// (-1)^(j-i) t^j, so the entry for power t^(n-p) in column i is
// C(n,i) C(n-i, n-p-i) (-1)^(n-p-i), zero where n-p < i.
// Uniform cubic B-spline (Foley et al., "Computer Graphics", 2nd ed., 11.2.3):
// M = 1/6 [[-1,3,-3,1], [3,-6,3,0], [-3,0,3,0], [1,4,1,0]].
// Each column set sums to one at every t (partition of unity), which is what
// lets the weights combine points affinely.
#pragma once

#include "casteljau/curve/decasteljau.h"

#include <array>
#include <cstddef>

namespace casteljau {

template <int N>
using BasisMatrix = std::array<std::array<double, N + 1>, N + 1>;

template <int N>
constexpr BasisMatrix<N> bezier_matrix() {
    BasisMatrix<N> m{};
    for (int p = 0; p <= N; ++p) {
        const int power = N - p;
        for (int i = 0; i <= power; ++i) {
            const int k = power - i;
            m[p][i] = binomial(N, i) * binomial(N - i, k) * (k % 2 ? -1.0 : 1.0);
        }
    }
    return m;
}

inline constexpr BasisMatrix<3> kBSplineMatrix = {{{-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0},
                                                   {3 / 6.0, -6 / 6.0, 3 / 6.0, 0},
                                                   {-3 / 6.0, 0, 3 / 6.0, 0},
                                                   {1 / 6.0, 4 / 6.0, 1 / 6.0, 0}}};

/// The basis values T(t) M, by Horner's rule down the rows of M.
template <std::size_t K>
constexpr std::array<double, K> basis_weights(const std::array<std::array<double, K>, K>& m,
                                              double t) {
    std::array<double, K> w{};
    for (std::size_t p = 0; p < K; ++p)
        for (std::size_t i = 0; i < K; ++i) w[i] = w[i] * t + m[p][i];
    return w;
}

} // namespace casteljau
