#include "casteljau/flatten/flatness.h"

#include "casteljau/curve/roots.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

namespace {

// Signed offsets of the inner control points from the chord line, scaled by
// the chord length (cross(P_i - P_0, v) = |v| d_i: the division by |v| is left
// to the caller, once). False when the chord is degenerate or some point
// projects outside the chord.
template <std::size_t K>
bool inner_offsets(std::span<const Point> p, std::array<double, K>& d, double& len_sq) {
    const Point a = p.front(), b = p.back();
    const Vec2 v = b - a;
    len_sq = v.length_sq();
    if (len_sq == 0.0) return false;
    for (std::size_t i = 0; i < K; ++i) {
        const Vec2 w = p[i + 1] - a;
        const double along = w.dot(v);
        if (along < 0.0 || along > len_sq) return false;
        d[i] = w.cross(v);
    }
    return true;
}

} // namespace

double hull_deviation(std::span<const Point> control) noexcept {
    const Point a = control.front(), b = control.back();
    double m = 0;
    for (std::size_t i = 1; i + 1 < control.size(); ++i)
        m = std::max(m, distance_to_segment(control[i], a, b));
    return m;
}

double chord_deviation(const Line&) noexcept { return 0.0; }

double chord_deviation(const QuadBez& c) noexcept {
    std::array<double, 1> d;
    double len_sq;
    if (!inner_offsets(c.points(), d, len_sq)) return hull_deviation(c.points());
    return 0.5 * std::fabs(d[0]) / std::sqrt(len_sq);
}

double chord_deviation(const CubicBez& c) noexcept {
    std::array<double, 2> d;
    double len_sq;
    if (!inner_offsets(c.points(), d, len_sq)) return hull_deviation(c.points());
    const auto offset = [&](double t) {
        return 3.0 * t * (1.0 - t) * ((1.0 - t) * d[0] + t * d[1]);
    };
    double roots[2];
    const int k = solve_quadratic(3.0 * (d[0] - d[1]), 2.0 * d[1] - 4.0 * d[0], d[0], roots);
    double m = 0;
    for (int i = 0; i < k; ++i)
        if (roots[i] > 0.0 && roots[i] < 1.0) m = std::max(m, std::fabs(offset(roots[i])));
    return m / std::sqrt(len_sq);
}

double chord_deviation(const Conic& c) noexcept {
    const std::array<Point, 3> p{c.p0, c.p1, c.p2};
    std::array<double, 1> d;
    double len_sq;
    if (!inner_offsets(std::span<const Point>(p), d, len_sq)) return hull_deviation(p);
    return c.w * std::fabs(d[0]) / ((1.0 + c.w) * std::sqrt(len_sq));
}

double chord_deviation(const HConic& c) noexcept { return chord_deviation(c.standard()); }

double hull_deviation(const HConic& c) noexcept { return hull_deviation(c.standard()); }

double chord_deviation(const Bezier& c) noexcept { return hull_deviation(c.points()); }

double hull_deviation(const Conic& c) noexcept {
    const std::array<Point, 3> p{c.p0, c.p1, c.p2};
    return hull_deviation(p);
}

double hull_deviation(const Bezier& c) noexcept { return hull_deviation(c.points()); }

double hull_deviation(const RationalBezier& c) noexcept {
    std::array<Point, kMaxPoints> p;
    for (int i = 0; i <= c.degree; ++i) p[i] = c.control_point(i);
    return hull_deviation(std::span<const Point>(p.data(), std::size_t(c.degree) + 1));
}

double chord_deviation(const RationalBezier& c) noexcept {
    // A rational quadratic is a conic: use its exact form.
    if (c.degree == 2) return chord_deviation(HConic{{c.h[0], c.h[1], c.h[2]}});
    return hull_deviation(c);
}

} // namespace casteljau
