#include "corpus.h"

#include <cmath>
#include <functional>
#include <numbers>

namespace casteljau::testing {

double Rng::log_uniform(double lo, double hi) {
    return std::exp(uniform(std::log(lo), std::log(hi)));
}

QuadBez random_quad(Rng& rng, double extent) {
    return {{rng.point(extent), rng.point(extent), rng.point(extent)}};
}

CubicBez random_cubic(Rng& rng, double extent) {
    return {{rng.point(extent), rng.point(extent), rng.point(extent), rng.point(extent)}};
}

Conic random_conic(Rng& rng, double extent) {
    return {rng.point(extent), rng.point(extent), rng.point(extent), rng.log_uniform(0.05, 20)};
}

Path random_blob(Rng& rng, double extent, int segments) {
    Path p;
    p.move_to(rng.point(extent));
    for (int i = 0; i < segments; ++i) {
        switch (rng.integer(0, 3)) {
        case 0:
            p.line_to(rng.point(extent));
            break;
        case 1:
            p.quad_to(rng.point(extent), rng.point(extent));
            break;
        case 2:
            p.cubic_to(rng.point(extent), rng.point(extent), rng.point(extent));
            break;
        default:
            p.conic_to(rng.point(extent), rng.point(extent), rng.log_uniform(0.1, 10));
            break;
        }
    }
    p.close();
    return p;
}

Bezier random_bezier(Rng& rng, int degree, double extent) {
    Bezier b;
    b.degree = degree;
    for (int i = 0; i <= degree; ++i) b.p[i] = rng.point(extent);
    return b;
}

namespace {

// A placed copy of a unit-size shape: random size, rotation and offset.
CubicBez place(Rng& rng, std::array<Point, 4> unit, double lo, double hi) {
    const double size = rng.log_uniform(lo, hi);
    const Affine m = Affine::translate({rng.uniform(0, 500), rng.uniform(0, 500)}) *
                     Affine::rotate(rng.uniform(0, 2 * std::numbers::pi)) * Affine::scale(size);
    return CubicBez{unit}.transformed(m);
}

} // namespace

std::vector<NamedCubic> cubic_corpus(unsigned seed, int per_kind) {
    Rng rng(seed);
    std::vector<NamedCubic> out;
    const double k = 4.0 / 3.0 * std::tan(std::numbers::pi / 8); // quarter-circle handle
    for (int i = 0; i < per_kind; ++i) {
        const double j = rng.uniform(-0.3, 0.3); // jitter of the shapes' inner points
        out.push_back({"random", random_cubic(rng, rng.log_uniform(50, 800))});
        out.push_back({"quarter_circle", place(rng, {{{1, 0}, {1, k}, {k, 1}, {0, 1}}}, 50, 800)});
        out.push_back(
            {"s_curve", place(rng, {{{0, 0}, {0.5, 0.6 + j}, {0.5, -0.6 + j}, {1, 0}}}, 50, 800)});
        out.push_back({"loop", place(rng, {{{0, 0}, {1.2 + j, 1}, {-0.2, 1}, {1, 0}}}, 50, 800)});
        out.push_back({"near_cusp",
                       place(rng, {{{0, 0}, {1, 1}, {0, 1 + 0.01 * j}, {1, 0.02 * j}}}, 50, 800)});
        out.push_back(
            {"nearly_straight",
             place(rng, {{{0, 0}, {0.3, 0.01 + 0.01 * j}, {0.7, -0.01}, {1, 0.005}}}, 200, 2000)});
    }
    return out;
}

double optimal_segments(const CubicBez& c, double tolerance) {
    // sqrt(kappa / (8 tol)) ds = sqrt(|B' x B''| / |B'|^3 / (8 tol)) |B'| dt.
    const auto f = [&](double t) {
        const Vec2 d1 = c.deriv(t), d2 = c.deriv2(t);
        const double speed = d1.length();
        if (speed == 0.0) return 0.0;
        return std::sqrt(std::fabs(d1.cross(d2)) / (speed * speed * speed) / (8 * tolerance)) *
               speed;
    };
    const auto simpson = [&](double a, double b, double fa, double fm, double fb) {
        return (b - a) / 6 * (fa + 4 * fm + fb);
    };
    std::function<double(double, double, double, double, double, double, int)> rec =
        [&](double a, double b, double fa, double fm, double fb, double whole, int depth) {
            const double m = 0.5 * (a + b), lm = 0.5 * (a + m), rm = 0.5 * (m + b);
            const double flm = f(lm), frm = f(rm);
            const double left = simpson(a, m, fa, flm, fm), right = simpson(m, b, fm, frm, fb);
            if (depth > 30 || std::fabs(left + right - whole) < 1e-9)
                return left + right + (left + right - whole) / 15;
            return rec(a, m, fa, flm, fm, left, depth + 1) +
                   rec(m, b, fm, frm, fb, right, depth + 1);
        };
    const double fa = f(0), fm = f(0.5), fb = f(1);
    return rec(0, 1, fa, fm, fb, simpson(0, 1, fa, fm, fb), 0);
}

} // namespace casteljau::testing
