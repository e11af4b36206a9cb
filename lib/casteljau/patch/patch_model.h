// PatchModel: the surface patches of one file, whatever their source.
//
// Every patch is held as one of the three Bezier kinds: B-spline pieces are
// stored as their exact Bezier conversion and mixed-degree patches (a 1 x 3
// from a .bpt file) are degree-elevated to the square kind, neither of which
// changes the surface. Shared boundaries stay shared bit for bit because both
// conversions are computed from the same control points in the same order.
#pragma once

#include "casteljau/patch/bezier_patch.h"

#include <span>
#include <variant>
#include <vector>

namespace casteljau {

using AnyPatch = std::variant<BilinearPatch, QuadPatch, CubicPatch>;

/// The Bezier patch of degree du in u and dv in v (each 1 to 3) on a grid of
/// dv + 1 rows of du + 1 points (row-major, rows along v), degree-elevated to
/// the square kind of the larger degree.
AnyPatch bezier_from_grid(int du, int dv, std::span<const PatchPoint> points);

/// A model: its patches, in any mix of kinds.
struct PatchModel {
    std::vector<AnyPatch> patches;

    /// Box of the control points, which holds the curve (convex hull property).
    Box3 control_bounds() const {
        Box3 b;
        for (const AnyPatch& p : patches) {
            const Box3 pb = std::visit([](const auto& q) { return q.control_bounds(); }, p);
            b.add(pb.lo);
            b.add(pb.hi);
        }
        return b;
    }
};

} // namespace casteljau
