// A tight upper bound of a polynomial piece's chord deviation from its chord
// and the curve's power-basis coefficients: the check behind every chord the
// integral flattener (integral.h) emits.
//
// The piece. Let B(t) = c0 + c1 t + c2 t^2 + c3 t^3 (c3 = 0 for a quadratic)
// and the piece be B over [a, a + h], a Bezier curve with control points P_i,
// chord v = P_N - P_0 = B(a + h) - B(a) and the chord's own points
// L_i = P_0 + (i/N) v. Then (Taylor at a, as guided.h's even cuts use it)
//   cubic:     P_i - L_i = -h^2 D(a + i h / 3), D(t) = B''(t) / 6 = c2 / 3 + c3 t,
//   quadratic: P_1 - L_1 = -h^2 c2 / 2,
// so the chord and the curve's coefficients give the piece, with no
// derivative evaluated at the vertices. With u_i = P_i - P_0:
//
// * When every inner point projects inside the chord (0 <= u_i . v <= |v|^2),
//   so does the whole curve (hull property), and the deviation is the largest
//   distance to the chord's line, |d(t)| / |v| with e_i = u_i x v = (P_i - L_i) x v:
//   - quadratic: d(t) = 2 t (1-t) e_1, so dev |v| = |e_1| / 2, exactly;
//   - cubic: d(t) = 3 t (1-t) ((1-t) e_1 + t e_2). With M = (e_1 + e_2) / 2
//     = -h^2 D(a + h/2) x v, E = (e_2 - e_1) / 2 = -(h^3 / 6) c3 x v and
//     s = 2t - 1 in [-1, 1],
//       d = (3/4) (1 - s^2) (M + E s).
//     If |E| <= |M| (no inflection in the piece, the common case), then
//       (1 - s^2)(|M| + E s sgn M) <= |M| + E^2 / (4 |M|)
//     because the difference is |M| (s - E / (2M))^2 + s^3 E sgn M >= 0 where
//     s E sgn M >= 0, and where it is negative (1 - s^2)(|M| + ...) <= |M|
//     outright. So dev |v| <= (3/16) (4 M^2 + E^2) / |M|: no square root and
//     no division when compared as squares, exact when the curvature is even
//     (E = 0) and at most 5.5% high (at |E| = |M|; 0.6% at |E| = |M| / 2).
//     If |E| > |M| (an inflection: the chords that straddle one), |d| is
//     largest at a root of 3 E s^2 + 2 M s - E, one in (-1, 0) and one in
//     (0, 1), taken exactly: those chords are long, the bound must not cut them.
// * Otherwise (a piece whose ends overshoot the chord: near cusps, collinear
//   control points, a zero chord), the smaller of two bounds that always hold:
//   the parametric one, (1 - 2^(1-N)) max_i |P_i - L_i| (guided.h), and the
//   hull one, max_i dist(P_i, chord segment) (flatness.h).
//
// The result is dev^2 <= num / den, a fraction, so that the flattener's
// common tests (against tol and against its planned deviation) multiply
// instead of dividing.
#pragma once

#include "casteljau/geom/point.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

/// The squared deviation bound num / den (den > 0).
struct ChordBound {
    double num = 0; ///< the squared bound's numerator
    double den = 1; ///< its denominator, > 0
    /// How the deviation grows with the piece's length h, as h^order: 2 where
    /// the curvature dominates, 3 across an inflection (the O(h^3) term).
    int order = 2;
    /// Whether the deviation is at most dev: num <= dev^2 den.
    bool within(double dev_sq) const noexcept { return num <= dev_sq * den; }
    /// The squared bound as one number.
    double value() const noexcept { return num / den; }
};

namespace chord_bound_detail {

/// The bound that holds for any piece: the smaller of the parametric and the
/// hull bound, from the inner points' offsets r_i = P_i - L_i.
template <int N>
[[gnu::noinline]] ChordBound overshoot_bound(const Vec2 (&r)[N - 1], Vec2 v) noexcept {
    constexpr double w = N == 2 ? 0.5 : 0.75; // 1 - 2^(1-N)
    double param = 0, hull = 0;
    for (int i = 0; i < N - 1; ++i) {
        param = std::max(param, r[i].length_sq());
        const SquaredDistance d = segment_distance_sq(v * (double(i + 1) / N) + r[i], v);
        hull = std::max(hull, d.num / d.den);
    }
    return {std::min(w * w * param, hull), 1};
}

/// The exact largest |(3/4)(1 - s^2)(M + E s)| on [-1, 1], |E| > |M|.
[[gnu::noinline]] inline double inflected_max(double M, double E) noexcept {
    const double root = std::sqrt(M * M + 3 * E * E), inv = 1 / (3 * E);
    double best = 0;
    for (const double s : {(root - M) * inv, (-root - M) * inv})
        best = std::max(best, std::fabs((1 - s * s) * (M + E * s)));
    return 0.75 * best;
}

} // namespace chord_bound_detail

/// The bound of the quadratic's piece of parameter length h with chord v,
/// c2 the quadratic's t^2 coefficient (top of the file).
inline ChordBound quad_chord_bound(Vec2 v, double h, Vec2 c2) noexcept {
    const double len_sq = v.length_sq(), k = 0.5 * h * h;
    const double along = 0.5 * len_sq - k * c2.dot(v);
    if (!((len_sq > 0) & (along >= 0) & (along <= len_sq))) {
        const Vec2 r[1] = {c2 * -k};
        return chord_bound_detail::overshoot_bound<2>(r, v);
    }
    const double e = k * c2.cross(v); // |e_1|
    return {0.25 * e * e, len_sq};
}

/// The bound of the cubic's piece [a, a + h] with chord v, c2 and c3 the
/// cubic's t^2 and t^3 coefficients (top of the file). Inlined into the
/// flattener's loop, whose hot path it is; the rare bounds are calls.
[[gnu::always_inline]] inline ChordBound cubic_chord_bound(Vec2 v, double a, double h, Vec2 c2,
                                                           Vec2 c3) noexcept {
    using namespace chord_bound_detail;
    const double len_sq = v.length_sq(), h2 = h * h, h3 = h2 * h * (1.0 / 6);
    const Vec2 mid = c2 * (1.0 / 3) + c3 * (a + 0.5 * h); // D(a + h/2)
    const double x = h2 * mid.dot(v), y = h3 * c3.dot(v);
    const double along1 = len_sq * (1.0 / 3) - x + y, along2 = len_sq * (2.0 / 3) - x - y;
    // No branch on each: their outcome is data.
    const bool inside =
        (len_sq > 0) & (along1 >= 0) & (along1 <= len_sq) & (along2 >= 0) & (along2 <= len_sq);
    if (!inside) {
        const Vec2 step = c3 * (h * (1.0 / 6));
        const Vec2 r[2] = {(mid - step) * -h2, (mid + step) * -h2};
        return overshoot_bound<3>(r, v);
    }
    const double M = -h2 * mid.cross(v), E = -h3 * c3.cross(v);
    if (std::fabs(E) > std::fabs(M)) {
        const double m = inflected_max(M, E);
        return {m * m, len_sq, 3};
    }
    if (M == 0) return {0, 1}; // then E = 0: a straight piece
    const double k = (3.0 / 16) * (4 * M * M + E * E);
    return {k * k, M * M * len_sq};
}

} // namespace casteljau
