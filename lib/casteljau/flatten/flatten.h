// One entry point for every flattening method and curve type, as the path
// flattener, the CLI and the benchmarks choose them at run time.
#pragma once

#include "casteljau/flatten/adaptive.h"
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/guided.h"
#include "casteljau/flatten/halving.h"
#include "casteljau/flatten/integral.h"
#include "casteljau/flatten/uniform.h"
#include "casteljau/geom/fixed_stack.h"

#include <array>
#include <string>
#include <unordered_map>

namespace casteljau {

enum class FlattenMethod {
    Adaptive, ///< greedy flat prefixes (adaptive.h): near the fewest segments, slow
    Uniform,  ///< N segments in advance (uniform.h)
    Halving,  ///< textbook midpoint subdivision (halving.h): a baseline
    Guided,   ///< cut into the predicted number of pieces (guided.h): fast, 1.3x the optimal count
    /// Uniform with, per curve, the smallest N whose measured error meets the
    /// tolerance (error.h): uniform sampling at its best, for comparisons at
    /// equal error. The first time a curve is seen it measures candidate N;
    /// after that the N is remembered (memoized_best_uniform below).
    UniformBest,
    /// Evenly spaced in the integral of the segment density, every chord
    /// checked (integral.h): near the optimal count, at 0.4x guided's speed.
    /// Not the default: at the same tolerance its chords stand nearer the
    /// bound all along, and the picture moves away from the exact one
    /// (bench/README.md: the tiger's mean difference to rsvg-convert grows
    /// from 1.98/255 to 2.71/255).
    Integral,
};

/// How to flatten: the tolerance, the method, and a segment count for uniform sampling.
struct FlattenOptions {
    double tolerance = 0.25; ///< device pixels; > 0
    FlattenMethod method = FlattenMethod::Guided;
    int segments = 0; ///< Uniform only: N per curve; 0 = the smallest that Wang's bound allows
};

/// The form a curve is subdivided in: itself, except conics, which subdivide in
/// homogeneous form so that the reported parameters stay the conic's own.
template <class Curve>
const Curve& subdivision_form(const Curve& c) {
    return c;
}
inline HConic subdivision_form(const Conic& c) { return HConic::from(c); }

/// Depth of the culling subdivision that fills (raster/path_edges.h) and
/// strokes (stroke/stroker.cpp) do before flattening only what is near the
/// image: 2^-40 of a 1e9 px curve is ~1e-3 px, so deeper never helps, and a
/// piece still over 4 image sizes at this depth is taken as its chord.
inline constexpr int kCullDepth = 40;

/// The culling walk: halves `curve` depth first, calling visit(piece, depth)
/// on each piece from the start of the curve to its end; a piece is halved
/// when visit returns true and depth < kCullDepth (at the cap, visit must
/// take the piece whole).
template <class Curve, class Visit>
void cull_walk(const Curve& curve, Visit&& visit) noexcept {
    struct Piece {
        Curve c;
        int depth;
    };
    FixedStack<Piece, kCullDepth + 1> stack;
    stack.push({curve, 0});
    while (!stack.empty()) {
        const Piece p = stack.pop();
        if (!visit(p.c, p.depth) || p.depth == kCullDepth) continue;
        const auto halves = p.c.split(0.5);
        stack.push({halves[1], p.depth + 1});
        stack.push({halves[0], p.depth + 1});
    }
}

/// UniformBest's N per curve, memoized per thread (keyed by the curve's exact
/// control points and the tolerance), so that repeated renders for a
/// comparison time the sampling, not the search. A comparison tool: the memo
/// is dropped whole once it holds kUniformMemoSize curves.
inline constexpr std::size_t kUniformMemoSize = 1 << 20;

template <class Curve>
int memoized_best_uniform(const Curve& c, double tolerance) {
    thread_local std::unordered_map<std::string, int> memo;
    std::string key(reinterpret_cast<const char*>(&tolerance), sizeof tolerance);
    const auto add = [&key](const auto& points) {
        key.append(reinterpret_cast<const char*>(points.data()), points.size() * sizeof(points[0]));
    };
    if constexpr (requires { c.hpoints(); })
        add(c.hpoints()); // RationalBezier
    else if constexpr (requires { c.points(); })
        add(c.points()); // Bez<N>, Bezier
    else if constexpr (requires { c.h; })
        add(c.h); // HConic
    else
        add(std::array<double, 7>{c.p0.x, c.p0.y, c.p1.x, c.p1.y, c.p2.x, c.p2.y, c.w}); // Conic
    if (const auto it = memo.find(key); it != memo.end()) return it->second;
    if (memo.size() >= kUniformMemoSize) memo.clear();
    return memo[key] = best_uniform_segments(c, tolerance, wang_segments(c, tolerance));
}

template <class Curve, class Sink>
void flatten_curve(const Curve& c, const FlattenOptions& o, Sink&& sink) {
    switch (o.method) {
    case FlattenMethod::Adaptive:
        flatten_adaptive(subdivision_form(c), o.tolerance, sink);
        break;
    case FlattenMethod::Halving:
        flatten_halving(subdivision_form(c), o.tolerance, sink);
        break;
    case FlattenMethod::Guided:
        flatten_guided(subdivision_form(c), o.tolerance, sink);
        break;
    case FlattenMethod::Integral:
        flatten_integral(subdivision_form(c), o.tolerance, sink);
        break;
    case FlattenMethod::UniformBest:
        flatten_uniform(c, memoized_best_uniform(c, o.tolerance), sink);
        break;
    case FlattenMethod::Uniform:
        flatten_uniform(c, o.segments > 0 ? o.segments : wang_segments(c, o.tolerance), sink);
        break;
    }
}

} // namespace casteljau
