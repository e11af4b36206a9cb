// The exact error measure: how far a curve is from the polyline a flattener
// made of it. Used by the tests, the benchmarks and `--stats`; it is
// deliberately independent of the flatness bounds it checks.
//
// For a polyline whose vertices sit on the curve at parameters
// 0 = t_0 < ... < t_n = 1, the error is
//   max_i max_{t in [t_i, t_{i+1}]} dist(C(t), [V_i, V_{i+1}]),
// each curve piece measured against its own chord (so a polyline that passes
// near the curve elsewhere gets no credit). Each piece is sampled at
// kErrorSamples + 1 evenly spaced parameters, and the best sample is refined by
// golden-section search on its two neighbouring intervals: the distance is a
// smooth function of t with at most a few local maxima on a piece that is
// anywhere near flat, so the refined value is the true maximum to ~1e-12
// relative (the tests check it against closed forms).
#pragma once

#include "casteljau/flatten/vertex.h"

#include <algorithm>
#include <cmath>
#include <span>
#include <vector>

namespace casteljau {

inline constexpr int kErrorSamples = 32;

template <class Curve>
double piece_error(const Curve& c, double ta, double tb, Point a, Point b) {
    const auto dist = [&](double t) { return distance_to_segment(c.eval(t), a, b); };
    const double h = (tb - ta) / kErrorSamples;
    int best = 0;
    double best_d = -1;
    for (int i = 0; i <= kErrorSamples; ++i) {
        const double d = dist(ta + h * i);
        if (d > best_d) best_d = d, best = i;
    }
    // Golden-section search for the maximum on the bracket around the sample.
    double lo = ta + h * std::max(best - 1, 0), hi = ta + h * std::min(best + 1, kErrorSamples);
    constexpr double g = 0.6180339887498949; // (sqrt(5) - 1) / 2
    double x1 = hi - g * (hi - lo), x2 = lo + g * (hi - lo);
    double f1 = dist(x1), f2 = dist(x2);
    for (int it = 0; it < 60 && hi - lo > 1e-15; ++it) {
        if (f1 < f2) {
            lo = x1, x1 = x2, f1 = f2;
            x2 = lo + g * (hi - lo), f2 = dist(x2);
        } else {
            hi = x2, x2 = x1, f2 = f1;
            x1 = hi - g * (hi - lo), f1 = dist(x1);
        }
    }
    return std::max({best_d, f1, f2});
}

/// `start` is the curve's start; `vertices` what a flattener emitted after it.
template <class Curve>
double polyline_error(const Curve& c, Point start, std::span<const FlatVertex> vertices) {
    double err = 0, ta = 0;
    Point a = start;
    for (const FlatVertex& v : vertices) {
        err = std::max(err, piece_error(c, ta, v.t, a, v.p));
        ta = v.t;
        a = v.p;
    }
    return err;
}

template <class Curve>
double uniform_error(const Curve& c, int n) {
    std::vector<FlatVertex> v;
    v.reserve(std::size_t(n));
    for (int i = 1; i <= n; ++i) {
        const double t = double(i) / n;
        v.push_back({i == n ? c.end() : c.eval(t), t});
    }
    return polyline_error(c, c.start(), v);
}

/// The smallest N whose uniform polyline measures within `tolerance`, searched
/// below `upper` (which must meet it: Wang's bound does). Measured error is
/// decreasing in N for all but pathological curves; bisection assumes it.
template <class Curve>
int best_uniform_segments(const Curve& c, double tolerance, int upper) {
    int lo = 0, hi = std::max(upper, 1); // err(lo) > tol (or lo == 0), err(hi) <= tol
    while (uniform_error(c, hi) > tolerance && hi < (1 << 20)) lo = hi, hi *= 2;
    while (hi - lo > 1) {
        const int mid = lo + (hi - lo) / 2;
        (uniform_error(c, mid) <= tolerance ? hi : lo) = mid;
    }
    return hi;
}

} // namespace casteljau
