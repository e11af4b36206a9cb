// Fuzz target: SVG path data (curve/path_data.h). Whatever the parser
// accepts must be finite (overflowing numbers and relative coordinates that
// add up past the double range are errors, never infinities in the path),
// and the error offset must lie inside the input. Then the hit tests (hit/,
// root finding by roots.h) on the path and its box: they end, and within
// doubles' range the nearest point is no farther than the path's start (a
// candidate) and the box meets the outline.
#include "casteljau/curve/path_data.h"
#include "casteljau/hit/nearest.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/winding.h"
#include "fuzz_target.h"

#include <cmath>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    const PathDataResult r = parse_path_data({reinterpret_cast<const char*>(data), size});
    if (r.error && r.error->offset > size) std::abort();
    if (r.path.empty()) return 0;
    const Rect hull = r.path.control_bounds();
    const Rect tight = r.path.bounds();
    for (const double v :
         {hull.x0, hull.y0, hull.x1, hull.y1, tight.x0, tight.y0, tight.x1, tight.y1})
        if (!std::isfinite(v)) std::abort();
    const Point mid{0.5 * hull.x0 + 0.5 * hull.x1, 0.5 * hull.y0 + 0.5 * hull.y1};
    (void)winding_number(r.path, mid);
    (void)fill_intersects_rect(r.path, hull.inflated(1), FillRule::EvenOdd);
    // Coordinates below 1e100: distances and areas stay finite.
    if (!(std::fmax(std::fabs(hull.x0), std::fabs(hull.x1)) < 1e100 &&
          std::fmax(std::fabs(hull.y0), std::fabs(hull.y1)) < 1e100))
        return 0;
    const PathNearestPoint n = nearest_point(r.path, mid);
    for (const Subpath& sp : r.path.subpaths()) {
        if (sp.segments.empty()) continue; // a lone move_to is no candidate
        if (!(n.nearest.distance <= distance(sp.start, mid) * (1 + 1e-9) + 1e-9)) std::abort();
        if (!outline_intersects_rect(r.path, hull.inflated(1))) std::abort();
        break;
    }
    return 0;
}
