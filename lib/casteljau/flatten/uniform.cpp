#include "casteljau/flatten/uniform.h"

#include "casteljau/flatten/error.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {
int clamp_count(double n) {
    if (!(n < double(kMaxUniformSegments))) return kMaxUniformSegments;
    return std::max(1, int(std::ceil(n)));
}
} // namespace

int wang_segments(std::span<const Point> control, double tolerance) noexcept {
    const std::size_t n = control.size();
    if (n < 3) return 1;
    double m = 0;
    for (std::size_t i = 0; i + 2 < n; ++i) {
        const Vec2 dd = (control[i + 2] - control[i + 1]) - (control[i + 1] - control[i]);
        m = std::max(m, dd.length());
    }
    const double d = double(n - 1);
    return clamp_count(std::sqrt(d * (d - 1) / 8.0 * m / tolerance));
}

int wang_segments(const Conic& c, double tolerance) noexcept {
    const Rect box = Rect::from_points(c.p0, c.p2).united(c.p1);
    const Point centre = lerp(box.min(), box.max(), 0.5);
    const Vec2 q0 = c.p0 - centre, q1 = c.p1 - centre, q2 = c.p2 - centre;
    const double r = std::sqrt(std::max({q0.length_sq(), q1.length_sq(), q2.length_sq()}));
    const Vec2 dp = q0 - q1 * (2 * c.w) + q2;
    const double dw = std::fabs(2 - 2 * c.w);
    const double numer = dp.length() / tolerance + std::max(0.0, r / tolerance - 1) * dw;
    return clamp_count(std::sqrt(numer / (4 * std::min(c.w, 1.0))));
}

int wang_segments(const RationalBezier& c, double tolerance) {
    // Start the doubling search from the polynomial bound of the control polygon.
    std::array<Point, kMaxPoints> p;
    for (int i = 0; i <= c.degree; ++i) p[i] = c.control_point(i);
    const int guess =
        wang_segments(std::span<const Point>(p.data(), std::size_t(c.degree) + 1), tolerance);
    return best_uniform_segments(c, tolerance, guess);
}

} // namespace casteljau
