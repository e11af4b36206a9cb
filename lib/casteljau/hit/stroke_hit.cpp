#include "casteljau/hit/stroke_hit.h"

#include "casteljau/stroke/stroker.h"

#include <algorithm>
#include <limits>

namespace casteljau {

namespace {

// Signed crossings of the polygon edge a -> b with the ray from p towards +x,
// with the half-open rule (a vertex on the ray counts as above it).
int edge_crossing(Point a, Point b, Point p) {
    const bool a_above = a.y >= p.y, b_above = b.y >= p.y;
    if (a_above == b_above) return 0;
    const double x = a.x + (p.y - a.y) / (b.y - a.y) * (b.x - a.x);
    return x > p.x ? (b_above ? 1 : -1) : 0;
}

} // namespace

double stroke_distance(const Path& path, const StrokeGeometry& style, Point p, double tolerance) {
    std::vector<Polygon> outline;
    stroke_outline(path, style, tolerance, outline);
    int winding = 0;
    double best = std::numeric_limits<double>::infinity();
    for (const Polygon& poly : outline)
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Point a = poly[i], b = poly[(i + 1) % poly.size()];
            winding += edge_crossing(a, b, p);
            best = std::min(best, distance_to_segment(p, a, b));
        }
    return winding != 0 ? 0.0 : best;
}

Rect stroke_bounds(const Path& path, const StrokeGeometry& style, double tolerance) {
    std::vector<Polygon> outline;
    stroke_outline(path, style, tolerance, outline);
    Rect r = Rect::empty();
    for (const Polygon& poly : outline)
        for (Point q : poly) r = r.united(q);
    return r.is_empty() ? r : r.inflated(tolerance);
}

} // namespace casteljau
