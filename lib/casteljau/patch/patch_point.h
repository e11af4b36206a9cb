// PatchPoint: a control point of a surface patch, five coordinates x y z s t.
//
// The texture coordinates (s, t) follow exactly the same Bezier formula as the
// position (the Quake 3 convention: g(u, v) = f(u, f(v, c00, c10, c20), ...)),
// so every construction here (de Casteljau, matrix form, subdivision) runs on
// PatchPoint as a whole and texture coordinates are never an afterthought.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/geom/point3.h"

namespace casteljau {

struct PatchPoint {
    Point3 p;
    Point st;

    constexpr bool operator==(const PatchPoint&) const = default;
    bool is_finite() const { return p.is_finite() && st.is_finite(); }
};

constexpr PatchPoint lerp(const PatchPoint& a, const PatchPoint& b, double t) {
    return {lerp(a.p, b.p, t), lerp(a.st, b.st, t)};
}

// Accumulates sum_i w_i q_i for weights that sum to one (an affine
// combination, as in the matrix forms and the B-spline basis), so that the
// sum is again a point.
struct AffineSum {
    Vec3 p{};
    Vec2 st{};

    constexpr void add(double w, const PatchPoint& q) {
        p += w * q.p.to_vec();
        st += w * q.st.to_vec();
    }
    constexpr PatchPoint point() const { return {Point3{} + p, Point{} + st}; }
};

} // namespace casteljau
