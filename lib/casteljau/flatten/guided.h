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
//
// Pieces by parameter. The stack holds parameter ranges only (a level: a
// range cut into k equal pieces, and how many are done), and pieces are
// visited in order, so a piece always starts where the last emitted one
// ended. A piece's control points come from its ends: for Bez<N> from the
// point and the derivative there (the Hermite form: the piece over [t0, t1]
// has P_1 = B(t0) + (h/N) B'(t0) and P_{N-1} = B(t1) - (h/N) B'(t1), h = t1 - t0),
// with B and B' evaluated in the power basis; for conics the same in
// homogeneous coordinates (ConicPieces); other curves take
// subsegment(t0, t1). Unlike cutting off pieces by successive splits, no
// piece waits on the one before it, and a level is 40 bytes.
//
// Cuts known flat. The parametric offsets of a polynomial piece are its
// second differences, which a cut into k scales by 1/k^2; for a cubic they
// are values of the linear D(t) = B''(t) / 6, whose length is convex, so one
// test at the cut bounds every piece of it (even_cut_is_flat). When it holds,
// the pieces are emitted untested: on the bench/flatten corpus, 40% of the
// vertices, at the same count and positions, for 1.1x the speed.
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
// The last vertex is the curve's end point, bit for bit.
#pragma once

#include "casteljau/flatten/flatness.h"
#include "casteljau/flatten/power_eval.h"
#include "casteljau/flatten/vertex.h"

#include <algorithm>
#include <array>
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

/// How far from flat a piece is: its squared deviation bound (see the top of
/// the file) over the squared tolerance, as the fraction num / den, so that
/// neither accepting a piece nor counting its cut divides (a division is
/// 13-20 cycles on the loop's critical path).
struct GuidedExcess {
    double num, den = 1; ///< den > 0
    /// Whether the piece passes the test.
    bool flat() const noexcept { return num <= den; }
    /// The excess as one number.
    double value() const noexcept { return num / den; }
};

/// guided_excess of a polynomial Bezier given by its control points (a fixed
/// extent for Bez<N>, so the loop over them unrolls). Inlined by force into
/// the probes (HermitePieces::probe says why).
template <std::size_t E>
[[gnu::always_inline]] inline GuidedExcess polynomial_excess(std::span<const Point, E> p,
                                                             double scaled_tol) noexcept {
    const std::size_t n = p.size() - 1;
    const Vec2 chord = p[n] - p[0];
    const double len_sq = chord.length_sq();
    double param = 0, perp = 0;
    bool inside = true;
    for (std::size_t i = 1; i < n; ++i) {
        const Vec2 w = p[i] - p[0];
        // Selects, not std::max, which GCC 12 compiled to a branch here (seen
        // in the profile): which inner point is farther is data.
        const double p = (w - chord * (double(i) / double(n))).length_sq();
        const double along = w.dot(chord), across = w.cross(chord);
        param = p > param ? p : param;
        inside &= (along >= 0) & (along <= len_sq); // no branch: its outcome is data
        perp = across * across > perp ? across * across : perp;
    }
    // The distance to the chord's line is the tighter bound when every inner
    // point projects inside the chord (then the whole curve does); its square
    // is perp / len_sq.
    const bool perp_applies = inside && len_sq > 0;
    if ((param <= scaled_tol) | (perp_applies & (perp <= scaled_tol * len_sq))) return {0};
    if (perp_applies && perp < param * len_sq) return {perp, scaled_tol * len_sq};
    return {param, scaled_tol};
}

/// The GuidedExcess of a piece, given `scaled_tol` = tol^2 /
/// guided_weight_sq(degree) for polynomial curves, tol^2 for rational ones.
template <class Curve>
inline GuidedExcess guided_excess(const Curve& c, double scaled_tol) noexcept {
    if constexpr (!requires { c.points(); }) { // rational: the hull bound of flatness.h
        const double d = hull_deviation(c);
        return {d * d, scaled_tol};
    } else {
        return polynomial_excess(c.points(), scaled_tol);
    }
}

/// ceil(excess^(1/4)), at most kGuidedMaxCut: the number of equal pieces a
/// piece with this excess (squared bound / squared tolerance) is cut into. By
/// counting the j^4 below it: two square roots and a division cost more than
/// seven compares.
inline int guided_cut(GuidedExcess e) noexcept {
    int k = 1;
    for (int j = 1; j < kGuidedMaxCut; ++j) k += int(e.num > double(j * j * j * j) * e.den);
    return k;
}

/// Pieces of a Bez<N> by parameter, in the Hermite form (top of the file).
/// probe(t0, t1) measures the piece from the last accepted end t0 to t1;
/// accept() makes t1 the last accepted end and returns its point.
template <int N>
class HermitePieces {
  public:
    /// The pieces of c, starting at t = 0.
    explicit HermitePieces(const Bez<N>& c) noexcept : eval_(c), prev_(eval_.start()) {}
    /// Moves to t1 without a test; returns the point there. Only the `last`
    /// piece of a cut known flat needs the derivative (for the probe after it).
    Point advance(double t1, bool last) noexcept {
        if (last) {
            next_ = eval_.at(t1);
            return accept();
        }
        return prev_.p = eval_.point(t1);
    }
    /// Whether each of the equal pieces of length h that cut [t0, t1] passes
    /// the parametric test.
    /// The piece [a, a + h] of a cubic has P_i - L_i = -h^2 D(a + i h / 3) for
    /// i = 1, 2, with D(t) = B''(t) / 6 = c_2 / 3 + c_3 t in the power basis;
    /// |D| is convex, so over all the pieces' inner thirds it is largest at
    /// the first or the last. A quadratic's P_1 - L_1 = -h^2 c_2 / 2 for every piece.
    bool even_cut_is_flat(double h, double t0, double t1, double scaled_tol) const noexcept {
        if constexpr (N == 1) {
            return true;
        } else {
            const PowerCurve<N>& power = eval_.power();
            const double h4 = h * h * h * h;
            if constexpr (N == 2) return h4 * power.c[1].length_sq() * 0.25 <= scaled_tol;
            const Vec2 a = power.c[1] * (1.0 / 3) + power.c[2] * (t0 + h * (1.0 / 3));
            const Vec2 b = power.c[1] * (1.0 / 3) + power.c[2] * (t1 - h * (1.0 / 3));
            return h4 * std::max(a.length_sq(), b.length_sq()) <= scaled_tol;
        }
    }
    /// The excess (guided_excess) of the piece [t0, t1]. Inlined by force,
    /// as PowerEval's evaluations are: the flattener's loop calls it once per
    /// piece, and GCC's inliner drops it when the translation unit grows
    /// (bench/flatten_bench with one flattener more: 0.36 -> 0.57 us a curve).
    [[gnu::always_inline]] GuidedExcess probe(double t0, double t1, double scaled_tol) noexcept {
        next_ = eval_.at(t1);
        if constexpr (N == 1) {
            return {0};
        } else {
            const double h = (t1 - t0) * (1.0 / N);
            std::array<Point, N + 1> p;
            p[0] = prev_.p;
            p[1] = prev_.p + prev_.d * h;
            p[N - 1] = next_.p - next_.d * h; // for a quadratic, P_1 again from its end
            p[N] = next_.p;
            return polynomial_excess(std::span<const Point, N + 1>(p), scaled_tol);
        }
    }
    /// Makes the last probed end the start of the next piece; returns its point.
    Point accept() noexcept {
        prev_ = next_;
        return prev_.p;
    }

  private:
    PowerEval<N> eval_; // B and B' in SSE2 pairs (power_eval.h)
    typename PowerEval<N>::Sample prev_, next_;
};

/// Pieces of a conic by parameter, in the homogeneous Hermite form. The
/// homogeneous curve H(t) = (w x, w y, w)(t) is a quadratic polynomial, so the
/// piece over [t0, t1] has the homogeneous control points H(t0),
/// H(t0) + (h/2) H'(t0) and H(t1), h = t1 - t0: subsegment(t0, t1)'s piece up
/// to rounding, from values kept from the last probe instead of two de
/// Casteljau cuts, and measured with hull_deviation's bound (the distance from
/// the middle control point to the chord) in squares: no square root, and no
/// division but the projections of the middle and the end point. 4.5-5x
/// faster per segment than SubsegmentPieces<HConic>, for the same cuts
/// (bench/flatten's conic/ benchmarks).
class ConicPieces {
  public:
    /// The pieces of c, starting at t = 0.
    explicit ConicPieces(const HConic& c) noexcept
        : a_(c.h[0]), b_(scaled(sub(c.h[1], c.h[0]), 2)),
          c_(sub(c.h[2], sub(scaled(c.h[1], 2), c.h[0]))), end_(c.h[2]),
          end_deriv_(scaled(sub(c.h[2], c.h[1]), 2)), prev_{a_, b_, c.start()} {}
    /// The excess (guided_excess of the hull bound) of the piece [t0, t1].
    GuidedExcess probe(double t0, double t1, double scaled_tol) noexcept {
        next_ = at(t1);
        const double half = 0.5 * (t1 - t0);
        const HPoint mid{prev_.h.x + half * prev_.d.x, prev_.h.y + half * prev_.d.y,
                         prev_.h.w + half * prev_.d.w};
        // distance_to_segment(P1, P0, P2)^2, as a fraction.
        const SquaredDistance d = segment_distance_sq(mid.project() - prev_.p, next_.p - prev_.p);
        return {d.num, scaled_tol * d.den};
    }
    /// Makes the last probed end the start of the next piece; returns its point.
    Point accept() noexcept {
        prev_ = next_;
        return prev_.p;
    }
    /// Moves to t1 without a test; returns the point there.
    Point advance(double t1, bool) noexcept {
        next_ = at(t1);
        return accept();
    }
    /// No bound on even cuts: every piece is tested.
    bool even_cut_is_flat(double, double, double, double) const noexcept { return false; }

  private:
    struct Sample {
        HPoint h, d; ///< H(t), H'(t)
        Point p;     ///< H(t) projected
    };
    static HPoint sub(HPoint a, HPoint b) noexcept { return {a.x - b.x, a.y - b.y, a.w - b.w}; }
    static HPoint scaled(HPoint a, double s) noexcept { return {a.x * s, a.y * s, a.w * s}; }
    /// H(t) = a + t (b + t c) and H'(t) = b + 2 t c; at t = 1 the end control
    /// point and its derivative exactly, so the last vertex is the curve's end bit for bit.
    Sample at(double t) const noexcept {
        if (t == 1.0) return {end_, end_deriv_, end_.project()};
        const HPoint h{a_.x + t * (b_.x + t * c_.x), a_.y + t * (b_.y + t * c_.y),
                       a_.w + t * (b_.w + t * c_.w)};
        const double t2 = 2 * t;
        return {h, {b_.x + t2 * c_.x, b_.y + t2 * c_.y, b_.w + t2 * c_.w}, h.project()};
    }
    HPoint a_, b_, c_;       ///< H in the power basis
    HPoint end_, end_deriv_; ///< H(1) and H'(1), exact
    Sample prev_, next_;
};

/// Pieces of any other curve (Bezier, RationalBezier; and HConic as the
/// reference for ConicPieces) by parameter, through subsegment; the same
/// interface as HermitePieces.
template <class Curve>
class SubsegmentPieces {
  public:
    /// The pieces of c, starting at t = 0.
    explicit SubsegmentPieces(const Curve& c) noexcept : c_(c) {}
    /// The excess (guided_excess) of the piece [t0, t1].
    GuidedExcess probe(double t0, double t1, double scaled_tol) noexcept {
        const Curve piece = c_.subsegment(t0, t1);
        next_ = t1 == 1.0 ? c_.end() : piece.end();
        return guided_excess(piece, scaled_tol);
    }
    /// The end of the last probed piece.
    Point accept() const noexcept { return next_; }
    /// Moves to t1 without a test; returns the point there.
    Point advance(double t1, bool) noexcept { return next_ = t1 == 1.0 ? c_.end() : c_.eval(t1); }
    /// No bound on even cuts: every piece is tested.
    bool even_cut_is_flat(double, double, double, double) const noexcept { return false; }

  private:
    Curve c_;
    Point next_;
};

/// How the guided flattener cuts pieces of a curve type: by subsegment...
template <class Curve>
struct GuidedPiecesOf {
    using type = SubsegmentPieces<Curve>; ///< the pieces
};
/// ...except Bez<N>, in the Hermite form...
template <int N>
struct GuidedPiecesOf<Bez<N>> {
    using type = HermitePieces<N>; ///< the pieces
};
/// ...and conics, in their homogeneous Hermite form.
template <>
struct GuidedPiecesOf<HConic> {
    using type = ConicPieces; ///< the pieces
};

/// The guided flattener as a range of FlatVertex (see flatten_guided for the
/// sink form). `Pieces` is a choice for tests and benchmarks, which compare
/// the fast forms with SubsegmentPieces.
template <class Curve, class Pieces = typename GuidedPiecesOf<Curve>::type>
class GuidedFlattener : public FlatVertexLoop<GuidedFlattener<Curve, Pieces>> {
  public:
    /// Flattens `c` to within `tolerance` (same units as the curve).
    GuidedFlattener(const Curve& c, double tolerance) noexcept
        : pieces_(c), scaled_tol_(tolerance * tolerance) {
        if constexpr (requires { c.points(); })
            scaled_tol_ /= guided_weight_sq(int(c.points().size()) - 1);
        stack_[0] = {0.0, 1.0, 1.0, 0, 1, false};
    }

  private:
    friend FlatVertexLoop<GuidedFlattener<Curve, Pieces>>;
    /// The loop: emit(v) for each vertex while it returns true; returns
    /// whether vertices remain.
    template <class Emit>
    bool run(Emit&& emit) noexcept {
        while (top_ >= 0) {
            Level& level = stack_[std::size_t(top_)];
            const double t0 = t_;
            const bool last = ++level.done == level.k;
            const double t1 = last ? level.t1 : level.t0 + double(level.done) * level.step;
            if (last) --top_; // a failing last piece reuses the slot (level stays readable)
            if (level.sure) {
                t_ = t1;
                if (!emit(FlatVertex{pieces_.advance(t1, last), t1})) return true;
                continue;
            }
            const GuidedExcess excess = pieces_.probe(t0, t1, scaled_tol_);
            if (excess.flat() || t1 - t0 <= kMinStep || top_ == kMaxLevel) {
                t_ = t1;
                if (!emit(FlatVertex{pieces_.accept(), t1})) return true;
                continue;
            }
            const int k = guided_cut(excess);
            const double step = (t1 - t0) * kInverse[std::size_t(k)];
            const bool sure = pieces_.even_cut_is_flat(step, t0, t1, scaled_tol_);
            stack_[std::size_t(++top_)] = {t0, step, t1, 0, k, sure};
        }
        return false;
    }

    /// [t0, t1] cut into k pieces of length step, of which `done` are visited.
    struct Level {
        double t0, step, t1;
        int done, k;
        bool sure;
    };
    // 1/k, so that a cut's step is a product, not a division on the loop's
    // critical path. The rounding of 1/k moves inner cuts by an ulp; the last
    // piece still ends at the level's t1 exactly.
    static constexpr double kInverse[kGuidedMaxCut + 1] = {
        0, 1.0, 1.0 / 2, 1.0 / 3, 1.0 / 4, 1.0 / 5, 1.0 / 6, 1.0 / 7, 1.0 / 8};
    static constexpr double kMinStep = 1.0 / double(1 << kGuidedMinLog2);
    static constexpr int kMaxLevel = kGuidedMinLog2 + 1;
    Pieces pieces_;
    // The stack holds at most one level per halving (top of the file). Left
    // uninitialised: only pushed levels are read.
    std::array<Level, kMaxLevel + 1> stack_;
    int top_ = 0;
    double t_ = 0; ///< where the last emitted piece ended
    double scaled_tol_;
};

/// Sink form: sink(FlatVertex) for every vertex after the start.
template <class Curve, class Sink>
void flatten_guided(const Curve& c, double tolerance, Sink&& sink) noexcept {
    GuidedFlattener<Curve>(c, tolerance).drain(sink);
}

} // namespace casteljau
