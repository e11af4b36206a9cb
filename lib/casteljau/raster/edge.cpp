#include "casteljau/raster/edge.h"

#include <algorithm>

namespace casteljau {

void EdgeList::reset(int width, int height) {
    edges_.clear();
    w_ = width;
    h_ = height;
}

void EdgeList::add_line(Point a, Point b) {
    if (a.y == b.y) return;
    const float dir = a.y < b.y ? 1.0f : -1.0f;
    if (a.y > b.y) std::swap(a, b);
    // y clip: nothing outside [0, H] covers a row.
    const double h = h_;
    if (b.y <= 0 || a.y >= h) return;
    const auto x_at = [&](double y) { return a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y)); };
    if (a.y < 0) a = {x_at(0), 0};
    if (b.y > h) b = {x_at(h), h};
    // x clip: split at the borders, then clamp (the clamped parts are vertical).
    const double w = w_;
    // Breakpoints in y: the ends and where the segment crosses x = 0 and x = W.
    double ys[4] = {a.y, 0, 0, 0};
    int n = 1;
    for (double border : {0.0, w}) {
        if ((a.x < border) != (b.x < border) && a.x != b.x) {
            const double y = a.y + (b.y - a.y) * ((border - a.x) / (b.x - a.x));
            if (y > a.y && y < b.y) ys[n++] = y;
        }
    }
    if (n == 3 && ys[1] > ys[2]) std::swap(ys[1], ys[2]);
    ys[n++] = b.y;
    const auto x_on = [&](double y) {
        const double x =
            y == a.y ? a.x : (y == b.y ? b.x : a.x + (b.x - a.x) * ((y - a.y) / (b.y - a.y)));
        return std::clamp(x, 0.0, w);
    };
    for (int i = 0; i + 1 < n; ++i)
        if (ys[i] < ys[i + 1]) push(x_on(ys[i]), ys[i], x_on(ys[i + 1]), ys[i + 1], dir);
}

void EdgeList::push(double x0, double y0, double x1, double y1, float dir) {
    const float fy0 = float(y0), fy1 = float(y1);
    if (fy0 < fy1) edges_.push_back({float(x0), fy0, float(x1), fy1, dir});
}

} // namespace casteljau
