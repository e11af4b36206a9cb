#include "check.h"

#include <algorithm>

namespace casteljau::testing {

std::vector<Point> convex_hull(std::vector<Point> pts) {
    std::sort(pts.begin(), pts.end(),
              [](Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    if (pts.size() < 3) return pts;
    std::vector<Point> h(2 * pts.size());
    std::size_t k = 0;
    const auto turn = [](Point o, Point a, Point b) { return (a - o).cross(b - o); };
    for (std::size_t i = 0; i < pts.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], pts[i]) <= 0) --k;
        h[k++] = pts[i];
    }
    for (std::size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && turn(h[k - 2], h[k - 1], pts[i - 1]) <= 0) --k;
        h[k++] = pts[i - 1];
    }
    h.resize(k - 1);
    return h;
}

double distance_outside(std::span<const Point> hull, Point p) {
    if (hull.size() == 1) return distance(hull[0], p);
    bool inside = hull.size() >= 3;
    double best = 1e300;
    for (std::size_t i = 0; i < hull.size(); ++i) {
        const Point a = hull[i], b = hull[(i + 1) % hull.size()];
        if ((b - a).cross(p - a) < 0) inside = false;
        best = std::min(best, distance_to_segment(p, a, b));
    }
    return inside ? 0.0 : best;
}

} // namespace casteljau::testing
