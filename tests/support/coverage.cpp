#include "coverage.h"

#include <algorithm>
#include <cmath>

namespace casteljau::testing {

std::vector<float> supersampled_coverage(const std::vector<Polygon>& polys, FillRule rule, int w,
                                         int h, int samples) {
    std::vector<double> count(std::size_t(w * h), 0.0);
    std::vector<std::pair<double, int>> xs;
    const double s = samples;
    for (int sy = 0; sy < h * samples; ++sy) {
        const double yc = (sy + 0.5) / s;
        xs.clear();
        for (const Polygon& p : polys)
            for (std::size_t i = 0; i < p.size(); ++i) {
                const Point a = p[i], b = p[(i + 1) % p.size()];
                if ((a.y <= yc) == (b.y <= yc)) continue;
                xs.push_back({a.x + (b.x - a.x) * (yc - a.y) / (b.y - a.y), a.y < b.y ? 1 : -1});
            }
        std::sort(xs.begin(), xs.end());
        int winding = 0;
        const int row = sy / samples;
        for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
            winding += xs[i].second;
            const bool inside = rule == FillRule::NonZero ? winding != 0 : (winding & 1) != 0;
            if (!inside) continue;
            const double x0 = std::clamp(xs[i].first, 0.0, double(w)),
                         x1 = std::clamp(xs[i + 1].first, 0.0, double(w));
            // Sample k of the row sits at (k + 1/2) / s; those in [x0, x1):
            const auto first_at_or_after = [&](double x) { return std::ceil(x * s - 0.5); };
            for (int px = int(x0); px < w && px < x1; ++px) {
                const double lo = std::max(x0, double(px)), hi = std::min(x1, double(px + 1));
                if (hi > lo)
                    count[std::size_t(row * w + px)] +=
                        first_at_or_after(hi) - first_at_or_after(lo);
            }
        }
    }
    std::vector<float> cov(count.size());
    for (std::size_t i = 0; i < cov.size(); ++i) cov[i] = float(count[i] / (s * s));
    return cov;
}

void CoverageImage::span(const Span& s) {
    if (s.y < last_y_ || (s.y == last_y_ && s.x < last_end_) || s.x < 0 || s.x + s.len > w_ ||
        s.y >= h_)
        order_ok_ = false;
    if (s.y != last_y_) last_end_ = 0;
    last_y_ = s.y;
    last_end_ = s.x + s.len;
    for (int i = 0; i < s.len; ++i) {
        const float c = s.at(i);
        if (!(c >= 0.0f && c <= 1.0f)) order_ok_ = false;
        if (s.x + i >= 0 && s.x + i < w_ && s.y >= 0 && s.y < h_)
            cov_[std::size_t(s.y * w_ + s.x + i)] = c;
    }
}

} // namespace casteljau::testing
