// Bez<N>: a Bezier curve of fixed degree N, with the usual names
// Line = Bez<1>, QuadBez = Bez<2>, CubicBez = Bez<3>.
//
// B(t) = sum_{i=0}^{N} C(N,i) t^i (1-t)^(N-i) p[i],  t in [0, 1].
// Invariants used throughout: B(0) = p[0] and B(1) = p[N] exactly (lerp is
// exact at the ends); B([0,1]) lies in the convex hull of p; B commutes with
// affine maps (transform the control points, not the samples).
//
// Three evaluations are kept because each is the reference for another:
// de Casteljau (`eval`, stable, the one everything else uses), the Bernstein
// sum (`eval_bernstein`) and the power basis (`power()`, cheapest per sample
// once the coefficients exist: what uniform sampling wants).
#pragma once

#include "casteljau/curve/decasteljau.h"
#include "casteljau/curve/roots.h"
#include "casteljau/geom/affine.h"
#include "casteljau/geom/rect.h"

#include <array>
#include <span>

namespace casteljau {

/// c0 + c[0] t + c[1] t^2 + ... : a curve in the power (monomial) basis.
template <int N>
struct PowerCurve {
    Point c0;
    std::array<Vec2, N> c;
    /// The point at parameter t in [0, 1].
    constexpr Point eval(double t) const { return horner_eval(c0, c, t); }
};

/// A Bezier curve of fixed degree N (1, 2 or 3) with its control points inline.
template <int N>
struct Bez {
    static_assert(N >= 1 && N <= 3, "fixed-degree curves are lines, quadratics and cubics");
    static constexpr int degree = N;
    std::array<Point, N + 1> p{};

    constexpr Bez() = default;
    /// From N + 1 control points.
    constexpr Bez(const std::array<Point, N + 1>& pts) : p(pts) {}
    /// A line from a to b.
    constexpr Bez(Point a, Point b) requires(N == 1) : p{a, b} {}
    /// A quadratic from a to c with control point b.
    constexpr Bez(Point a, Point b, Point c) requires(N == 2) : p{a, b, c} {}
    /// A cubic from a to d with control points b and c.
    constexpr Bez(Point a, Point b, Point c, Point d) requires(N == 3) : p{a, b, c, d} {}

    /// Where the curve starts (t = 0).
    constexpr Point start() const { return p[0]; }
    /// Where the curve ends (t = 1).
    constexpr Point end() const { return p[N]; }

    /// The point at parameter t in [0, 1].
    constexpr Point eval(double t) const { return decasteljau_eval(points(), t); }
    /// The point at t by the direct Bernstein sum (the reference for eval).
    constexpr Point eval_bernstein(double t) const { return bernstein_eval(points(), t); }
    /// The same curve in the power basis (for cheap uniform sampling).
    constexpr PowerCurve<N> power() const {
        PowerCurve<N> pc{};
        pc.c0 = power_coefficients(points(), pc.c);
        return pc;
    }

    /// Control vectors of the derivative curve B'(t), a Bezier of degree N - 1.
    constexpr std::array<Vec2, N> hodograph() const {
        std::array<Vec2, N> h{};
        casteljau::hodograph(points(), h);
        return h;
    }
    /// First derivative at t.
    constexpr Vec2 deriv(double t) const {
        const auto h = hodograph();
        return decasteljau_eval(std::span<const Vec2, N>(h), t);
    }
    /// Second derivative at t.
    constexpr Vec2 deriv2(double t) const {
        if constexpr (N == 1) {
            return {};
        } else {
            const auto h = hodograph();
            std::array<Vec2, N - 1> h2{};
            for (int i = 0; i < N - 1; ++i) h2[i] = (h[i + 1] - h[i]) * double(N - 1);
            return decasteljau_eval(std::span<const Vec2, N - 1>(h2), t);
        }
    }

    /// The pieces over [0, t] and [t, 1], by de Casteljau.
    constexpr std::array<Bez, 2> split(double t) const {
        std::array<Bez, 2> halves{};
        decasteljau_split(points(), t, std::span<Point, N + 1>(halves[0].p),
                          std::span<Point, N + 1>(halves[1].p));
        return halves;
    }
    /// The piece over [t0, t1], as a curve over [0, 1].
    constexpr Bez subsegment(double t0, double t1) const {
        Bez s{};
        decasteljau_subsegment(points(), t0, t1, std::span<Point, N + 1>(s.p));
        return s;
    }
    /// The same curve one degree higher (degree elevation).
    constexpr Bez<N + 1> elevate() const requires(N < 3) {
        Bez<N + 1> e{};
        elevate_degree(points(), e.p);
        return e;
    }
    /// The curve mapped by m (its control points mapped).
    constexpr Bez transformed(const Affine& m) const {
        Bez r{};
        for (int i = 0; i <= N; ++i) r.p[i] = m * p[i];
        return r;
    }
    /// The control points.
    constexpr const std::array<Point, N + 1>& control_points() const { return p; }
    /// Box of the control points, which holds the curve (convex hull property).
    constexpr Rect control_bounds() const {
        Rect r = Rect::empty();
        for (Point q : p) r = r.united(q);
        return r;
    }
    /// Tight box: the end points plus the curve at every root of x'(t) and
    /// y'(t) in (0, 1). When the inner control points lie in the end points'
    /// box, so does the curve (convex hull): that box, with no root to find,
    /// which is the common case of glyph outlines and most drawn curves. The
    /// hodograph of a quadratic or a cubic is linear or quadratic: its roots
    /// in closed form; higher degrees by subdivision (bernstein_roots).
    Rect bounds() const {
        Rect r = Rect::from_points(p[0], p[N]);
        bool inside = true;
        for (int i = 1; i < N; ++i) inside = inside && r.contains(p[i]);
        if (inside) return r;
        const auto h = hodograph();
        for (int axis = 0; axis < 2; ++axis) {
            std::array<double, N> c{};
            for (int i = 0; i < N; ++i) c[i] = axis == 0 ? h[i].x : h[i].y;
            std::array<double, N> roots{};
            int k = 0;
            if constexpr (N == 2) { // c0 (1 - t) + c1 t
                if ((c[0] < 0 && c[1] > 0) || (c[0] > 0 && c[1] < 0))
                    roots[k++] = c[0] / (c[0] - c[1]);
            } else if constexpr (N == 3) { // Bernstein (c0, c1, c2) in the power basis
                double q[2];
                const int n = solve_quadratic(c[0] - 2 * c[1] + c[2], 2 * (c[1] - c[0]), c[0], q);
                for (int i = 0; i < n; ++i) roots[k++] = q[i];
            } else {
                k = bernstein_roots(c, roots);
            }
            for (int i = 0; i < k; ++i)
                if (roots[i] > 0 && roots[i] < 1) r = r.united(eval(roots[i]));
        }
        return r;
    }

    /// The control points as a span.
    constexpr std::span<const Point, N + 1> points() const { return p; }
    /// Exact equality of every member.
    constexpr bool operator==(const Bez&) const = default;
};

using Line = Bez<1>;
using QuadBez = Bez<2>;
using CubicBez = Bez<3>;

} // namespace casteljau
