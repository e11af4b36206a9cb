// Uniform flattening: N segments chosen in advance, vertices at t_i = i / N.
// The baseline everything adaptive is compared against.
//
// The N that guarantees a tolerance comes from Wang's formula (Goldman,
// "Pyramid Algorithms", 2003, 5.6.3): for a degree-d Bezier curve, the chords
// of N uniform pieces stay within tol of the curve when
//   N >= sqrt( d (d-1) / 8 * max_i |P_{i+2} - 2 P_{i+1} + P_i| / tol ),
// because |B''| <= d (d-1) max |second differences| and a chord of parameter
// length h deviates by at most h^2 max |B''| / 8 from a C2 curve. For conics
// the analogue of Zheng and Sederberg ("Estimating tessellation parameter
// intervals for rational curves and surfaces", ACM TOG 19(1), 2000, thm 3,
// cor. 1) is used, with the control points centred on their bounding box to
// make it translation invariant:
//   N^2 >= (|P_0 - 2 w P_1 + P_2| / tol + max(0, r / tol - 1) |2 - 2w|) / (4 min(w, 1))
// with r the largest centred control point distance. Both bounds are
// conservative: the measured best N (error.h) is often smaller, and the
// benchmarks compare against that best N, not against these bounds.
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/curve/bezier.h"
#include "casteljau/curve/conic.h"
#include "casteljau/curve/rational.h"
#include "casteljau/flatten/vertex.h"

#include <cmath>

namespace casteljau {

/// Segment counts are capped so a hostile curve cannot ask for unbounded work;
/// 2^20 matches the adaptive flattener's depth cap.
inline constexpr int kMaxUniformSegments = 1 << 20;

int wang_segments(std::span<const Point> control, double tolerance) noexcept;
template <int N>
int wang_segments(const Bez<N>& c, double tolerance) noexcept {
    return wang_segments(c.points(), tolerance);
}
inline int wang_segments(const Bezier& c, double tolerance) noexcept {
    return wang_segments(c.points(), tolerance);
}
int wang_segments(const Conic& c, double tolerance) noexcept;
/// No closed form is used for rational curves of higher degree: the smallest N
/// whose measured error meets the tolerance (error.h) is taken instead.
int wang_segments(const RationalBezier& c, double tolerance);

template <class Curve, class Sink>
void flatten_uniform(const Curve& c, int n, Sink&& sink) noexcept {
    const auto emit = [&](const auto& form) {
        for (int i = 1; i < n; ++i) {
            const double t = double(i) / double(n);
            sink(FlatVertex{form.eval(t), t});
        }
        sink(FlatVertex{c.end(), 1.0});
    };
    // The power basis costs one Horner evaluation per vertex; curves without
    // one (conics, rational curves) evaluate by de Casteljau.
    if constexpr (requires { c.power(); })
        emit(c.power());
    else
        emit(c);
}

} // namespace casteljau
