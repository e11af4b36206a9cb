#include "casteljau/curve/bspline.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace casteljau {

namespace {

// The index k of the span [t_k, t_{k+1}) holding u, restricted to p <= k < n
// and to nonempty spans, so the domain's right end belongs to the last span.
std::size_t find_span(const std::vector<double>& t, std::size_t n, int p, double u) {
    const auto first = t.begin() + p, last = t.begin() + std::ptrdiff_t(n);
    std::size_t k = std::size_t(std::upper_bound(first, last, u) - t.begin()) - 1;
    k = std::clamp(k, std::size_t(p), n - 1);
    while (k > std::size_t(p) && t[k] == t[k + 1]) --k; // step back off empty spans
    return k;
}

template <class T>
T de_boor(const std::vector<T>& pts, const std::vector<double>& t, int p, double u) {
    const std::size_t n = pts.size();
    u = std::clamp(u, t[std::size_t(p)], t[n]);
    const std::size_t k = find_span(t, n, p, u);
    std::array<T, kMaxPoints> d;
    for (int j = 0; j <= p; ++j) d[j] = pts[k - std::size_t(p) + std::size_t(j)];
    for (int r = 1; r <= p; ++r) {
        for (int j = p; j >= r; --j) {
            const std::size_t i = k - std::size_t(p) + std::size_t(j);
            const double lo = t[i], hi = t[i + std::size_t(p + 1 - r)];
            d[j] = lerp(d[j - 1], d[j], (u - lo) / (hi - lo));
        }
    }
    return d[std::size_t(p)];
}

template <class T>
void boehm_insert(std::vector<T>& pts, std::vector<double>& t, int p, double u) {
    const std::size_t n = pts.size();
    const std::size_t k = find_span(t, n, p, u);
    std::vector<T> q(n + 1);
    for (std::size_t i = 0; i <= k - std::size_t(p); ++i) q[i] = pts[i];
    for (std::size_t i = k - std::size_t(p) + 1; i <= k; ++i) {
        const double a = (u - t[i]) / (t[i + std::size_t(p)] - t[i]);
        q[i] = lerp(pts[i - 1], pts[i], a);
    }
    for (std::size_t i = k + 1; i <= n; ++i) q[i] = pts[i - 1];
    pts = std::move(q);
    t.insert(t.begin() + std::ptrdiff_t(k) + 1, u);
}

// Control nets of the Bezier pieces, one per nonempty span of the domain.
template <class T>
std::vector<std::vector<T>> bezier_nets(std::vector<T> pts, std::vector<double> t, int p) {
    const double a = t[std::size_t(p)], b = t[pts.size()];
    std::vector<double> breaks;
    for (double u : t)
        if (u >= a && u <= b && (breaks.empty() || breaks.back() != u)) breaks.push_back(u);
    for (double u : breaks) {
        while (std::count(t.begin(), t.end(), u) < p) boehm_insert(pts, t, p, u);
    }
    std::vector<std::vector<T>> nets;
    for (std::size_t k = std::size_t(p); k + 1 <= pts.size(); ++k) {
        if (!(t[k] < t[k + 1])) continue;
        nets.emplace_back(pts.begin() + std::ptrdiff_t(k - std::size_t(p)),
                          pts.begin() + std::ptrdiff_t(k) + 1);
    }
    return nets;
}

std::string validate_knots(int p, std::size_t n, const std::vector<double>& t) {
    if (p < 1 || p > kMaxDegree)
        return "degree " + std::to_string(p) + " is outside 1.." + std::to_string(kMaxDegree);
    if (n < std::size_t(p) + 1)
        return std::to_string(n) + " control points are too few for degree " + std::to_string(p);
    if (t.size() != n + std::size_t(p) + 1)
        return "expected " + std::to_string(n + std::size_t(p) + 1) + " knots, got " +
               std::to_string(t.size());
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (!std::isfinite(t[i])) return "knot " + std::to_string(i) + " is not finite";
        if (i > 0 && t[i] < t[i - 1]) return "knots decrease at index " + std::to_string(i);
    }
    if (!(t[std::size_t(p)] < t[n])) return "the domain [t_p, t_n] is empty";
    for (std::size_t i = 0; i < t.size();) {
        std::size_t j = i;
        while (j < t.size() && t[j] == t[i]) ++j;
        if (j - i > std::size_t(p) + 1)
            return "knot " + std::to_string(t[i]) + " has multiplicity above degree + 1";
        i = j;
    }
    return {};
}

std::string validate_points(const std::vector<Point>& pts) {
    for (std::size_t i = 0; i < pts.size(); ++i)
        if (!pts[i].is_finite()) return "control point " + std::to_string(i) + " is not finite";
    return {};
}

std::vector<HPoint> homogeneous(const Nurbs& c) {
    std::vector<HPoint> h(c.points.size());
    for (std::size_t i = 0; i < h.size(); ++i) h[i] = HPoint::weighted(c.points[i], c.weights[i]);
    return h;
}

} // namespace

std::string BSpline::validate() const {
    std::string e = validate_knots(degree, points.size(), knots);
    return e.empty() ? validate_points(points) : e;
}

Point BSpline::eval(double u) const { return de_boor(points, knots, degree, u); }

void BSpline::insert_knot(double u) { boehm_insert(points, knots, degree, u); }

std::vector<Bezier> BSpline::to_beziers() const {
    std::vector<Bezier> out;
    for (const auto& net : bezier_nets(points, knots, degree)) out.push_back(Bezier::from(net));
    return out;
}

Nurbs Nurbs::circle(Point center, double radius) {
    const double s = std::numbers::sqrt2 / 2;
    Nurbs c;
    c.degree = 2;
    const Vec2 offsets[9] = {{1, 0},   {1, 1},  {0, 1},  {-1, 1}, {-1, 0},
                             {-1, -1}, {0, -1}, {1, -1}, {1, 0}};
    for (int i = 0; i < 9; ++i) {
        c.points.push_back(center + offsets[i] * radius);
        c.weights.push_back(i % 2 ? s : 1.0);
    }
    c.knots = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    return c;
}

std::string Nurbs::validate() const {
    std::string e = validate_knots(degree, points.size(), knots);
    if (!e.empty()) return e;
    if (weights.size() != points.size())
        return "expected " + std::to_string(points.size()) + " weights, got " +
               std::to_string(weights.size());
    for (std::size_t i = 0; i < weights.size(); ++i)
        if (!(weights[i] > 0.0) || !std::isfinite(weights[i]))
            return "weight " + std::to_string(i) + " is not a positive finite number";
    return validate_points(points);
}

Point Nurbs::eval(double u) const {
    return de_boor(homogeneous(*this), knots, degree, u).project();
}

void Nurbs::insert_knot(double u) {
    std::vector<HPoint> h = homogeneous(*this);
    boehm_insert(h, knots, degree, u);
    points.resize(h.size());
    weights.resize(h.size());
    for (std::size_t i = 0; i < h.size(); ++i) points[i] = h[i].project(), weights[i] = h[i].w;
}

std::vector<RationalBezier> Nurbs::to_beziers() const {
    std::vector<RationalBezier> out;
    for (const auto& net : bezier_nets(homogeneous(*this), knots, degree)) {
        RationalBezier r;
        r.degree = degree;
        std::copy(net.begin(), net.end(), r.h.begin());
        out.push_back(r);
    }
    return out;
}

std::vector<double> clamped_uniform_knots(int degree, std::size_t point_count) {
    const std::size_t p = std::size_t(degree), spans = point_count - p;
    std::vector<double> t;
    for (std::size_t i = 0; i < p; ++i) t.push_back(0.0);
    for (std::size_t i = 0; i <= spans; ++i) t.push_back(double(i) / double(spans));
    for (std::size_t i = 0; i < p; ++i) t.push_back(1.0);
    return t;
}

} // namespace casteljau
