// Levien's flattener ("Flattening quadratic Beziers", 2019), the method of
// kurbo and lyon: the known route to a near-optimal count, kept as the
// baseline the integral flattener (integral.h) is measured against
// (bench/flatten, `flatten/levien/...`). It is not used for drawing.
//
// Quadratics. Every quadratic is a piece of the parabola y = x^2, moved,
// turned and scaled by s. On it a chord of a short stretch dx at x deviates
// by about dx^2 / (4 (1 + 4x^2)^(1/2)) (Levien's k s^2 / 8), so the count of
// chords of deviation tol is
//   n = sqrt(s) (A(x2) - A(x0)) / (2 sqrt(tol)),  A(x) = integral_0^x (1 + 4u^2)^(-1/4) du,
// the vertices evenly spaced in A. (A(x) = G(2x) / 2 with parabola.h's G.)
// Levien's closed forms, with the constants he fitted:
//   A(x)    ~ x / (1 - D + (D^4 + x^2 / 4)^(1/4)),  D = 0.67
//   A^-1(a) ~ a (1 - B + (B^2 + a^2 / 4)^(1/2)),    B = 0.39
// For the quadratic P0, P1, P2 with d01 = P1 - P0, d12 = P2 - P1 and
// dd = d01 - d12 (the parabola's axis) and cross = (P2 - P0) x dd, the ends
// lie at x0 = d01 . dd / cross and x2 = d12 . dd / cross (x is linear in the
// curve parameter), and s = |cross| / (|dd| |x2 - x0|). A quadratic whose
// apex lies between its ends (x0, x2 of opposite signs) is counted by
// Levien's cusp rule: its integral scaled by sqrt(tol) / A(sqrt(tol / s)),
// which bounds the count of a sharp turn by that of a chord through it.
//
// Cubics. Cut into m quadratics of equal parameter length, each with the
// control point (3 (Q1 + Q2) - Q0 - Q3) / 4 of the cubic's piece Q, within
// sqrt(3) / 36 |P3 - 3 P2 + 3 P1 - P0| / m^3 of the piece; m is the least
// that makes this kQuadShare tol. The count is taken over all the
// quadratics at once, n = ceil(sum of their counts), and the vertices evenly
// spaced in the summed integral, as kurbo does. Unlike kurbo, which emits
// the quadratics' points, the vertices are the cubic's points at the
// quadratics' parameters: on the curve, as every flattener here emits.
//
// No chord is checked, so the tolerance is met only as far as the model fits.
// Where the curvature keeps its sign the closed forms hold it to a few
// percent; across an inflection a quadratic has no curvature to count, and
// the chords there deviate up to 1.5x the tolerance (bench/flatten corpus,
// tests/flatten/levien_test.cpp). The count is the model's alone: no search,
// no correction, no corner handling.
//
// Limits. At most kLevienMaxQuads quadratics are planned together; a longer
// cubic (a third difference over 64^3 * 2.08 = 5.4e5 tolerances) is planned in
// chunks of that many, each ending on a vertex. At most kMaxUniformSegments
// chords a chunk.
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/flatten/power_eval.h"
#include "casteljau/flatten/uniform.h"
#include "casteljau/flatten/vertex.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

/// The share of the tolerance the quadratics may stray from the cubic:
/// kurbo's (lyon takes 0.2). The vertices lie on the cubic, so the share buys
/// the count model's fit, not positions; and finer quadratics do not cure
/// the model's overshoot at inflections (measured on the bench/flatten corpus
/// at 0.25 px, the worst error over the S-curves: 1.21 tol at 0.02, 1.41 at
/// 0.05, 1.39 at 0.1, 1.21 at 0.2, 1.79 at 0.4; over the near-cusps 3.5 tol
/// at 0.02, 1.06 at 0.1).
inline constexpr double kQuadShare = 0.1;
/// Quadratics planned together at most (the top of the file).
inline constexpr int kLevienMaxQuads = 64;

namespace levien_detail {
inline constexpr double kD = 0.67; // Levien's fitted constants
inline constexpr double kB = 0.39;

/// Levien's A(x) (top of the file).
inline double integral(double x) noexcept {
    return x / (1 - kD + std::sqrt(std::sqrt(kD * kD * kD * kD + 0.25 * x * x)));
}
/// Levien's A^-1(a).
inline double inverse(double a) noexcept {
    return a * (1 - kB + std::sqrt(kB * kB + 0.25 * a * a));
}

/// One quadratic's plan: its count `val` (in units of 2 sqrt(tol) chords)
/// and its parameter as a function of the fraction u of its integral.
struct QuadPlan {
    double a0 = 0, da = 0, u0 = 0, u_scale = 0, val = 0;

    QuadPlan() = default;
    /// The plan of the quadratic p0, p1, p2 at sqrt(tol) = sqrt_tol. A
    /// straight one (no finite scale) gets val = 0 and t_at(u) = 0.
    QuadPlan(Point p0, Point p1, Point p2, double sqrt_tol) noexcept {
        const Vec2 d01 = p1 - p0, d12 = p2 - p1, dd = d01 - d12;
        const double cross = (p2 - p0).cross(dd);
        const double x0 = d01.dot(dd) / cross, x2 = d12.dot(dd) / cross;
        const double scale = std::fabs(cross / (dd.length() * (x2 - x0)));
        if (!std::isfinite(scale)) return;
        const double sqrt_scale = std::sqrt(scale);
        a0 = integral(x0);
        const double a2 = integral(x2);
        da = a2 - a0;
        if ((x0 < 0) == (x2 < 0))
            val = std::fabs(da) * sqrt_scale;
        else
            val = sqrt_tol * std::fabs(da) / integral(sqrt_tol / sqrt_scale);
        u0 = inverse(a0);
        u_scale = 1 / (inverse(a2) - u0);
    }
    /// The quadratic's parameter where the fraction u of its integral is reached.
    double t_at(double u) const noexcept {
        return std::clamp((inverse(a0 + da * u) - u0) * u_scale, 0.0, 1.0);
    }
};
} // namespace levien_detail

/// The quadratics Levien's flattener cuts `c` into at `tolerance` (top of the
/// file): the least m with sqrt(3) / 36 |P3 - 3 P2 + 3 P1 - P0| / m^3 <=
/// kQuadShare tol, at most kMaxUniformSegments.
inline int levien_quadratics(const CubicBez& c, double tolerance) noexcept {
    const Vec2 d3 = (c.p[3] - c.p[0]) + (c.p[1] - c.p[2]) * 3.0;
    const double k = kQuadShare * 36 / std::sqrt(3.0);
    const double m = std::ceil(std::cbrt(d3.length() / (k * tolerance)));
    return !(m > 1) ? 1 : m >= kMaxUniformSegments ? kMaxUniformSegments : int(m);
}

/// Levien's flattener of a cubic as a range of FlatVertex (see
/// flatten_levien for the sink form).
class LevienFlattener : public FlatVertexLoop<LevienFlattener> {
  public:
    /// Flattens `c` to about `tolerance` > 0 (same units as the curve).
    LevienFlattener(const CubicBez& c, double tolerance) noexcept
        : eval_(c), sqrt_tol_(std::sqrt(tolerance)), quads_(levien_quadratics(c, tolerance)) {
        plan_chunk();
    }

  private:
    friend FlatVertexLoop<LevienFlattener>;
    template <class Emit>
    bool run(Emit&& emit) noexcept {
        while (chunk_ < quads_) {
            while (i_ < n_) { // the chunk's inner vertices
                const double target = step_ * double(i_++);
                while (q_ + 1 < count_ && target >= passed_ + plans_[std::size_t(q_)].val)
                    passed_ += plans_[std::size_t(q_++)].val;
                const auto& plan = plans_[std::size_t(q_)];
                const double u = plan.val > 0 ? (target - passed_) / plan.val : 0;
                const double t = (double(chunk_ + q_) + plan.t_at(u)) * h_;
                if (!emit(FlatVertex{eval_.point(t), t})) return true;
            }
            chunk_ += count_;
            const bool last = chunk_ >= quads_;
            const double t = last ? 1.0 : double(chunk_) * h_;
            if (!last) plan_chunk();
            if (!emit(FlatVertex{eval_.point(t), t})) return true;
        }
        return false;
    }

    /// Plans the quadratics from chunk_ on: their counts, summed, and the step.
    void plan_chunk() noexcept {
        h_ = 1.0 / double(quads_);
        count_ = std::min(kLevienMaxQuads, quads_ - chunk_);
        double sum = 0;
        auto a = eval_.at(double(chunk_) * h_);
        for (int j = 0; j < count_; ++j) {
            const int k = chunk_ + j + 1;
            const auto b = eval_.at(k == quads_ ? 1.0 : double(k) * h_);
            // The piece's quadratic control point (top of the file), from the
            // ends' derivatives: Q1 = Q0 + h B'(t0) / 3, Q2 = Q3 - h B'(t1) / 3.
            const Point mid = lerp(a.p, b.p, 0.5) + (a.d - b.d) * (0.25 * h_);
            plans_[std::size_t(j)] = levien_detail::QuadPlan(a.p, mid, b.p, sqrt_tol_);
            sum += plans_[std::size_t(j)].val;
            a = b;
        }
        const double n = std::ceil(0.5 * sum / sqrt_tol_);
        n_ = !(n > 1) ? 1 : n >= kMaxUniformSegments ? kMaxUniformSegments : int(n);
        step_ = sum / n_;
        i_ = 1, q_ = 0, passed_ = 0;
    }

    PowerEval<3> eval_;
    double sqrt_tol_;
    int quads_; ///< all the quadratics
    double h_ = 1, step_ = 0, passed_ = 0;
    int chunk_ = 0, count_ = 0; ///< the chunk's first quadratic and its count
    int n_ = 1, i_ = 1, q_ = 0; ///< the chunk's chords, the next vertex, its quadratic
    std::array<levien_detail::QuadPlan, kLevienMaxQuads> plans_{};
};

/// Sink form: sink(FlatVertex) for every vertex after the start.
template <class Sink>
void flatten_levien(const CubicBez& c, double tolerance, Sink&& sink) noexcept {
    LevienFlattener(c, tolerance).drain(sink);
}

} // namespace casteljau
