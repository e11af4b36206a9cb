// How far, in pixels, a patch piece can be from triangles through its surface.
//
// Let q_rk be the control points in camera space (right, down, forward), L the
// bilinear interpolant of the four corners and d_rk = q_rk - L(k/M, r/N).
// Degree-elevated, L has exactly the control points L(k/M, r/N), so the piece
// is S = L + E with E a Bezier patch on the d_rk: E(u, v) lies in their hull.
// Take any triangle whose corners are surface points S(w_a) of the piece, a
// point T = sum b_a S(w_a) of it and the surface point S(w) at w = sum b_a w_a:
//   T - S(w) = [sum b_a L(w_a) - L(w)] + [sum b_a E(w_a) - E(w)].
// L is affine plus the twist term uv (q00 - q10 - q01 + q11), so the first
// bracket is the twist times a covariance of (u, v) over the unit square,
// at most 1/4; the second is a difference of two points of hull(d), at most
// twice its largest member.
//
// To pixels: for camera points A = B + e, the pixel distance is exactly
//   |pi(A) - pi(B)| = f / A.z * |e_xy - (B_xy / B.z) e_z|,
// the error with its component along the ray through B removed (errors along
// the line of sight do not show). Both A and B lie in the control hull, so
// A.z >= z_min, and B_xy / B.z, a linear-fractional function, takes its
// extremes over the hull at control points: it is r0 + delta with |delta| <= dr
// around the corners' mean ray r0. Each term is convex in e, so its maximum
// over a hull is at a vertex, and
//   bound = f / z_min * (2 max_rk P(d_rk) + P(twist) / 4),
//   P(e) = |e_xy - r0 e_z| + dr |e_z|.
// This holds for every triangulation of the piece with vertices on it, which
// is what lets the tessellator add edge vertices for its neighbours freely.
//
// Where part of the hull is nearer than `near` (clipped anyway), depths are
// clamped to `near`; the bound then covers only the part drawn. A piece
// entirely behind `near` or beside the image is invisible: it is not refined.
#pragma once

#include "casteljau/tessellate/projection.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

/// The screen-space flatness bound of a patch and its parts.
struct ScreenFlatness {
    double bound = 0;                ///< px, as above
    double u_bend = 0;               ///< px: how far the rows bend away from their chords
    double v_bend = 0;               ///< px: the same for the columns
    double u_width = 0, v_width = 0; ///< px: extent along u and along v
    bool visible = true;
};

template <class Patch>
ScreenFlatness screen_flatness(const Patch& piece, const ScreenProjection& s) {
    constexpr int M = Patch::kDegreeU, N = Patch::kDegreeV;
    Vec3 q[N + 1][M + 1];
    double zmin = INFINITY, zmax = -INFINITY;
    double px_lo = INFINITY, px_hi = -INFINITY, py_lo = INFINITY, py_hi = -INFINITY;
    for (int r = 0; r <= N; ++r)
        for (int k = 0; k <= M; ++k) {
            q[r][k] = s.to_camera(piece.c[r][k].p);
            zmin = std::min(zmin, q[r][k].z);
            zmax = std::max(zmax, q[r][k].z);
        }
    ScreenFlatness out;
    if (zmax < s.near) {
        out.visible = false;
        return out;
    }
    const auto ray = [&](Vec3 c) {
        const double z = std::max(c.z, s.near);
        return Vec2{c.x / z, c.y / z};
    };
    const Vec2 r0 = 0.25 * (ray(q[0][0]) + ray(q[0][M]) + ray(q[N][0]) + ray(q[N][M]));
    double dr = 0;
    for (int r = 0; r <= N; ++r)
        for (int k = 0; k <= M; ++k) {
            const Vec2 d = ray(q[r][k]);
            dr = std::max(dr, (d - r0).length());
            px_lo = std::min(px_lo, d.x), px_hi = std::max(px_hi, d.x);
            py_lo = std::min(py_lo, d.y), py_hi = std::max(py_hi, d.y);
        }
    const double f = s.focal;
    if (zmin >= s.near && (s.center.x + f * px_hi < 0 || s.center.x + f * px_lo > s.width ||
                           s.center.y + f * py_hi < 0 || s.center.y + f * py_lo > s.height)) {
        out.visible = false;
        return out;
    }
    const double scale = f / std::max(zmin, s.near);
    const auto P = [&](Vec3 e) {
        return Vec2{e.x - r0.x * e.z, e.y - r0.y * e.z}.length() + dr * std::abs(e.z);
    };
    double dev = 0;
    for (int r = 0; r <= N; ++r)
        for (int k = 0; k <= M; ++k) {
            const double a = double(k) / M, b = double(r) / N;
            const Vec3 l = lerp(lerp(q[0][0], q[0][M], a), lerp(q[N][0], q[N][M], a), b);
            dev = std::max(dev, P(q[r][k] - l));
            out.u_bend = std::max(out.u_bend, P(q[r][k] - lerp(q[r][0], q[r][M], a)));
            out.v_bend = std::max(out.v_bend, P(q[r][k] - lerp(q[0][k], q[N][k], b)));
        }
    const double twist = P(q[0][0] - q[0][M] - q[N][0] + q[N][M]);
    out.bound = scale * (2 * dev + 0.25 * twist);
    out.u_bend *= scale;
    out.v_bend *= scale;
    out.u_width = scale * std::max(P(q[0][M] - q[0][0]), P(q[N][M] - q[N][0]));
    out.v_width = scale * std::max(P(q[N][0] - q[0][0]), P(q[N][M] - q[0][M]));
    return out;
}

} // namespace casteljau
