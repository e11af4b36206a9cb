#include "casteljau/hit/stroke_hit.h"

#include "casteljau/hit/winding.h"
#include "casteljau/stroke/stroker.h"

#include <algorithm>
#include <limits>

namespace casteljau {

Path stroke_outline_path(const Path& path, const StrokeGeometry& style, double tolerance) {
    Stroker stroker;
    Path out;
    for (const Polygon& poly : stroker.outline(path, style, tolerance)) {
        if (poly.empty()) continue;
        out.move_to(poly[0]);
        for (std::size_t i = 1; i < poly.size(); ++i) out.line_to(poly[i]);
        out.close();
    }
    return out;
}

namespace {

// Signed crossings of the edge a -> b with the ray from p towards +x, by
// winding.h's rule (a point on the ray's line counts as above it), in closed
// form: the outline is thousands of lines, which the curves' general test
// took 40% of a query to count.
int edge_crossing(Point a, Point b, Point p) {
    const bool a_above = a.y >= p.y, b_above = b.y >= p.y;
    if (a_above == b_above) return 0;
    const double x = a.x + (p.y - a.y) * ((b.x - a.x) / (b.y - a.y));
    return x > p.x ? (b_above ? 1 : -1) : 0;
}

} // namespace

double stroke_distance(const Path& path, const StrokeGeometry& style, Point p, double tolerance) {
    // The outline's polygons as they are, not as a Path (building one was
    // another 30%, its allocations most of it).
    Stroker stroker;
    int winding = 0;
    double best = std::numeric_limits<double>::infinity();
    for (const Polygon& poly : stroker.outline(path, style, tolerance))
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const Point a = poly[i], b = poly[i + 1 < poly.size() ? i + 1 : 0];
            winding += edge_crossing(a, b, p);
            best = std::min(best, distance_to_segment(p, a, b));
        }
    return winding != 0 ? 0.0 : best;
}

Rect stroke_bounds(const Path& path, const StrokeGeometry& style, double tolerance) {
    // Lines only: the control bounds are the vertices' box.
    const Rect r = stroke_outline_path(path, style, tolerance).control_bounds();
    return r.is_empty() ? r : r.inflated(tolerance);
}

} // namespace casteljau
