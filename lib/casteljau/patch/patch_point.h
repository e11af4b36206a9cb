// PatchPoint: a control point of a surface patch, five coordinates x y z s t.
//
// The texture coordinates (s, t) follow exactly the same Bezier formula as the
// position (the Quake 3 convention: g(u, v) = f(u, f(v, c00, c10, c20), ...)),
// so every construction here (de Casteljau, matrix form, subdivision) runs on
// PatchPoint as a whole and texture coordinates are never an afterthought.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/point3.h"

#include <array>
#include <cstddef>

namespace casteljau {

/// A surface control point: position and texture coordinates.
struct PatchPoint {
    Point3 p;
    Point st;

    /// Exact equality of every member.
    constexpr bool operator==(const PatchPoint&) const = default;
    /// Whether every component is finite.
    bool is_finite() const { return p.is_finite() && st.is_finite(); }
};

constexpr PatchPoint lerp(const PatchPoint& a, const PatchPoint& b, double t) {
    return {lerp(a.p, b.p, t), lerp(a.st, b.st, t)};
}

/// Accumulates sum_i w_i q_i for weights that sum to one (an affine
/// combination, as in the matrix forms and the B-spline basis), so that the
/// sum is again a point.
struct AffineSum {
    Vec3 p{};
    Vec2 st{};

    /// Adds w times q.
    constexpr void add(double w, const PatchPoint& q) {
        p += w * q.p.to_vec();
        st += w * q.st.to_vec();
    }
    /// The sum as a point (meaningful when the weights sum to 1).
    constexpr PatchPoint point() const { return {Point3{} + p, Point{} + st}; }
};

template <std::size_t K, std::size_t R>
using PatchGrid = std::array<std::array<PatchPoint, K>, R>; ///< R rows (along v) of K points

/// sum_r sum_k wv[r] wu[k] c[r][k]: the point of a tensor-product patch from
/// its basis values in v and in u (the matrix forms' last step).
template <std::size_t K, std::size_t R>
constexpr PatchPoint tensor_sum(const std::array<double, R>& wv, const std::array<double, K>& wu,
                                const PatchGrid<K, R>& c) {
    AffineSum sum;
    for (std::size_t r = 0; r < R; ++r)
        for (std::size_t k = 0; k < K; ++k) sum.add(wv[r] * wu[k], c[r][k]);
    return sum.point();
}

/// The smallest box holding a control grid, hence its patch (convex hull property).
template <std::size_t K, std::size_t R>
constexpr Box3 grid_bounds(const PatchGrid<K, R>& c) {
    Box3 b;
    for (const auto& row : c)
        for (const PatchPoint& q : row) b.add(q.p);
    return b;
}

} // namespace casteljau
