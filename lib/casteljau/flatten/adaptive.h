// Adaptive flattening by de Casteljau subdivision, splitting off the longest
// flat prefix ("greedy chord") instead of halving.
//
// Why not halving. Halving a piece divides its deviation by about 4, so the
// leaves of midpoint subdivision have deviations spread over [tol/4, tol] and
// the polyline has ~1.3-1.7x the segments it needs (measured: bench/flatten).
// The optimum for a polyline with vertices on the curve is about
//   n* = integral of sqrt(kappa / (8 tol)) ds
// because a chord over arc length s of curvature kappa deviates by kappa s^2 / 8
// (Levien, "Flattening quadratic Beziers", 2019): the optimum gives every chord
// the same deviation tol.
//
// The algorithm. Keep the unflattened remainder R = C restricted to [t0, 1]
// (a de Casteljau subsegment, so no re-evaluation of C is ever needed). If R is
// flat (chord_deviation(R) <= tol, see flatness.h: an exact deviation for
// quadratics, cubics and conics) emit its end and stop. Otherwise find u in
// (0, 1) such that the prefix R[0, u] is flat with a deviation in
// [kAccept tol, tol], split R there by de Casteljau, emit the prefix's end and
// continue with the suffix. The search is a safeguarded secant on the model
// dev(u) ~ c u^2 (a short chord's deviation grows with the square of its
// length): each probe u has a measured deviation e and proposes
// u * sqrt(kTarget tol / e), kept inside the bracket [largest flat u, smallest
// non-flat u] and bisecting when it falls out. The first probe is predicted
// from the previous chord (same c, like a step-size controller of an ODE
// solver), so most chords cost one or two probes.
//
// Guarantees. Every emitted chord passed the flatness test, so the polyline is
// within tol of the curve (flatness.h), except where the depth cap acts: no
// chord is shorter than 2^-kMaxDepth of the curve's parameter range, so a
// curve gives at most 2^kMaxDepth + 1 segments and the loop always ends. The
// cap only acts when the tolerance is below the rounding noise of the
// coordinates (|P| * 2^-52 > tol, i.e. coordinates beyond ~1e13 px at 0.01 px):
// then the chord of the minimal length is emitted as it is. Greedy prefixes
// are optimal in count for a monotone flatness test (an interval-covering
// argument), so within the kAccept window this is near the optimum n*.
//
// No recursion and no stack: the remainder is the only pending piece, because
// a prefix is split off only once it is known to be flat.
#pragma once

#include "casteljau/flatten/flatness.h"
#include "casteljau/flatten/vertex.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

/// The constants of the adaptive flattener: depth cap and stack size.
struct AdaptiveParams {
    /// The depth cap: minimal chord length in parameter space is 2^-kMaxDepth.
    static constexpr int kMaxDepth = 20;
    static constexpr double kMinStep = 1.0 / double(1 << kMaxDepth);
    /// A probe with deviation in [kAccept tol, tol] is taken at once. 0.9 costs
    /// at most 1/sqrt(0.9) - 1 = 5% more chords than exact equality, and keeps
    /// the mean probe count near 2 (bench/flatten reports both).
    static constexpr double kAccept = 0.9;
    /// Aim inside the window rather than at its top edge, so rounding in the
    /// model does not push probes just above tol.
    static constexpr double kTarget = 0.95;
    /// Probes per chord before the largest flat one so far is taken.
    static constexpr int kMaxProbes = 6;
    /// The remainder is tested as a whole when the predicted chord is at least
    /// 1/kRestCheck of it. Predictions err by well under 2x except where the
    /// curvature changes abruptly, where a skipped test costs one extra chord.
    static constexpr double kRestCheck = 2.0;
};

/// The adaptive flattener as a range of FlatVertex (see flatten_adaptive for the callback form).
template <class Curve>
class AdaptiveFlattener : public FlatVertexRange<AdaptiveFlattener<Curve>> {
  public:
    /// The flattener constants.
    using P = AdaptiveParams;

    /// Flattens `c` to within `tolerance` (same units as the curve).
    AdaptiveFlattener(const Curve& c, double tolerance) noexcept : rest_(c), tol_(tolerance) {}

    /// Writes the next vertex; false once the end point has been emitted.
    bool next(FlatVertex& out) noexcept {
        if (done_) return false;
        const double span = 1.0 - t0_;
        // The whole remainder is tested only when the predicted chord could
        // reach its end: otherwise the prediction already says it is not flat.
        double guess = hint_ / span;
        if (hint_ == 0 || guess * P::kRestCheck >= 1.0 || span <= 2 * P::kMinStep) {
            const double e = chord_deviation(rest_);
            if (e <= tol_ || span <= 2 * P::kMinStep) {
                out = {rest_.end(), 1.0};
                done_ = true;
                return true;
            }
            if (hint_ == 0) guess = std::sqrt(P::kTarget * tol_ / e);
        }
        const double min_u = P::kMinStep / span;
        Split s = flat_prefix(std::clamp(guess, min_u, 0.98), min_u);
        balance_last_two(s);
        const double step = s.u * span;
        t0_ += step;
        // Predict the next chord's parameter length from this one's deviation.
        hint_ = s.dev > 0 ? step * std::sqrt(P::kTarget * tol_ / s.dev) : 2 * step;
        rest_ = s.halves[1];
        out = {rest_.start(), t0_};
        return true;
    }

  private:
    struct Split {
        std::array<Curve, 2> halves;
        double u = 0, dev = 0;
    };

    /// When the remainder ends in two chords (prefix and suffix both flat), a
    /// greedy prefix leaves a sliver as the last chord; two equal halves cost the
    /// same count and spread the deviation, so take them when both are flat.
    void balance_last_two(Split& s) const noexcept {
        if (s.u <= 0.5 || chord_deviation(s.halves[1]) > tol_) return;
        const auto halves = rest_.split(0.5);
        const double d0 = chord_deviation(halves[0]), d1 = chord_deviation(halves[1]);
        if (d0 <= tol_ && d1 <= tol_) s = {halves, 0.5, std::max(d0, d1)};
    }

    /// The safeguarded secant search described at the top of the file, from a
    /// first probe u; `min_u` is the depth cap in the remainder's parameter.
    Split flat_prefix(double u, double min_u) const noexcept {
        Split best{};
        bool have = false;
        double lo = 0, hi = 1;
        for (int probe = 0;; ++probe) {
            const auto halves = rest_.split(u);
            const double dev = chord_deviation(halves[0]);
            if (dev <= tol_) {
                best = {halves, u, dev};
                have = true;
                lo = u;
                if (dev >= P::kAccept * tol_) break;
            } else {
                hi = u;
            }
            if (have && probe + 1 >= P::kMaxProbes) break;
            if (u <= min_u) { // depth cap: take the minimal chord as it is
                if (!have) best = {halves, u, dev};
                break;
            }
            double next = dev > 0 ? u * std::sqrt(P::kTarget * tol_ / dev) : 0.5 * (u + hi);
            if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
            // Without any flat probe yet, at least halve: the model can be far
            // off near cusps, and this bounds the probes by kMaxDepth.
            if (!have && probe >= 1) next = std::min(next, 0.5 * hi);
            u = std::max(next, min_u);
        }
        return best;
    }

    Curve rest_;
    double tol_;
    double t0_ = 0;   ///< curve parameter at rest_.start()
    double hint_ = 0; ///< predicted parameter length of the next chord (0: none)
    bool done_ = false;
};

/// Sink form: sink(FlatVertex) for every vertex after the start.
template <class Curve, class Sink>
void flatten_adaptive(const Curve& c, double tolerance, Sink&& sink) noexcept {
    drain_flattener(AdaptiveFlattener<Curve>(c, tolerance), sink);
}

} // namespace casteljau
