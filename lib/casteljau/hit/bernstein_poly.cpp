#include "casteljau/hit/bernstein_poly.h"

#include "casteljau/curve/roots.h"

#include <type_traits>
#include <variant>

namespace casteljau {

double BernsteinPoly::eval(double t) const { return bernstein_value(coefficients(), t); }

BernsteinPoly operator*(const BernsteinPoly& a, const BernsteinPoly& b) {
    BernsteinPoly r;
    r.degree = a.degree + b.degree;
    // The binomials once each (C(n, i) takes i divisions), not per term.
    std::array<double, BernsteinPoly::kMaxDegree + 1> ca, cb, inv_cr;
    for (int i = 0; i <= a.degree; ++i) ca[std::size_t(i)] = binomial(a.degree, i) * a.c[i];
    for (int j = 0; j <= b.degree; ++j) cb[std::size_t(j)] = binomial(b.degree, j) * b.c[j];
    for (int k = 0; k <= r.degree; ++k) inv_cr[std::size_t(k)] = 1 / binomial(r.degree, k);
    for (int i = 0; i <= a.degree; ++i)
        for (int j = 0; j <= b.degree; ++j)
            r.c[i + j] += ca[std::size_t(i)] * cb[std::size_t(j)] * inv_cr[std::size_t(i + j)];
    return r;
}

BernsteinPoly operator-(const BernsteinPoly& a, const BernsteinPoly& b) {
    BernsteinPoly r = a;
    for (int i = 0; i <= a.degree; ++i) r.c[i] -= b.c[i];
    return r;
}

BernsteinPoly operator+(const BernsteinPoly& a, const BernsteinPoly& b) {
    BernsteinPoly r = a;
    for (int i = 0; i <= a.degree; ++i) r.c[i] += b.c[i];
    return r;
}

BernsteinPoly derivative(const BernsteinPoly& a) {
    BernsteinPoly r;
    if (a.degree == 0) return r;
    r.degree = a.degree - 1;
    for (int i = 0; i < a.degree; ++i) r.c[i] = a.degree * (a.c[i + 1] - a.c[i]);
    return r;
}

namespace {

template <std::size_t N>
HomogeneousSegment from_points(const std::array<Point, N>& p, const std::array<double, N>& w,
                               Point origin) {
    HomogeneousSegment h;
    h.x.degree = h.y.degree = h.w.degree = int(N) - 1;
    for (std::size_t i = 0; i < N; ++i) {
        h.x.c[i] = w[i] * (p[i].x - origin.x);
        h.y.c[i] = w[i] * (p[i].y - origin.y);
        h.w.c[i] = w[i];
    }
    return h;
}

} // namespace

HomogeneousSegment HomogeneousSegment::from(const Segment& s, Point origin) {
    return std::visit(
        [&](const auto& c) {
            using Curve = std::decay_t<decltype(c)>;
            if constexpr (std::is_same_v<Curve, Conic>) {
                return from_points(c.control_points(), std::array<double, 3>{1.0, c.w, 1.0},
                                   origin);
            } else {
                std::array<double, Curve::degree + 1> ones;
                ones.fill(1.0);
                return from_points(c.p, ones, origin);
            }
        },
        s);
}

BernsteinPoly HomogeneousSegment::x_minus(double v) const {
    BernsteinPoly r = x;
    for (int i = 0; i <= r.degree; ++i) r.c[i] -= v * w.c[i];
    return r;
}

BernsteinPoly HomogeneousSegment::y_minus(double v) const {
    BernsteinPoly r = y;
    for (int i = 0; i <= r.degree; ++i) r.c[i] -= v * w.c[i];
    return r;
}

int roots_in_unit_interval(const BernsteinPoly& p, std::span<double> out) {
    return bernstein_roots(p.coefficients(), out);
}

} // namespace casteljau
