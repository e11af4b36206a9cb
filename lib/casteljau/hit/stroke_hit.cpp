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

double stroke_distance(const Path& path, const StrokeGeometry& style, Point p, double tolerance) {
    const Path outline = stroke_outline_path(path, style, tolerance);
    if (fill_contains(outline, p, FillRule::NonZero)) return 0.0;
    double best = std::numeric_limits<double>::infinity();
    for (const Subpath& sp : outline.subpaths())
        for (const Segment& s : sp.segments) {
            const Line& l = std::get<Line>(s);
            best = std::min(best, distance_to_segment(p, l.start(), l.end()));
        }
    return best;
}

Rect stroke_bounds(const Path& path, const StrokeGeometry& style, double tolerance) {
    // Lines only: the control bounds are the vertices' box.
    const Rect r = stroke_outline_path(path, style, tolerance).control_bounds();
    return r.is_empty() ? r : r.inflated(tolerance);
}

} // namespace casteljau
