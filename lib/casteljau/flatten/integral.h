// The integral flattener (selected by FlattenOptions or `--flatten integral`;
// guided.h is the default): Levien's method ("Flattening quadratic Beziers",
// 2019) made exact. The count of chords is the integral of the segment
// density (density.h), about the optimal count, and the vertices are spaced
// evenly in that integral, so that every chord deviates by about the same
// amount; then every chord is checked against the curve, and the few the
// density misplaces are corrected. Measured on the bench/flatten corpus
// (bench/README.md, 2026-11-29): 1.043x the optimal count at 0.25 px and
// 1.029x at 0.1 px at 27 M segments/s (0.62 us a curve), fewer segments than
// the greedy adaptive.h at about 2.5x its speed, 0.8x guided.h's segments at
// 1.7x its time a curve, and 0.77x the segments of Levien's method
// (levien.h) at equal measured error, in about its time a curve.
//
// The plan. With I = integral_0^1 w (a chord over which w integrates to d
// deviates by about tol d^2), the curve gets n = ceil(I) chords, the j-th
// ending where the integral reaches j I / n: each deviates by about
// tol (I/n)^2 <= tol. The vertices depend on the plan only, not on each other
// (no search, no chain of subdivisions), so they are computed kAhead at a
// time, their work overlapping, before they are checked. A corner
// (density.h) splits the plan in two: a vertex at the corner, and each side
// planned on its own.
//
// The check. Each chord is measured with chord_bound.h from its ends and the
// curve's power-basis coefficients (the ends' points by Horner's rule,
// PowerEval; no derivative), an upper bound within 0.6% of the exact
// deviation on the chords the plan makes. A chord is taken when the bound is
// <= tol and, except the last of a plan, >= kFloor times what the plan
// predicts (a chord far below its plan means the density overestimated it:
// taking it would waste the rest of the plan's spacing).
//
// The correction. A chord that fails either test is searched for the length
// whose deviation is in [kAccept, 1] tol: a safeguarded secant on
// g = sqrt(dev / tol), which grows like the chord's length where the
// curvature dominates (its first step assumes dev ~ h^3 across an
// inflection, chord_bound.h's order); then the rest is planned again from
// there: ceil(rest of I) chords, evenly spaced in the rest. Corrections happen
// where the density is a poor model: inflections (the chord's O(h^3) term),
// peaks of w between samples (loops' apexes), near corners. On the
// bench/flatten corpus they are 7% of the chords at 0.25 px, 9% at 0.1 px,
// and take 2.5 probes each.
//
// Guarantees. Every emitted chord passed the check (so the polyline is within
// tol of the curve, measured exactly by error.h), unless a chord of parameter
// length kIntegralMinStep = 2^-21 failed it: then the tolerance is below the
// coordinates' rounding noise (such a chord of a curve of size S deviates by
// at most about |B''| h^2 / 8 <= 6 S 2^-42 / 8: below 1e-4 px up to
// S = 5e8 px), and that chord and the rest of the curve are cut into chords
// of that length, untested. No chord is shorter than kIntegralMinStep but the
// ones ending at a corner or at the end, so a curve gives at most 2^21 + 2
// chords and the loop ends (regression:
// Integral.ChordCountIsCappedWhenTheToleranceIsBelowRounding, where searching
// every chord down to the shortest took 4 s). The vertices' parameters
// increase strictly, and the last vertex is the curve's end point at t = 1,
// bit for bit.
//
// Curves. Lines, quadratics and cubics (Bez<N>). Conics, rational curves and
// Beziers of higher degree go to the guided flattener (guided.h): their
// density has no model here yet (SVG's arcs, circles and rounded rectangles
// are conics, so a scene's share of them keeps guided's counts).
#pragma once

#include "casteljau/flatten/chord_bound.h"
#include "casteljau/flatten/density.h"
#include "casteljau/flatten/guided.h"
#include "casteljau/flatten/power_eval.h"
#include "casteljau/flatten/uniform.h"
#include "casteljau/flatten/vertex.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

/// Planned chords per curve at most: a hostile curve cannot ask for unbounded
/// work; uniform.h's cap.
inline constexpr int kIntegralMaxPlan = kMaxUniformSegments;
/// No chord is shorter, but the ones ending at a corner or the end (top of the
/// file): the guided flattener's shortest tested piece.
inline constexpr double kIntegralMinStep = 1.0 / double(1 << kGuidedMinLog2);

/// The constants of the check and the correction.
struct IntegralParams {
    /// A planned chord below kFloor times its planned deviation is stretched.
    /// Measured on the bench/flatten corpus at 0.25 px: 0.9 gives 1.045x the
    /// optimal count, 0.7 1.048x, no stretching 1.052x.
    static constexpr double kFloor = 0.9;
    /// A corrected chord is taken once its deviation is in [kAccept, 1] tol.
    static constexpr double kAccept = 0.97;
    /// The secant aims inside that window, so that rounding in its model does
    /// not push probes just above tol.
    static constexpr double kAim = 0.99;
    /// sqrt(kAim): the secant's aim for sqrt(deviation / tol).
    static constexpr double kGoal = 0.99498743710662;
    static_assert(kGoal * kGoal > kAim - 1e-12 && kGoal * kGoal < kAim + 1e-12);
    /// Probes per correction before the longest passing one is taken.
    static constexpr int kMaxProbes = 8;
};

/// The integral flattener of a Bez<N> as a range of FlatVertex (see
/// flatten_integral for the sink form).
template <int N>
class IntegralFlattener : public FlatVertexLoop<IntegralFlattener<N>> {
  public:
    /// The flattener constants.
    using P = IntegralParams;

    /// Flattens `c` to within `tolerance` > 0 (same units as the curve).
    IntegralFlattener(const Bez<N>& c, double tolerance) noexcept
        : eval_(c), density_(eval_.power(), tolerance), prev_(c.start()),
          tol_sq_(tolerance * tolerance) {
        end_integral_ = density_.total();
        end_t_ = density_.corner();
        if (end_t_ < 1.0) end_integral_ = density_.integral_at(end_t_);
        plan(0);
    }

  private:
    friend FlatVertexLoop<IntegralFlattener<N>>;
    /// The loop: emit(v) for each vertex while it returns true; returns
    /// whether it stopped at a vertex (false: none was left).
    template <class Emit>
    bool run(Emit&& emit) noexcept {
        while (!done_) {
            double t1;
            Point p;
            if (below_rounding_) {
                t1 = std::min(t_ + kIntegralMinStep, end_t_);
                p = eval_.point(t1);
            } else {
                if (next_ == filled_) fill();
                t1 = ahead_t_[std::size_t(next_)];
                p = ahead_p_[std::size_t(next_++)];
                if (!(t1 >= t_ + kIntegralMinStep)) {
                    t1 = std::min(t_ + kIntegralMinStep, end_t_);
                    p = eval_.point(t1);
                }
                const ChordBound b = bound(p, t1);
                if (b.within(tol_sq_) && (left_ == 1 || !b.within(floor_sq_))) {
                    ++planned_;
                    --left_;
                } else {
                    t1 = correct(t1, p, b);
                    if (t1 < end_t_) plan(density_.integral_at(t1));
                }
            }
            t_ = t1;
            prev_ = p;
            if (t1 == end_t_) reach_end();
            if (!emit(FlatVertex{p, t1})) return true;
        }
        return false;
    }

    /// Computes the plan's next vertices ahead of their checks: they depend
    /// on nothing but the plan, so their work (the inverse of the integral
    /// and the curve's point, a chain of dependent operations each) overlaps.
    /// This and bound() are inlined by force: GCC's inliner drops them when
    /// the translation unit grows (bench/flatten_bench with one flattener
    /// more: 0.73 -> 0.98 us a curve), and a call each costs a third.
    [[gnu::always_inline]] void fill() noexcept {
        next_ = 0;
        filled_ = std::min(left_, kAhead);
        for (int j = 0; j < filled_; ++j) {
            const double t =
                j == left_ - 1
                    ? end_t_
                    : std::min(density_.t_at(base_ + step_ * double(planned_ + 1 + j)), end_t_);
            ahead_t_[std::size_t(j)] = t;
            ahead_p_[std::size_t(j)] = eval_.point(t);
        }
    }

    /// The check (chord_bound.h) of the chord from the last vertex to p at t1.
    [[gnu::always_inline]] ChordBound bound(Point p, double t1) const noexcept {
        const Vec2 v = p - prev_;
        if constexpr (N == 1) {
            return {0, 1};
        } else if constexpr (N == 2) {
            return quad_chord_bound(v, t1 - t_, eval_.power().c[1]);
        } else {
            return cubic_chord_bound(v, t_, t1 - t_, eval_.power().c[1], eval_.power().c[2]);
        }
    }

    /// Plans the rest up to end_t_ from the vertex where the integral is `from`.
    void plan(double from) noexcept {
        base_ = from;
        planned_ = 0;
        next_ = filled_ = 0;
        const double rest = std::max(end_integral_ - from, 0.0);
        // 1e-9: a rest that is an integer up to rounding needs no extra chord.
        const double n = std::ceil(rest - 1e-9);
        left_ = n <= 1 ? 1 : n >= kIntegralMaxPlan ? kIntegralMaxPlan : int(n);
        step_ = rest / left_;
        const double planned_dev = P::kFloor * step_ * step_; // in units of tol
        floor_sq_ = tol_sq_ * planned_dev * planned_dev;
    }

    /// At end_t_: the curve's end, or a corner (density.h), past which the
    /// rest of the curve is planned.
    void reach_end() noexcept {
        if (end_t_ == 1.0) {
            done_ = true;
            return;
        }
        end_t_ = 1.0;
        const double from = end_integral_;
        end_integral_ = density_.total();
        plan(from);
    }

    /// The correction (top of the file) of the chord ending at t1 at point p
    /// with bound b: returns the end taken and leaves its point in p.
    [[gnu::noinline]] double correct(double t1, Point& p, ChordBound b) noexcept {
        // g = sqrt(deviation / tol) grows like h where the curvature is even
        // (dev ~ h^2), so a secant on g(h) toward kGoal lands in one or two
        // probes, and bisection takes over where it does not.
        double h = t1 - t_, pass_h = 0, fail_h = 0; // longest passing, shortest failing
        double best_t = 0, prev_h = 0, prev_g = 0;
        Point best{};
        for (int probe = 1;; ++probe) {
            const double r = b.num / (b.den * tol_sq_); // (deviation / tol)^2
            if (r <= 1) {
                pass_h = h, best_t = t1, best = p;
                if (r >= P::kAccept * P::kAccept || t1 == end_t_ || probe >= P::kMaxProbes) break;
            } else {
                fail_h = h;
                if (h <= kIntegralMinStep) { // below the rounding noise: take it and the rest
                    best_t = t1, best = p;
                    below_rounding_ = true;
                    break;
                }
                if (pass_h > 0 && probe >= P::kMaxProbes) break;
            }
            const double g = std::sqrt(std::sqrt(r));
            double next = 2 * h;
            if (prev_h > 0 && g != prev_g)
                next = h + (P::kGoal - g) * (h - prev_h) / (g - prev_g);
            else if (g > 0) // first step: dev ~ h^order
                next = h * (b.order == 3 ? std::cbrt(P::kGoal * P::kGoal / (g * g)) : P::kGoal / g);
            const double cap = fail_h > 0 ? fail_h : end_t_ - t_;
            // Bisection where the secant leaves the bracket, and from the
            // kMaxProbes-th probe on (no passing chord yet): the bracket then
            // halves each probe, down to kIntegralMinStep at worst.
            if (!(next > pass_h && next < cap) || probe >= P::kMaxProbes)
                next = fail_h > 0 ? 0.5 * (pass_h + fail_h) : cap;
            next = std::max(next, kIntegralMinStep);
            prev_h = h, prev_g = g;
            t1 = next >= end_t_ - t_ ? end_t_ : t_ + next;
            h = t1 - t_;
            p = eval_.point(t1);
            b = bound(p, t1);
        }
        p = best;
        return best_t;
    }

    PowerEval<N> eval_;
    typename DensityOf<N>::type density_;
    Point prev_; ///< the last vertex
    double tol_sq_, floor_sq_ = 0;
    double end_t_ = 1.0, end_integral_ = 0; ///< where the plan ends: 1 or a corner
    double base_ = 0, step_ = 0; ///< the plan: chord j ends where the integral is base + j step
    int planned_ = 0, left_ = 1; ///< chords of the plan emitted, and still to go
    double t_ = 0;               ///< where the last vertex is
    bool done_ = false;
    bool below_rounding_ = false; ///< a shortest chord failed: the rest is cut untested
    // Vertices computed ahead (fill): 1.2x the segments per second of one at a
    // time on the bench/flatten corpus; 4 and 8 measured the same, 16 8% slower
    // (more of them thrown away when a correction replans).
    static constexpr int kAhead = 8;
    std::array<double, kAhead> ahead_t_; ///< the plan's next vertices (fill)
    std::array<Point, kAhead> ahead_p_;
    int next_ = 0, filled_ = 0; ///< the first unchecked one, and how many
};

/// Sink form: sink(FlatVertex) for every vertex after the start.
template <int N, class Sink>
void flatten_integral(const Bez<N>& c, double tolerance, Sink&& sink) noexcept {
    IntegralFlattener<N>(c, tolerance).drain(sink);
}

/// Other curves: the guided flattener (top of the file).
template <class Curve, class Sink>
void flatten_integral(const Curve& c, double tolerance, Sink&& sink) noexcept {
    flatten_guided(c, tolerance, sink);
}

} // namespace casteljau
