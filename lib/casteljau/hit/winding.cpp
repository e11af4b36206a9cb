#include "casteljau/hit/winding.h"

#include "casteljau/curve/roots.h"
#include "casteljau/hit/bernstein_poly.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

// The sign with sgn(0) = +1: a point on the ray's line counts as above it.
bool above(double v) { return v >= 0.0; }

} // namespace

int segment_crossings(const Segment& s, Point p) {
    const HomogeneousSegment h = HomogeneousSegment::from(s, p);
    const BernsteinPoly f = h.y_minus(0.0);
    const auto coef = f.coefficients();
    const bool all_above = std::all_of(coef.begin(), coef.end(), above);
    const bool all_below = std::none_of(coef.begin(), coef.end(), above);
    const auto xs = h.x.coefficients();
    // x_i w_i <= 0 for every control point: the curve never gets right of p.
    if (all_above || all_below ||
        std::all_of(xs.begin(), xs.end(), [](double x) { return x <= 0; }))
        return 0;
    // Wholly right of p (x_i w_i > 0): every sign change of f counts, and
    // their sum, +1 up and -1 down in turn, telescopes to the ends' difference.
    if (std::all_of(xs.begin(), xs.end(), [](double x) { return x > 0; }))
        return int(above(coef.back())) - int(above(coef.front()));
    // Samples: both ends and the middles between consecutive roots; f keeps
    // its sign between two samples except across one root or at an end.
    std::array<double, BernsteinPoly::kMaxDegree> roots{};
    const int k = roots_in_unit_interval(f, roots);
    std::array<double, BernsteinPoly::kMaxDegree + 3> t{};
    int n = 0;
    t[n++] = 0.0;
    double prev = 0.0;
    for (int i = 0; i < k; ++i) t[n++] = 0.5 * (prev + roots[i]), prev = roots[i];
    t[n++] = 0.5 * (prev + 1.0);
    t[n++] = 1.0;
    int winding = 0;
    // Exact end values: f(0) and f(1) are the end coefficients. A change of
    // sign between two samples is located to a double's resolution from the
    // samples' values (bracketed_root counts 0 as above, as above() does).
    double before = coef.front();
    for (int i = 1; i < n; ++i) {
        const double now = i == n - 1 ? coef.back() : f.eval(t[i]);
        if (above(now) != above(before)) {
            const double tc = bracketed_root([&](double u) { return f.eval(u); }, t[i - 1], t[i],
                                             before, now, 0.0);
            if (h.x.eval(tc) / h.w.eval(tc) > 0.0) winding += above(now) ? 1 : -1;
        }
        before = now;
    }
    return winding;
}

int winding_number(const Path& path, Point p) {
    int winding = 0;
    for (const Subpath& sp : path.subpaths()) {
        for (const Segment& s : sp.segments) winding += segment_crossings(s, p);
        if (const auto line = fill_closing_line(sp)) winding += segment_crossings(*line, p);
    }
    return winding;
}

bool fill_contains(const Path& path, Point p, FillRule rule) {
    const int w = winding_number(path, p);
    return rule == FillRule::NonZero ? w != 0 : (w & 1) != 0;
}

} // namespace casteljau
