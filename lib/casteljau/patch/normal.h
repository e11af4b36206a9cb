// Unit normals of a patch, including at degenerate edges.
//
// n = du x dv / |du x dv| wherever that cross product is not negligible (it is
// compared with the square of the control net's size, so the test does not
// depend on units). Where one derivative vanishes along a whole edge, as at
// the poles of the teapot's lid and body where a row of control points
// collapses to one point, the normal is the limit along the parameter line:
// if du = 0 on the edge v = v0, then du(u, v) = (v - v0) duv(u, v0) + O((v - v0)^2),
// so n -> sign(v - v0) (duv x dv) / |duv x dv| as v approaches v0 from inside
// the patch (and symmetrically for dv = 0 on u = u0). Only where that too
// vanishes (a corner where both edges collapse) is the normal taken a small
// step toward the patch centre. A patch collapsed to a point has none: {}.
#pragma once

#include "casteljau/patch/bezier_patch.h"

namespace casteljau {

namespace detail {

/// |n|^2 against (1e-10 L^2)^2: well above rounding of the cross product of
/// derivatives of size L (about 1e-16 L^2), well below any real tangent plane.
inline bool normal_is_degenerate(Vec3 n, double size) {
    const double floor = 1e-10 * size * size;
    return n.length_sq() <= floor * floor;
}

} // namespace detail

/// With the derivatives at (u, v) and the control net's size already at hand
/// (the tessellators have both).
template <class Patch>
Vec3 patch_normal(const Patch& patch, double u, double v, const PatchDerivatives& d, double size) {
    Vec3 n = d.du.cross(d.dv);
    if (!detail::normal_is_degenerate(n, size)) return n.normalized();
    if (d.du.length_sq() <= d.dv.length_sq())
        n = (v < 0.5 ? 1.0 : -1.0) * d.duv.cross(d.dv);
    else
        n = (u < 0.5 ? 1.0 : -1.0) * d.du.cross(d.duv);
    if (!detail::normal_is_degenerate(n, size)) return n.normalized();
    for (double h : {1e-6, 1e-4, 1e-2}) {
        const auto e = patch.derivatives(u + (0.5 - u) * h, v + (0.5 - v) * h);
        n = e.du.cross(e.dv);
        if (!detail::normal_is_degenerate(n, size)) return n.normalized();
    }
    return {};
}

template <class Patch>
Vec3 patch_normal(const Patch& patch, double u, double v) {
    return patch_normal(patch, u, v, patch.derivatives(u, v), patch.control_bounds().diagonal());
}

} // namespace casteljau
