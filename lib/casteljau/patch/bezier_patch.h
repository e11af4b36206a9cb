// Tensor-product Bezier patches: BilinearPatch (2x2), QuadPatch (3x3,
// biquadratic, the Quake 3 patch) and CubicPatch (4x4, the Utah teapot's).
//
// The control grid is c[r][k]: row r runs along v, column k along u, so
//   g(u, v) = f(u, f(v, c[0][0], c[1][0], ...), f(v, c[0][1], c[1][1], ...), ...)
// with f the 1D de Casteljau construction (Farin, "Curves and Surfaces for
// CAGD", 5th ed., 16.3). eval() is that nesting; eval_matrix() is the matrix
// form of basis_matrix.h; they agree to rounding (tested).
//
// Derivatives come out of the same construction: reducing each column in v
// down to its last two points gives both the column's point and its v
// derivative N (b - a); reducing those in u the same way gives du, dv and
// the mixed d2g/dudv. Splits in u (v) run de Casteljau along every row
// (column); since lerp is exact at t = 0 and 1, a split keeps the outer rows
// (columns) bit for bit, which tessellate/ relies on for watertight edges.
#pragma once

#include "casteljau/curve/decasteljau.h"
#include "casteljau/patch/basis_matrix.h"
#include "casteljau/patch/patch_point.h"

#include <array>
#include <span>

namespace casteljau {

/// A patch point with its position derivatives.
struct PatchDerivatives {
    PatchPoint point;
    Vec3 du, dv, duv;
};

/// M is the degree in u (columns), N the degree in v (rows).
template <int M, int N>
struct BezierPatch {
    static constexpr int kDegreeU = M, kDegreeV = N;
    /// One row of control points (along u).
    using Row = std::array<PatchPoint, M + 1>;
    PatchGrid<M + 1, N + 1> c{};

    /// Control point of row r, column k.
    constexpr const PatchPoint& at(int r, int k) const { return c[r][k]; }
    /// Corners in the order (u, v) = (0,0), (1,0), (0,1), (1,1).
    constexpr std::array<PatchPoint, 4> corners() const {
        return {c[0][0], c[0][M], c[N][0], c[N][M]};
    }
    /// The boundary or interior curve along u at row r, and along v at column k.
    constexpr Row row(int r) const { return c[r]; }
    /// Column k of control points (along v).
    constexpr std::array<PatchPoint, N + 1> column(int k) const {
        std::array<PatchPoint, N + 1> col{};
        for (int r = 0; r <= N; ++r) col[r] = c[r][k];
        return col;
    }

    /// The surface at (u, v), by de Casteljau.
    constexpr PatchPoint eval(double u, double v) const {
        Row q{};
        for (int k = 0; k <= M; ++k) q[k] = along(column(k), v);
        return along(q, u);
    }

    /// The surface at (u, v) by the matrix form U M P M^T V^T (the reference).
    constexpr PatchPoint eval_matrix(double u, double v) const {
        constexpr BasisMatrix<M> mu = bezier_matrix<M>();
        constexpr BasisMatrix<N> mv = bezier_matrix<N>();
        return tensor_sum(basis_weights(mv, v), basis_weights(mu, u), c);
    }

    /// Position and first derivatives at (u, v).
    constexpr PatchDerivatives derivatives(double u, double v) const {
        Row q{};
        std::array<Vec3, M + 1> qv{};
        for (int k = 0; k <= M; ++k) {
            const auto [a, b] = last_two(column(k), v);
            q[k] = lerp(a, b, v);
            qv[k] = N * (b.p - a.p);
        }
        const auto [a, b] = last_two(q, u);
        const auto [va, vb] = last_two(qv, u);
        return {lerp(a, b, u), M * (b.p - a.p), lerp(va, vb, u), M * (vb - va)};
    }

    /// The halves [0, t] and [t, 1] in u.
    constexpr std::array<BezierPatch, 2> split_u(double t) const {
        std::array<BezierPatch, 2> out{};
        for (int r = 0; r <= N; ++r)
            decasteljau_split(std::span<const PatchPoint, M + 1>(c[r]), t,
                              std::span<PatchPoint, M + 1>(out[0].c[r]),
                              std::span<PatchPoint, M + 1>(out[1].c[r]));
        return out;
    }

    /// The halves [0, t] and [t, 1] in v.
    constexpr std::array<BezierPatch, 2> split_v(double t) const {
        std::array<BezierPatch, 2> out{};
        for (int k = 0; k <= M; ++k) {
            const auto col = column(k);
            std::array<PatchPoint, N + 1> lo{}, hi{};
            decasteljau_split(std::span<const PatchPoint, N + 1>(col), t,
                              std::span<PatchPoint, N + 1>(lo), std::span<PatchPoint, N + 1>(hi));
            for (int r = 0; r <= N; ++r) {
                out[0].c[r][k] = lo[r];
                out[1].c[r][k] = hi[r];
            }
        }
        return out;
    }

    /// The piece over [u0, u1] x [v0, v1].
    constexpr BezierPatch subpatch(double u0, double u1, double v0, double v1) const {
        BezierPatch out = *this;
        for (int r = 0; r <= N; ++r)
            decasteljau_subsegment(std::span<const PatchPoint, M + 1>(c[r]), u0, u1,
                                   std::span<PatchPoint, M + 1>(out.c[r]));
        for (int k = 0; k <= M; ++k) {
            const auto col = out.column(k);
            std::array<PatchPoint, N + 1> piece{};
            decasteljau_subsegment(std::span<const PatchPoint, N + 1>(col), v0, v1,
                                   std::span<PatchPoint, N + 1>(piece));
            for (int r = 0; r <= N; ++r) out.c[r][k] = piece[r];
        }
        return out;
    }

    /// Box of the control points, which holds the curve (convex hull property).
    constexpr Box3 control_bounds() const { return grid_bounds(c); }

  private:
    template <class T, std::size_t K>
    static constexpr T along(const std::array<T, K>& p, double t) {
        return decasteljau_eval(std::span<const T, K>(p), t);
    }
    /// The two points of the last-but-one de Casteljau level: their lerp is the
    /// point, their difference times the degree the derivative.
    template <class T, std::size_t K>
    static constexpr std::array<T, 2> last_two(std::array<T, K> q, double t) {
        if constexpr (K == 1) {
            return {q[0], q[0]};
        } else {
            for (std::size_t n = K - 1; n > 1; --n)
                for (std::size_t i = 0; i < n; ++i) q[i] = lerp(q[i], q[i + 1], t);
            return {q[0], q[1]};
        }
    }
};

using BilinearPatch = BezierPatch<1, 1>;
using QuadPatch = BezierPatch<2, 2>;
using CubicPatch = BezierPatch<3, 3>;

/// Degree elevation in u or v (Farin 5th ed., 5.1 per row): the same surface
/// with one more control point per row (column). Readers use it to bring a
/// mixed-degree patch (say 1 x 3) to one of the three square kinds.
template <int M, int N>
constexpr BezierPatch<M + 1, N> elevate_u(const BezierPatch<M, N>& p) {
    BezierPatch<M + 1, N> out{};
    for (int r = 0; r <= N; ++r) {
        out.c[r][0] = p.c[r][0];
        out.c[r][M + 1] = p.c[r][M];
        for (int k = 1; k <= M; ++k)
            out.c[r][k] = lerp(p.c[r][k], p.c[r][k - 1], double(k) / (M + 1));
    }
    return out;
}

template <int M, int N>
constexpr BezierPatch<M, N + 1> elevate_v(const BezierPatch<M, N>& p) {
    BezierPatch<M, N + 1> out{};
    for (int k = 0; k <= M; ++k) {
        out.c[0][k] = p.c[0][k];
        out.c[N + 1][k] = p.c[N][k];
        for (int r = 1; r <= N; ++r)
            out.c[r][k] = lerp(p.c[r][k], p.c[r - 1][k], double(r) / (N + 1));
    }
    return out;
}

} // namespace casteljau
