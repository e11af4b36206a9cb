#include "casteljau/hit/rect_hit.h"

#include "casteljau/hit/bernstein_poly.h"
#include "casteljau/hit/winding.h"

#include <algorithm>

namespace casteljau {

namespace {

bool inside(const Rect& outer, const Rect& inner) {
    return outer.x0 <= inner.x0 && inner.x1 <= outer.x1 && outer.y0 <= inner.y0 &&
           inner.y1 <= outer.y1;
}

// Whether the curve crosses the line {coordinate = c} at a point whose other
// coordinate lies in [lo, hi].
bool crosses_side(const Segment& s, const HomogeneousSegment& h, bool vertical_side, double c,
                  double lo, double hi) {
    const BernsteinPoly f = vertical_side ? h.x_minus(c) : h.y_minus(c);
    const auto coef = f.coefficients();
    if (std::all_of(coef.begin(), coef.end(), [](double v) { return v > 0; }) ||
        std::all_of(coef.begin(), coef.end(), [](double v) { return v < 0; }))
        return false;
    std::array<double, BernsteinPoly::kMaxDegree> roots{};
    const int k = roots_in_unit_interval(f, roots);
    for (int i = 0; i < k; ++i) {
        const Point p = segment_eval(s, roots[i]);
        const double other = vertical_side ? p.y : p.x;
        if (lo <= other && other <= hi) return true;
    }
    return false;
}

} // namespace

bool segment_intersects_rect(const Segment& s, const Rect& r) {
    if (r.is_empty()) return false;
    const Rect hull = segment_control_bounds(s);
    if (!r.intersects(hull)) return false;
    if (inside(r, hull) || r.contains(segment_start(s)) || r.contains(segment_end(s))) return true;
    const HomogeneousSegment h = HomogeneousSegment::from(s, Point{});
    return crosses_side(s, h, true, r.x0, r.y0, r.y1) ||
           crosses_side(s, h, true, r.x1, r.y0, r.y1) ||
           crosses_side(s, h, false, r.y0, r.x0, r.x1) ||
           crosses_side(s, h, false, r.y1, r.x0, r.x1);
}

bool outline_intersects_rect(const Path& path, const Rect& r) {
    for (const Subpath& sp : path.subpaths())
        for (const Segment& s : sp.segments)
            if (segment_intersects_rect(s, r)) return true;
    return false;
}

bool fill_intersects_rect(const Path& path, const Rect& r, FillRule rule) {
    if (r.is_empty()) return false;
    for (const Subpath& sp : path.subpaths()) {
        for (const Segment& s : sp.segments)
            if (segment_intersects_rect(s, r)) return true;
        const auto line = fill_closing_line(sp);
        if (line && segment_intersects_rect(*line, r)) return true;
    }
    // No boundary crosses the rectangle: it is wholly inside or wholly outside.
    return fill_contains(path, r.min(), rule);
}

} // namespace casteljau
