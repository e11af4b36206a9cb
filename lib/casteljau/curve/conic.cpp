#include "casteljau/curve/conic.h"

#include "casteljau/curve/roots.h"

#include <cmath>

namespace casteljau {

namespace {

std::array<HPoint, 3> homogeneous(const Conic& c) { return HConic::from(c).h; }

Conic from_homogeneous(const std::array<HPoint, 3>& h) { return HConic{h}.standard(); }

} // namespace

Conic Conic::circular_arc(Point center, double radius, double a0, double a1) {
    const double half = 0.5 * (a1 - a0), mid = 0.5 * (a0 + a1);
    const double w = std::cos(half);
    const auto on_circle = [&](double a, double r) {
        return center + Vec2{std::cos(a), std::sin(a)} * r;
    };
    return {on_circle(a0, radius), on_circle(mid, radius / w), on_circle(a1, radius), w};
}

Point Conic::eval(double t) const {
    return decasteljau_eval(std::span<const HPoint, 3>(homogeneous(*this)), t).project();
}

Vec2 Conic::deriv(double t) const {
    // Quotient rule on C = N / D with N, D the homogeneous numerator and weight.
    const auto h = homogeneous(*this);
    const HPoint v = decasteljau_eval(std::span<const HPoint, 3>(h), t);
    const HPoint d0{2 * (h[1].x - h[0].x), 2 * (h[1].y - h[0].y), 2 * (h[1].w - h[0].w)};
    const HPoint d1{2 * (h[2].x - h[1].x), 2 * (h[2].y - h[1].y), 2 * (h[2].w - h[1].w)};
    const HPoint dv = lerp(d0, d1, t);
    const double inv = 1.0 / (v.w * v.w);
    return {(dv.x * v.w - v.x * dv.w) * inv, (dv.y * v.w - v.y * dv.w) * inv};
}

Vec2 Conic::deriv2(double t) const {
    // Differentiating N = C D twice: N'' = C'' D + 2 C' D' + C D'', so
    // C'' = (N'' - 2 C' D' - C D'') / D, with N'' and D'' constant.
    const auto h = homogeneous(*this);
    const HPoint v = decasteljau_eval(std::span<const HPoint, 3>(h), t);
    const double dw = 2 * std::lerp(h[1].w - h[0].w, h[2].w - h[1].w, t);
    const double ddw = 2 * (h[0].w - 2 * h[1].w + h[2].w);
    const Vec2 ddn{2 * (h[0].x - 2 * h[1].x + h[2].x), 2 * (h[0].y - 2 * h[1].y + h[2].y)};
    const Vec2 c1 = deriv(t);
    const Vec2 c = v.project().to_vec();
    return (ddn - c1 * (2 * dw) - c * ddw) / v.w;
}

std::array<Conic, 2> Conic::split(double t) const {
    const auto h = homogeneous(*this);
    std::array<HPoint, 3> l{}, r{};
    decasteljau_split(std::span<const HPoint, 3>(h), t, std::span<HPoint, 3>(l),
                      std::span<HPoint, 3>(r));
    return {from_homogeneous(l), from_homogeneous(r)};
}

Conic Conic::subsegment(double t0, double t1) const {
    const auto h = homogeneous(*this);
    std::array<HPoint, 3> s{};
    decasteljau_subsegment(std::span<const HPoint, 3>(h), t0, t1, std::span<HPoint, 3>(s));
    return from_homogeneous(s);
}

Rect Conic::bounds() const {
    // x'(t) has the sign of N_x' D - N_x D', a quadratic: with N = a t^2 + b t + c
    // and D = d t^2 + e t + f it is (ae - bd) t^2 + 2 (af - cd) t + (bf - ce).
    const auto h = homogeneous(*this);
    const double d = h[0].w - 2 * h[1].w + h[2].w, e = 2 * (h[1].w - h[0].w), f = h[0].w;
    Rect r = Rect::from_points(p0, p2);
    for (int axis = 0; axis < 2; ++axis) {
        const auto coord = [&](const HPoint& q) { return axis == 0 ? q.x : q.y; };
        const double a = coord(h[0]) - 2 * coord(h[1]) + coord(h[2]);
        const double b = 2 * (coord(h[1]) - coord(h[0])), c = coord(h[0]);
        double roots[2];
        const int k = solve_quadratic(a * e - b * d, 2 * (a * f - c * d), b * f - c * e, roots);
        for (int i = 0; i < k; ++i)
            if (roots[i] > 0.0 && roots[i] < 1.0) r = r.united(eval(roots[i]));
    }
    return r;
}

RationalBezier Conic::to_rational() const {
    RationalBezier r;
    r.degree = 2;
    const auto h = homogeneous(*this);
    for (int i = 0; i < 3; ++i) r.h[i] = h[i];
    return r;
}

} // namespace casteljau
