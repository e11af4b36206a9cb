#include "casteljau/curve/bezier.h"

#include "casteljau/curve/roots.h"

#include <algorithm>

namespace casteljau {

Bezier Bezier::from(std::span<const Point> pts) {
    Bezier b;
    b.degree = int(pts.size()) - 1;
    std::copy(pts.begin(), pts.end(), b.p.begin());
    return b;
}

PowerForm Bezier::power() const {
    PowerForm f;
    f.degree = degree;
    f.c0 = power_coefficients(points(), f.c);
    return f;
}

namespace {
// Control vectors of the k-th derivative (k = 1, 2); returns how many there are.
std::size_t derivative_net(const Bezier& b, int k, std::array<Vec2, kMaxPoints>& h) {
    hodograph(b.points(), h);
    std::size_t count = std::size_t(b.degree); // the hodograph has degree - 1 + 1 points
    if (k == 2) {
        for (std::size_t i = 0; i + 1 < count; ++i) h[i] = (h[i + 1] - h[i]) * double(count - 1);
        --count;
    }
    return count;
}
} // namespace

Vec2 Bezier::deriv(double t) const {
    std::array<Vec2, kMaxPoints> h{};
    const std::size_t n = derivative_net(*this, 1, h);
    return decasteljau_eval(std::span<const Vec2>(h.data(), n), t);
}

Vec2 Bezier::deriv2(double t) const {
    if (degree < 2) return {};
    std::array<Vec2, kMaxPoints> h{};
    const std::size_t n = derivative_net(*this, 2, h);
    return decasteljau_eval(std::span<const Vec2>(h.data(), n), t);
}

std::array<Bezier, 2> Bezier::split(double t) const {
    std::array<Bezier, 2> halves;
    const std::size_t n = std::size_t(degree) + 1;
    halves[0].degree = halves[1].degree = degree;
    decasteljau_split(points(), t, std::span<Point>(halves[0].p.data(), n),
                      std::span<Point>(halves[1].p.data(), n));
    return halves;
}

Bezier Bezier::subsegment(double t0, double t1) const {
    Bezier s;
    s.degree = degree;
    decasteljau_subsegment(points(), t0, t1, std::span<Point>(s.p.data(), std::size_t(degree) + 1));
    return s;
}

Bezier Bezier::elevate() const {
    Bezier e;
    e.degree = degree + 1;
    elevate_degree(points(), std::span<Point>(e.p.data(), std::size_t(degree) + 2));
    return e;
}

Bezier Bezier::transformed(const Affine& m) const {
    Bezier r = *this;
    for (int i = 0; i <= degree; ++i) r.p[i] = m * p[i];
    return r;
}

Rect Bezier::control_bounds() const {
    Rect r = Rect::empty();
    for (Point q : points()) r = r.united(q);
    return r;
}

Rect Bezier::bounds() const {
    Rect r = Rect::from_points(start(), end());
    std::array<Vec2, kMaxPoints> h{};
    hodograph(points(), h);
    std::array<double, kMaxPoints> cx{}, cy{}, roots{};
    const std::size_t n = std::size_t(degree);
    for (std::size_t i = 0; i < n; ++i) cx[i] = h[i].x, cy[i] = h[i].y;
    for (const auto* c : {&cx, &cy}) {
        const int k = bernstein_roots(std::span<const double>(c->data(), n),
                                      std::span<double>(roots.data(), n));
        for (int i = 0; i < k; ++i) r = r.united(eval(roots[i]));
    }
    return r;
}

bool Bezier::operator==(const Bezier& o) const {
    return degree == o.degree && std::equal(points().begin(), points().end(), o.p.begin());
}

} // namespace casteljau
