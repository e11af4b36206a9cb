#include "casteljau/hit/nearest.h"

#include "casteljau/hit/bernstein_poly.h"

#include <algorithm>

namespace casteljau {

NearestPoint nearest_point(const Segment& s, Point q) {
    const HomogeneousSegment h = HomogeneousSegment::from(s, q);
    // The nearest points are where (X, Y) / W - q is normal to the curve:
    // g = X (X' W - X W') + Y (Y' W - Y W') = 0 (times W^3 > 0). With every
    // weight 1 (lines, quadratics, cubics) W = 1 and g = X X' + Y Y', of
    // degree 2n - 1 instead of the general 3n - 1: a cubic's quintic costs
    // half the root finding of its degree-elevated octic.
    const auto w = h.w.coefficients();
    const bool polynomial = std::all_of(w.begin(), w.end(), [](double v) { return v == 1.0; });
    BernsteinPoly g;
    if (polynomial) {
        g = h.x * derivative(h.x) + h.y * derivative(h.y);
    } else {
        const BernsteinPoly dw = derivative(h.w);
        g = h.x * (derivative(h.x) * h.w - h.x * dw) + h.y * (derivative(h.y) * h.w - h.y * dw);
    }
    std::array<double, BernsteinPoly::kMaxDegree> roots{};
    const int k = roots_in_unit_interval(g, roots);
    NearestPoint best;
    const auto consider = [&](double t) {
        const Point p = segment_eval(s, t);
        const double d = distance(p, q);
        if (d < best.distance) best = {t, p, d};
    };
    consider(0.0);
    consider(1.0);
    for (int i = 0; i < k; ++i) consider(roots[i]);
    return best;
}

PathNearestPoint nearest_point(const Path& path, Point q) {
    PathNearestPoint best;
    const auto& subpaths = path.subpaths();
    for (std::size_t i = 0; i < subpaths.size(); ++i)
        for (std::size_t j = 0; j < subpaths[i].segments.size(); ++j) {
            const NearestPoint n = nearest_point(subpaths[i].segments[j], q);
            if (n.distance < best.nearest.distance) best = {i, j, n};
        }
    return best;
}

} // namespace casteljau
