// One entry point for every flattening method and curve type, as the path
// flattener, the CLI and the benchmarks choose them at run time.
#pragma once

#include "casteljau/flatten/adaptive.h"
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/halving.h"
#include "casteljau/flatten/uniform.h"

namespace casteljau {

enum class FlattenMethod {
    Adaptive, // greedy flat prefixes (adaptive.h): the default
    Uniform,  // N segments in advance (uniform.h)
    Halving,  // textbook midpoint subdivision (halving.h): a baseline
    // Uniform with, per curve, the smallest N whose measured error meets the
    // tolerance (error.h): uniform sampling at its best, for comparisons at
    // equal error. Slow: it measures several candidate N per curve.
    UniformBest,
};

struct FlattenOptions {
    double tolerance = 0.25; // device pixels; > 0
    FlattenMethod method = FlattenMethod::Adaptive;
    int segments = 0; // Uniform only: N per curve; 0 = the smallest that Wang's bound allows
};

// The form a curve is subdivided in: itself, except conics, which subdivide in
// homogeneous form so that the reported parameters stay the conic's own.
template <class Curve>
const Curve& subdivision_form(const Curve& c) {
    return c;
}
inline HConic subdivision_form(const Conic& c) { return HConic::from(c); }

template <class Curve, class Sink>
void flatten_curve(const Curve& c, const FlattenOptions& o, Sink&& sink) {
    switch (o.method) {
    case FlattenMethod::Adaptive:
        flatten_adaptive(subdivision_form(c), o.tolerance, sink);
        break;
    case FlattenMethod::Halving:
        flatten_halving(subdivision_form(c), o.tolerance, sink);
        break;
    case FlattenMethod::UniformBest:
        flatten_uniform(c, best_uniform_segments(c, o.tolerance, wang_segments(c, o.tolerance)),
                        sink);
        break;
    case FlattenMethod::Uniform:
        flatten_uniform(c, o.segments > 0 ? o.segments : wang_segments(c, o.tolerance), sink);
        break;
    }
}

} // namespace casteljau
