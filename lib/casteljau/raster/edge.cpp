#include "casteljau/raster/edge.h"

#include "casteljau/geom/line_clip.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

void EdgeList::reset(PixelRect clip, int row_begin, int row_end) {
    edges_.clear();
    clip_ = clip;
    row_begin_ = std::max(row_begin, clip.y0);
    row_end_ = std::min(row_end, clip.y1);
}

void EdgeList::add_clipped(Point a, Point b, float dir) {
    const double top = clip_.y0, bottom = clip_.y1, left = clip_.x0, right = clip_.x1;
    // y clip: nothing outside [y0, y1] covers a row.
    // Interpolation that stays finite for any finite end points, up to 1e308,
    // where a plain difference of two coordinates overflows (and inf * 0 is
    // NaN): crossing_parameter (line_clip.h), and p + (q - p) r, or
    // (1 - r) p + r q where q - p overflows.
    const auto mix = [](double p, double q, double r) {
        const double d = q - p;
        return std::isfinite(d) ? p + d * r : (1.0 - r) * p + r * q;
    };
    const auto x_at = [&](double y) { return mix(a.x, b.x, crossing_parameter(y, a.y, b.y)); };
    if (a.y < top) a = {x_at(top), top};
    if (b.y > bottom) b = {x_at(bottom), bottom};
    // x clip: split at the borders, then clamp (the clamped parts are vertical).
    // Breakpoints in y: the ends and where the segment crosses the borders.
    double ys[4] = {a.y, 0, 0, 0};
    int n = 1;
    for (double border : {left, right}) {
        if ((a.x < border) != (b.x < border) && a.x != b.x) {
            const double y = mix(a.y, b.y, crossing_parameter(border, a.x, b.x));
            if (y > a.y && y < b.y) ys[n++] = y;
        }
    }
    if (n == 3 && ys[1] > ys[2]) std::swap(ys[1], ys[2]);
    ys[n++] = b.y;
    const auto x_on = [&](double y) {
        const double x = y == a.y ? a.x : (y == b.y ? b.x : x_at(y));
        return std::clamp(x, left, right);
    };
    for (int i = 0; i + 1 < n; ++i)
        if (ys[i] < ys[i + 1]) push(x_on(ys[i]), ys[i], x_on(ys[i + 1]), ys[i + 1], dir);
}

} // namespace casteljau
