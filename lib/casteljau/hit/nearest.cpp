#include "casteljau/hit/nearest.h"

#include "casteljau/hit/bernstein_poly.h"

namespace casteljau {

NearestPoint nearest_point(const Segment& s, Point q) {
    const HomogeneousSegment h = HomogeneousSegment::from(s, q);
    const BernsteinPoly dw = derivative(h.w);
    const BernsteinPoly dx = derivative(h.x) * h.w - h.x * dw;
    const BernsteinPoly dy = derivative(h.y) * h.w - h.y * dw;
    const BernsteinPoly g = h.x * dx + h.y * dy;
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
