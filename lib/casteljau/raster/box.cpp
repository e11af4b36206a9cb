#include "casteljau/raster/box.h"

#include "casteljau/raster/sweep.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

// The coverage of one row's pixels: the partial columns at both ends of the
// rectangle and the constant run between them. Columns are absolute.
struct BoxRow {
    int left, right;        // the partial columns: left, and right (right > left)
    float left_cover;       // horizontal overlap of the left partial column
    float right_cover;      // ... of the right one (0: the rectangle ends on its border)
    int run_begin, run_end; // the fully covered columns [run_begin, run_end)
};

// Columns of the rectangle [xl, xr], xl < xr. A side on a column border
// covers its column whole, and joins the run.
BoxRow columns(float xl, float xr) {
    const int i = int(std::floor(xl)), j = int(std::floor(xr));
    if (i == j) return {i, i + 1, xr - xl, 0.0f, i + 1, i + 1};
    BoxRow r{i, j, float(i + 1) - xl, xr - float(j), i + 1, j};
    if (r.left_cover == 1.0f) r.run_begin = i;
    return r;
}

// Emits one pixel of coverage c, if visible.
void pixel(SpanSink& sink, int y, int x, float c) {
    if (c >= kInvisible) sink.span({y, x, 1, &c, 0.0f});
}

} // namespace

bool fill_box(const EdgeList& edges, SpanSink& sink) {
    const std::vector<Edge>& list = edges.edges();
    if (list.size() != 2) return false;
    const Edge& a = list[0];
    const Edge& b = list[1];
    if (a.x0 != a.x1 || b.x0 != b.x1 || a.y0 != b.y0 || a.y1 != b.y1 || a.dir != -b.dir)
        return false;
    const float xl = std::min(a.x0, b.x0), xr = std::max(a.x0, b.x0);
    if (!(xl < xr)) return true; // no area
    const BoxRow row = columns(xl, xr);
    const int y_begin = std::max(edges.row_begin(), int(a.y0));
    const int y_end = std::min(edges.row_end(), int(std::ceil(a.y1)));
    for (int y = y_begin; y < y_end; ++y) {
        const float v = std::min(a.y1, float(y + 1)) - std::max(a.y0, float(y));
        if (row.run_begin > row.left) pixel(sink, y, row.left, row.left_cover * v);
        if (row.run_begin < row.run_end && v >= kInvisible)
            sink.span({y, row.run_begin, row.run_end - row.run_begin, nullptr, v});
        pixel(sink, y, row.right, row.right_cover * v);
    }
    return true;
}

} // namespace casteljau
