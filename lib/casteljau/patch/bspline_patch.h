// BSplinePatch: one 4x4 piece of a uniform bicubic B-spline surface.
//
// Matrix form x = S M G M^T T with M = kBSplineMatrix (basis_matrix.h), S in v
// and T in u, G the 4x4 grid c[r][k] (rows along v). The piece is a bicubic
// Bezier patch whose control points are, row by row and then column by
// column, the images of four B-spline points under
//   P0 = (b0 + 4 b1 + b2) / 6,   P1 = (4 b1 + 2 b2) / 6,
//   P2 = (2 b1 + 4 b2) / 6,      P3 = (b1 + 4 b2 + b3) / 6
// (Boehm's conversion; Farin 5th ed., 7.5): to_bezier(). Evaluation by nested
// de Casteljau goes through that conversion; eval_matrix() does not. Neither
// the surface nor its corners interpolate the control points.
#pragma once

#include "casteljau/patch/bezier_patch.h"

#include <array>

namespace casteljau {

/// A uniform bicubic B-spline patch: 4 x 4 control points.
struct BSplinePatch {
    PatchGrid<4, 4> c{};

    /// The surface at (u, v) by the B-spline matrix form.
    constexpr PatchPoint eval_matrix(double u, double v) const {
        return tensor_sum(basis_weights(kBSplineMatrix, v), basis_weights(kBSplineMatrix, u), c);
    }

    /// The same surface as a bicubic Bezier patch.
    constexpr CubicPatch to_bezier() const {
        constexpr double w[4][4] = {{1 / 6.0, 4 / 6.0, 1 / 6.0, 0},
                                    {0, 4 / 6.0, 2 / 6.0, 0},
                                    {0, 2 / 6.0, 4 / 6.0, 0},
                                    {0, 1 / 6.0, 4 / 6.0, 1 / 6.0}};
        std::array<std::array<PatchPoint, 4>, 4> rows{};
        for (int r = 0; r < 4; ++r)
            for (int i = 0; i < 4; ++i) {
                AffineSum s;
                for (int k = 0; k < 4; ++k) s.add(w[i][k], c[r][k]);
                rows[r][i] = s.point();
            }
        CubicPatch out;
        for (int i = 0; i < 4; ++i)
            for (int k = 0; k < 4; ++k) {
                AffineSum s;
                for (int r = 0; r < 4; ++r) s.add(w[i][r], rows[r][k]);
                out.c[i][k] = s.point();
            }
        return out;
    }

    /// The surface at (u, v), through its Bezier form.
    constexpr PatchPoint eval(double u, double v) const { return to_bezier().eval(u, v); }
    /// Position and first derivatives at (u, v).
    constexpr PatchDerivatives derivatives(double u, double v) const {
        return to_bezier().derivatives(u, v);
    }
    /// Box of the control points, which holds the curve (convex hull property).
    constexpr Box3 control_bounds() const { return grid_bounds(c); }
};

} // namespace casteljau
