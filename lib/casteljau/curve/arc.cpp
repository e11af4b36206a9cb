#include "casteljau/curve/arc.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace casteljau {

namespace {

// Signed angle from u to v in (-pi, pi].
double angle_between(Vec2 u, Vec2 v) { return std::atan2(u.cross(v), u.dot(v)); }

int piece_count(double dtheta) {
    // 1e-9 keeps an exact 90-degree arc in one piece despite rounding.
    const double quarters = std::fabs(dtheta) / (0.5 * std::numbers::pi) - 1e-9;
    return std::clamp(int(std::ceil(quarters)), 1, 4);
}

} // namespace

Affine EllipseArc::unit_circle_map() const {
    return Affine::translate(center.to_vec()) * Affine::rotate(x_rotation) *
           Affine::scale(radii.x, radii.y);
}

EllipseArc svg_arc(const SvgArcInput& in) {
    EllipseArc arc;
    if (in.from == in.to) {
        arc.kind = EllipseArc::Kind::Nothing;
        return arc;
    }
    double rx = std::fabs(in.radii.x), ry = std::fabs(in.radii.y);
    if (rx == 0.0 || ry == 0.0) {
        arc.kind = EllipseArc::Kind::Line;
        return arc;
    }
    const double phi = degrees_to_radians(std::fmod(in.x_rotation_deg, 360.0));
    const double cs = std::cos(phi), sn = std::sin(phi);
    // F.6.5 step 1: the midpoint-relative start point in the ellipse's frame.
    const Vec2 h = (in.from - in.to) * 0.5;
    const Vec2 p{cs * h.x + sn * h.y, -sn * h.x + cs * h.y};
    // F.6.6: scale the radii up until the ellipse reaches both end points,
    // by sqrt(Lambda), Lambda = (x1'/rx)^2 + (y1'/ry)^2. Taken as a hypotenuse
    // of ratios so that radii far larger or smaller than the end points'
    // distance neither overflow nor underflow (1e-300 radii squared are 0).
    const double root_lambda = std::hypot(p.x / rx, p.y / ry);
    if (root_lambda > 1.0) {
        rx *= root_lambda;
        ry *= root_lambda;
    }
    // F.6.5 step 2: the centre in that frame. Its coefficient
    //   sqrt((rx^2 ry^2 - rx^2 y1'^2 - ry^2 x1'^2) / (rx^2 y1'^2 + ry^2 x1'^2))
    // is, divided through by rx^2 ry^2, sqrt(1 / Lambda - 1): zero once the
    // radii were scaled up (the centre is the chord's midpoint).
    double coef = root_lambda >= 1.0 ? 0.0 : std::sqrt(1.0 / (root_lambda * root_lambda) - 1.0);
    if (in.large_arc == in.sweep) coef = -coef;
    const Vec2 c{coef * rx * p.y / ry, -coef * ry * p.x / rx};
    // Step 3: back to user space.
    const Point mid = lerp(in.from, in.to, 0.5);
    arc.center = mid + Vec2{cs * c.x - sn * c.y, sn * c.x + cs * c.y};
    // Step 4: start angle and sweep.
    const Vec2 u{(p.x - c.x) / rx, (p.y - c.y) / ry}, v{(-p.x - c.x) / rx, (-p.y - c.y) / ry};
    arc.theta1 = angle_between({1, 0}, u);
    double dtheta = angle_between(u, v);
    if (!in.sweep && dtheta > 0) dtheta -= 2 * std::numbers::pi;
    if (in.sweep && dtheta < 0) dtheta += 2 * std::numbers::pi;
    arc.dtheta = dtheta;
    arc.radii = {rx, ry};
    arc.x_rotation = phi;
    return arc;
}

namespace {

// Maps each unit-circle piece made by `make(a0, a1)` through the ellipse's map,
// then pins the first start and the last end to the exact input end points.
template <class Piece, class Make, class Pin>
int arc_pieces(const SvgArcInput& in, std::array<Piece, 4>& out, Make make, Pin pin) {
    const EllipseArc arc = svg_arc(in);
    if (arc.kind != EllipseArc::Kind::Arc) return 0;
    const int n = piece_count(arc.dtheta);
    const Affine m = arc.unit_circle_map();
    const double step = arc.dtheta / n;
    for (int i = 0; i < n; ++i) {
        const double a0 = arc.theta1 + step * i;
        out[i] = make(a0, a0 + step).transformed(m);
    }
    pin(out[0], out[n - 1]);
    return n;
}

} // namespace

int svg_arc_to_conics(const SvgArcInput& in, std::array<Conic, 4>& out) {
    return arc_pieces(
        in, out,
        [](double a0, double a1) {
            return Conic::circular_arc({0, 0}, 1.0, a0, a1);
        },
        [&](Conic& first, Conic& last) { first.p0 = in.from, last.p2 = in.to; });
}

int svg_arc_to_cubics(const SvgArcInput& in, std::array<CubicBez, 4>& out) {
    return arc_pieces(
        in, out,
        [](double a0, double a1) {
            const double k = 4.0 / 3.0 * std::tan((a1 - a0) / 4.0);
            const Point s{std::cos(a0), std::sin(a0)}, e{std::cos(a1), std::sin(a1)};
            return CubicBez{s, s + Vec2{-s.y, s.x} * k, e - Vec2{-e.y, e.x} * k, e};
        },
        [&](CubicBez& first, CubicBez& last) { first.p[0] = in.from, last.p[3] = in.to; });
}

} // namespace casteljau
