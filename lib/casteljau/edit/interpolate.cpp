#include "casteljau/edit/interpolate.h"

#include <algorithm>

namespace casteljau {

namespace {

// The Thomas algorithm for x_{i-1} + diag_i x_i + x_{i+1} = r_i (x_{-1} =
// x_n = 0), in two steps so that one matrix serves several right-hand sides:
// the pivots of the elimination, then a solve in place for each r.
std::vector<double> thomas_pivots(std::vector<double> diag) {
    for (std::size_t i = 1; i < diag.size(); ++i) diag[i] -= 1.0 / diag[i - 1];
    return diag;
}

template <class T> // double or Vec2
void thomas_solve(const std::vector<double>& pivot, std::vector<T>& r) {
    const std::size_t n = r.size();
    for (std::size_t i = 1; i < n; ++i) r[i] -= r[i - 1] * (1.0 / pivot[i - 1]);
    r[n - 1] = r[n - 1] * (1.0 / pivot[n - 1]);
    for (std::size_t i = n - 1; i-- > 0;) r[i] = (r[i] - r[i + 1]) * (1.0 / pivot[i]);
}

// Solves D_{i-1} + 4 D_i + D_{i+1} = rhs_i with indices mod n (n >= 3): the
// cyclic system is the tridiagonal one with corner entries 1, i.e. A' + u v^T
// with u = (gamma, 0.., 1), v = (1, 0.., 1/gamma).
std::vector<Vec2> solve_cyclic(std::vector<Vec2> rhs) {
    const std::size_t n = rhs.size();
    const double gamma = -4.0; // -diag[0], as Numerical Recipes advises
    std::vector<double> diag(n, 4.0);
    diag[0] -= gamma;
    diag[n - 1] -= 1.0 / gamma;
    const std::vector<double> pivot = thomas_pivots(std::move(diag));
    std::vector<double> u(n, 0.0);
    u[0] = gamma;
    u[n - 1] = 1.0;
    thomas_solve(pivot, rhs);
    thomas_solve(pivot, u);
    const double denom = 1.0 + u[0] + u[n - 1] / gamma;
    const Vec2 fact = (rhs[0] + rhs[n - 1] * (1.0 / gamma)) * (1.0 / denom);
    for (std::size_t i = 0; i < n; ++i) rhs[i] -= fact * u[i];
    return rhs;
}

Point weighted(Point a, double wa, Point b, double wb, Point c, double wc) {
    return Point{} + (a.to_vec() * wa + b.to_vec() * wb + c.to_vec() * wc);
}

} // namespace

std::vector<CubicBez> uniform_bspline_to_beziers(std::span<const Point> d, bool closed) {
    const std::size_t n = d.size();
    std::vector<CubicBez> out;
    if (n < (closed ? 1u : 4u)) return out;
    const std::size_t spans = closed ? n : n - 3;
    out.reserve(spans);
    const auto at = [&](std::size_t i) { return d[i % n]; };
    for (std::size_t k = 0; k < spans; ++k) {
        const Point a = at(k), b = at(k + 1), c = at(k + 2), e = at(k + 3);
        out.push_back({weighted(a, 1.0 / 6, b, 4.0 / 6, c, 1.0 / 6),
                       weighted(b, 2.0 / 3, c, 1.0 / 3, c, 0.0),
                       weighted(b, 1.0 / 3, c, 2.0 / 3, c, 0.0),
                       weighted(b, 1.0 / 6, c, 4.0 / 6, e, 1.0 / 6)});
    }
    return out;
}

Subpath interpolate_c2(std::span<const Point> p, bool closed) {
    Subpath sp;
    sp.closed = closed;
    if (p.empty()) return sp;
    sp.start = p[0];
    if (p.size() < 2) return sp;
    std::vector<Point> d; // B-spline control points
    if (closed && p.size() >= 3) {
        std::vector<Vec2> rhs(p.size());
        for (std::size_t i = 0; i < p.size(); ++i) rhs[i] = p[i].to_vec() * 6.0;
        for (Vec2 v : solve_cyclic(std::move(rhs))) d.push_back(Point{} + v);
    } else {
        // Open (a closed pair is the open curve there and back): natural ends
        // D_0 = p_0, D_n = p_n, and the phantom points D_-1, D_n+1.
        std::vector<Point> q(p.begin(), p.end());
        if (closed) q.push_back(p[0]);
        const std::size_t n = q.size() - 1;
        d.resize(n + 3);
        d[1] = q[0];
        d[n + 1] = q[n];
        if (n >= 2) {
            std::vector<Vec2> rhs(n - 1);
            for (std::size_t i = 1; i < n; ++i) rhs[i - 1] = q[i].to_vec() * 6.0;
            rhs.front() -= q[0].to_vec();
            rhs.back() -= q[n].to_vec();
            thomas_solve(thomas_pivots(std::vector<double>(n - 1, 4.0)), rhs);
            for (std::size_t i = 1; i < n; ++i) d[i + 1] = Point{} + rhs[i - 1];
        }
        d[0] = d[1] + (d[1] - d[2]);
        d[n + 2] = d[n + 1] + (d[n + 1] - d[n]);
    }
    const bool periodic = closed && p.size() >= 3;
    for (const CubicBez& c : uniform_bspline_to_beziers(d, periodic)) sp.segments.push_back(c);
    // The pieces of a periodic spline start at the junction of D_0..D_2, p_1;
    // rotate so that the subpath starts at p_0 like the points.
    if (periodic) {
        std::rotate(sp.segments.begin(), sp.segments.end() - 1, sp.segments.end());
        sp.start = segment_start(sp.segments.front());
    }
    return sp;
}

} // namespace casteljau
