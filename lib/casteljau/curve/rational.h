// Rational Bezier curves of any degree, in homogeneous coordinates.
//
// R(t) = sum_i B_i^n(t) w_i P_i / sum_i B_i^n(t) w_i, with every w_i > 0.
// Stored as HPoint (w x, w y, w): the curve is then an ordinary (polynomial)
// Bezier curve in 3D whose central projection is R, so de Casteljau, splitting
// and subsegments are the polynomial ones applied to HPoint (Farin ch. 13).
// With positive weights R([0,1]) lies in the convex hull of the P_i, which is
// the property the flatteners rely on. Affine maps act on the projected points
// and commute with the projection.
#pragma once

#include "casteljau/curve/decasteljau.h"
#include "casteljau/geom/affine.h"

#include <array>
#include <span>

namespace casteljau {

/// A homogeneous 2D point (w x, w y, w).
struct HPoint {
    double x = 0, y = 0, w = 1; ///< x and y are already multiplied by w

    /// The point p with weight w, in homogeneous form.
    static constexpr HPoint weighted(Point p, double w) { return {p.x * w, p.y * w, w}; }
    /// The 2D point it stands for (central projection).
    constexpr Point project() const { return {x / w, y / w}; }
    /// Exact equality of every member.
    constexpr bool operator==(const HPoint&) const = default;
};

constexpr HPoint lerp(HPoint a, HPoint b, double t) {
    const double s = 1.0 - t;
    return {s * a.x + t * b.x, s * a.y + t * b.y, s * a.w + t * b.w};
}

/// A rational Bezier curve of run-time degree, in homogeneous coordinates.
struct RationalBezier {
    int degree = 1;
    std::array<HPoint, kMaxPoints> h{};

    /// The homogeneous control points as a span.
    std::span<const HPoint> hpoints() const { return {h.data(), std::size_t(degree) + 1}; }
    /// Where the curve starts (t = 0).
    Point start() const { return h[0].project(); }
    /// Where the curve ends (t = 1).
    Point end() const { return h[std::size_t(degree)].project(); }
    /// Control point i, projected.
    Point control_point(int i) const { return h[std::size_t(i)].project(); }
    /// The weight of control point i.
    double weight(int i) const { return h[std::size_t(i)].w; }

    /// The point at parameter t in [0, 1].
    Point eval(double t) const { return decasteljau_eval(hpoints(), t).project(); }
    /// The pieces over [0, t] and [t, 1], by de Casteljau.
    std::array<RationalBezier, 2> split(double t) const {
        std::array<RationalBezier, 2> r;
        const std::size_t n = std::size_t(degree) + 1;
        r[0].degree = r[1].degree = degree;
        decasteljau_split(hpoints(), t, std::span<HPoint>(r[0].h.data(), n),
                          std::span<HPoint>(r[1].h.data(), n));
        return r;
    }
    /// The piece over [t0, t1], as a curve over [0, 1].
    RationalBezier subsegment(double t0, double t1) const {
        RationalBezier r;
        r.degree = degree;
        decasteljau_subsegment(hpoints(), t0, t1,
                               std::span<HPoint>(r.h.data(), std::size_t(degree) + 1));
        return r;
    }
    /// The curve mapped by m (its control points mapped).
    RationalBezier transformed(const Affine& m) const {
        RationalBezier r = *this;
        for (int i = 0; i <= degree; ++i) r.h[i] = HPoint::weighted(m * h[i].project(), h[i].w);
        return r;
    }
};

} // namespace casteljau
