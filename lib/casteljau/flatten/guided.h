// Guided subdivision: adaptive de Casteljau subdivision that cuts a piece
// failing the flatness test into as many equal parameter pieces as its
// deviation predicts, instead of halving it. The fast flattener: about 1.3x
// the optimal segment count, at a fraction of the greedy flattener's cost per
// segment (bench/flatten reports both).
//
// The flatness test (Bez<N>, N = 1..3, and Bezier). Write the chord with its
// uniform parametrisation L(t) = (1-t) P_0 + t P_n as a degree-n Bezier: its
// control points are L_i = P_0 + (i/n) (P_n - P_0). Then
//   B(t) - L(t) = sum_{0<i<n} b_{i,n}(t) (P_i - L_i),
// and the inner Bernstein weights sum to 1 - (1-t)^n - t^n <= 1 - 2^(1-n), so
//   |B(t) - L(t)| <= (1 - 2^(1-n)) max_i |P_i - L_i| =: bound
// (3/4 of the largest offset for a cubic, 1/2 for a quadratic). L(t) lies on
// the chord segment, so every curve point is within `bound` of the chord and,
// pairing the same t, every chord point within `bound` of the curve: the
// Hausdorff distance is at most `bound`. Where every inner control point
// projects inside the chord, the same Bernstein sum bounds the distance to
// the chord's line by (1 - 2^(1-n)) max_i dist(P_i, line), and the whole curve
// projects inside the chord (hull property), so the smaller of the two bounds
// is used: the parametric one overestimates curves whose speed varies. The
// test compares squares, so an accepted piece costs no square root and no
// division. Rational curves (conics, RationalBezier) use the hull bound of
// flatness.h instead.
//
// The cut. A piece of parameter length h of a smooth curve has bound ~ c h^2
// (the second differences of the control points scale with h^2), so a piece
// with bound b > tol is cut into k = ceil(sqrt(b / tol)) equal pieces, which
// would each be flat if its curvature were even. Each is tested again, and
// the ones that are not flat (curvature that varies) are cut the same way.
// Pieces are cut off one by one from the front (split at 1/k, 1/(k-1), ...),
// so a level of the stack holds only the unprocessed rest of a piece.
//
// Guarantees. Every emitted piece passed the test, except pieces of at most
// 2^-kGuidedMinLog2 of the parameter range, emitted as their chord: reached
// only when the tolerance is below the coordinates' rounding noise. Every cut
// divides the length by at least 2, so the stack holds at most one level per
// halving, kGuidedMinLog2 + 1 (one more for rounding in the lengths). Every
// piece is cut from one longer than 2^-kGuidedMinLog2 into at most
// kGuidedMaxCut, so it is longer than 2^-kGuidedMinLog2 / kGuidedMaxCut = 2^-24:
// the pieces are disjoint, so a curve gives at most 2^24 segments and the
// loop always ends (regression: Flatten.DepthCapHoldsWhenTheToleranceIsBelowRounding,
// which a depth cap alone failed, cutting every piece 8 ways on all 24 levels).
#pragma once

#include "casteljau/flatten/flatness.h"
#include "casteljau/flatten/vertex.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <span>

namespace casteljau {

/// Most pieces one cut makes. A cut into k pieces predicted from the piece's
/// largest offset over-cuts where the curvature is uneven; cutting at most 8
/// ways and testing again adapts (measured on the bench/flatten corpus at
/// 0.25 px: 1.33x the optimal count at 8, 1.5x at 2, that is halving, and
/// 1.57x with no limit).
inline constexpr int kGuidedMaxCut = 8;
/// Pieces of parameter length <= 2^-21 are emitted as their chord, so no
/// piece is shorter than 2^-21 / kGuidedMaxCut = 2^-24.
inline constexpr int kGuidedMinLog2 = 21;

/// The largest sum of a degree-n Bezier's inner Bernstein weights, 1 - 2^(1-n),
/// squared: the factor of the parametric bound (top of the file).
inline double guided_weight_sq(int n) noexcept {
    const double w = 1.0 - 2.0 / double(std::size_t(1) << n);
    return w * w;
}

/// guided_excess of a polynomial Bezier given by its control points (a fixed
/// extent for Bez<N>, so the loop over them unrolls).
template <std::size_t E>
inline double polynomial_excess(std::span<const Point, E> p, double scaled_tol) noexcept {
    const std::size_t n = p.size() - 1;
    const Vec2 chord = p[n] - p[0];
    const double len_sq = chord.length_sq();
    double param = 0, perp = 0;
    bool inside = true;
    for (std::size_t i = 1; i < n; ++i) {
        const Vec2 w = p[i] - p[0];
        param = std::max(param, (w - chord * (double(i) / double(n))).length_sq());
        const double along = w.dot(chord), across = w.cross(chord);
        inside &= (along >= 0) & (along <= len_sq); // no branch: its outcome is data
        perp = std::max(perp, across * across);
    }
    // The distance to the chord's line is the tighter bound when every inner
    // point projects inside the chord (then the whole curve does).
    if (inside && len_sq > 0) {
        if (perp <= scaled_tol * len_sq) return 0;
        param = std::min(param, perp / len_sq);
    }
    return param / scaled_tol;
}

/// How far from flat a piece is: its squared deviation bound (see the top of
/// the file) over the squared tolerance, given as `scaled_tol` = tol^2 /
/// guided_weight_sq(degree) for polynomial curves, tol^2 for rational ones;
/// at most 1 when flat. Accepting a polynomial piece costs no division.
template <class Curve>
inline double guided_excess(const Curve& c, double scaled_tol) noexcept {
    if constexpr (!requires { c.points(); }) { // rational: the hull bound of flatness.h
        const double d = hull_deviation(c);
        return d * d / scaled_tol;
    } else {
        return polynomial_excess(c.points(), scaled_tol);
    }
}

/// The guided flattener as a range of FlatVertex (see flatten_guided for the sink form).
template <class Curve>
class GuidedFlattener : public FlatVertexRange<GuidedFlattener<Curve>> {
  public:
    /// Flattens `c` to within `tolerance` (same units as the curve).
    GuidedFlattener(const Curve& c, double tolerance) noexcept
        : scaled_tol_(tolerance * tolerance) {
        if constexpr (requires { c.points(); })
            scaled_tol_ /= guided_weight_sq(int(c.points().size()) - 1);
        std::construct_at(&stack_[0].level, Level{c, 0.0, 1.0, 1});
    }

    /// Writes the next vertex; false once the end point has been emitted.
    bool next(FlatVertex& out) noexcept {
        while (top_ >= 0) {
            Level& level = stack_[std::size_t(top_)].level;
            const double t0 = level.t0;
            Curve piece;
            double t1 = level.t1;
            if (level.left == 1) {
                piece = level.rest;
                --top_;
            } else {
                const auto halves = level.rest.split(1.0 / double(level.left));
                piece = halves[0];
                level.rest = halves[1];
                t1 = t0 + (level.t1 - t0) / double(level.left);
                level.t0 = t1;
                --level.left;
            }
            const double excess = guided_excess(piece, scaled_tol_);
            if (excess <= 1.0 || t1 - t0 <= kMinStep || top_ == kMaxLevel) {
                out = {piece.end(), t1};
                return true;
            }
            const double k = std::ceil(std::sqrt(std::sqrt(excess)));
            std::construct_at(&stack_[std::size_t(++top_)].level,
                              Level{piece, t0, t1, int(std::min(k, double(kGuidedMaxCut)))});
        }
        return false;
    }

  private:
    struct Level {
        Curve rest;    ///< the unprocessed rest of a cut piece
        double t0, t1; ///< its parameter range on the whole curve
        int left;      ///< equal pieces still to cut from it
    };
    // The slots are left uninitialised: Point zero-initialises, and clearing
    // 2 KB per curve would cost more than flattening a short one.
    union Slot {
        Slot() noexcept {}
        Level level;
    };
    static constexpr double kMinStep = 1.0 / double(1 << kGuidedMinLog2);
    static constexpr int kMaxLevel = kGuidedMinLog2 + 1;
    // A level is popped when its last piece is taken, so a failing last piece
    // reuses the slot: the stack holds at most one level per halving.
    std::array<Slot, kMaxLevel + 1> stack_;
    int top_ = 0;
    double scaled_tol_;
};

/// Sink form: sink(FlatVertex) for every vertex after the start.
template <class Curve, class Sink>
void flatten_guided(const Curve& c, double tolerance, Sink&& sink) noexcept {
    drain_flattener(GuidedFlattener<Curve>(c, tolerance), sink);
}

} // namespace casteljau
