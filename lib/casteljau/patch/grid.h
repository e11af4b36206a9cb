// Control grids larger than one patch, cut into patches that share points.
//
// * A (2a+1) x (2b+1) grid (Quake 3's patchDef2) is a x b biquadratic patches;
//   neighbours share a row or column of control points, so they share the
//   boundary curve exactly (the grid is C0 by construction; Quake 3's
//   tr_curve.c reads it the same way).
// * An R x C uniform cubic B-spline grid (R, C >= 4) is x (C-3) pieces,
//   each a 4x4 window; neighbours share three rows or columns, hence C2.
// Grids are row-major: rows along v, points within a row along u.
#pragma once

#include "casteljau/patch/bezier_patch.h"
#include "casteljau/patch/bspline_patch.h"

#include <span>
#include <vector>

namespace casteljau {

/// Requires rows and cols odd and >= 3, and points.size() == rows * cols.
std::vector<QuadPatch> quad_grid_patches(int rows, int cols, std::span<const PatchPoint> points);

/// Requires rows, cols >= 4 and points.size() == rows * cols.
std::vector<BSplinePatch> bspline_grid_patches(int rows, int cols,
                                               std::span<const PatchPoint> points);

} // namespace casteljau
