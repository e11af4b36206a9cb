// The segment density of a curve: how many chords of deviation tol a
// polyline needs per unit of the curve parameter, and its integral, the
// chord count. The integral flattener (integral.h) spaces its vertices evenly
// in this integral.
//
// The density. A chord of a smooth curve over the parameter interval
// [m - h/2, m + h/2] deviates from the curve by
//   dev = h^2 |B'(m) x B''(m)| / (8 |B'(m)|) + O(h^3)
// (the k s^2 / 8 of a chord over arc length s = h |B'| at curvature
// k = |B' x B''| / |B'|^3; exact for a parabola). So with
//   w(t) = sqrt(|B'(t) x B''(t)| / (8 tol |B'(t)|))
// a chord over which w integrates to d deviates by about tol d^2, and
// I = integral_0^1 w is the count of the optimal polyline with vertices on the
// curve (Levien, "Flattening quadratic Beziers", 2019; testing::optimal_segments).
//
// The models, each with total(), integral_at(t) (the integral from 0),
// t_at(I) (its inverse; both monotone) and corner():
// - ParabolaDensity, quadratics: exact, through parabola.h's G
//   (w(u) = sqrt(|b| / (8 tol)) (1 + x(u)^2)^(-1/4) with the parabola's own
//   coordinate x, see parabola.h): Levien's method.
// - CubicDensity, cubics: there is no closed form. Levien's route, quadratics
//   approximating the cubic within a share of the tolerance, models w poorly
//   for the work: each quadratic's w is off where the cubic's curvature
//   varies across it (measured on the bench/flatten corpus at 0.25 px,
//   vertices placed on the cubic by each quadratic's exact G: with 5
//   quadratics a curve 37% of the chords came out over tol, with 10 22%, with
//   21 4%; with this flattener's corrections 10 quadratics gave 1.061x the
//   optimal count, the samples below 1.045x). Instead, w, w' and 1 / w are sampled at
//   kDensityPanels + 1 even parameters (a division and two square roots a
//   sample, SSE2 pairs); a panel's integral is the trapezoid corrected by the
//   end slopes, and t(I) on it the cubic Hermite through its ends with slopes
//   dt/dI = 1 / w: t_at costs a vertex a polynomial, no square root and no
//   division. Smooth stretches come out within 1e-4 of the true integral
//   (quarter circles); a peak of w between samples (loops' apexes) or an
//   inflection's square-root zero within a few percent
//   (tests/flatten/integral_test.cpp).
// The cubic term. Where B' x B'' vanishes (an inflection) w does too, yet a
// chord across it deviates by the cubic term of the curve: over [m - L, m + L]
// by (2 / (3 sqrt 3)) |B' x B'''| L^3 / (6 |B'|), so chords of deviation tol have
// the density w3 = cbrt(|B' x B'''| / (9 sqrt(3) |B'| tol)) / 2. A sample takes
// max(w, w3) (density.cpp): on the bench/flatten corpus at 0.25 px the near
// cusps' chords over tol went from 1.28 a curve to none, their probes from 4.6
// to 0.7, the count from 1.045x to 1.043x the optimum, the time a curve from
// 0.71 to 0.69 us (0.1 px: 1.05 to 1.00 us); the S-curves' corrections stay
// (1.2 a curve to 1.14: their chords fail the tolerance by a few percent, the
// model's own error, more than at the inflection).
// Neither model has to be exact: the flattener checks every chord and corrects
// the few that a model misplaces.
//
// Corners. Where the curve turns by a large angle within less than the
// tolerance (a cusp, a near cusp, a collinear curve's turning point), no
// density helps: a chord across the turn deviates by the size of the legs,
// whatever w integrates to, and the optimal polyline has a vertex at the turn.
// So a speed minimum whose radius of curvature is below kCornerRadius tol is
// a corner, where the flattener puts a vertex and plans each side on its own
// (on the bench/flatten corpus it takes the near cusps from 3.1 corrections a
// curve to 1.7, and their count from 1.083x to 1.080x the optimum; the corner
// must be exact: found to 1e-9 only, the corpus's count rose by 0.1%).
//
// Degenerate curves (straight, collinear, a point) have w = 0 and I = 0:
// their one planned chord is checked like every other.
#pragma once

#include "casteljau/curve/bez.h"
#include "casteljau/flatten/parabola.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

/// A line: no curvature, no chords beyond the one.
struct LineDensity {
    /// The density of a line (nothing to measure).
    LineDensity(const PowerCurve<1>&, double) noexcept {}
    /// The integral of w over [0, 1].
    double total() const noexcept { return 0; }
    /// The integral of w over [0, t].
    double integral_at(double) const noexcept { return 0; }
    /// The parameter where the integral reaches I.
    double t_at(double) const noexcept { return 1; }
    /// No corner.
    double corner() const noexcept { return 1; }
};

/// A corner: a speed minimum whose radius of curvature is below this many
/// tolerances (top of the file). Measured on the bench/flatten corpus: 0.5 to
/// 2 split the same near-cusps; 4 and more also split loops' apexes, costing
/// an extra chord's rounding there.
inline constexpr double kCornerRadius = 1.0;

/// The exact density of a quadratic (top of the file and parabola.h).
class ParabolaDensity {
  public:
    /// The density of the quadratic with power-basis coefficients pc, at tolerance tol > 0.
    ParabolaDensity(const PowerCurve<2>& pc, double tol) noexcept {
        const Vec2 a = pc.c[0], b = pc.c[1] * 2.0; // B'(0) and B''
        const double c = std::fabs(b.cross(a)), b_sq = b.length_sq();
        // The apex, where B' is least (B' . B'' = 0), is a corner (the cubics'
        // kCornerRadius, below) when its radius of curvature c^2 / |b|^3 is
        // below kCornerRadius tol; a collinear quadratic's turning point is one.
        const double apex = b_sq > 0 ? -b.dot(a) / b_sq : 1.0, r = kCornerRadius * tol;
        if (apex > 0 && apex < 1 && c * c * c * c <= r * r * b_sq * b_sq * b_sq) corner_ = apex;
        // x(u) = b . B'(u) / |c| reaches |b| max|B'| / |c|: beyond 1e9 the
        // parabola is a line to within 1e-9 of its size, whose few chords the
        // flattener's check places, and x^2 stays far from overflow.
        const double reach = std::sqrt(b_sq) * std::max(a.length(), (a + b).length());
        if (!(c > 1e-9 * reach)) return;
        x0_ = b.dot(a) / c;
        dx_ = b_sq / c; // x(u) = x0 + dx u
        inv_dx_ = c / b_sq;
        scale_ = c / std::sqrt(b_sq * std::sqrt(b_sq) * 8 * tol);
        inv_scale_ = 1 / scale_;
        g0_ = parabola_integral(x0_);
        total_ = scale_ * (parabola_integral(x0_ + dx_) - g0_);
    }
    /// The integral of w over [0, 1].
    double total() const noexcept { return total_; }
    /// The parameter of a corner (see CubicDensity), or 1 when there is none.
    double corner() const noexcept { return corner_; }
    /// The integral of w over [0, t].
    double integral_at(double t) const noexcept {
        return total_ > 0 ? scale_ * (parabola_integral(x0_ + dx_ * t) - g0_) : 0;
    }
    /// The parameter where the integral reaches I, in [0, 1].
    double t_at(double I) const noexcept {
        const double x = parabola_integral_inverse(g0_ + I * inv_scale_);
        return std::clamp((x - x0_) * inv_dx_, 0.0, 1.0);
    }

  private:
    double x0_ = 0, dx_ = 1, inv_dx_ = 1, scale_ = 0, inv_scale_ = 0, g0_ = 0, total_ = 0;
    double corner_ = 1.0;
};

/// Panels of the cubic's density model: 9 samples a curve. Measured on the
/// bench/flatten corpus at 0.25 px (before corners were split off), the share
/// of chords the flattener had to correct: 4 panels 25%, 6 panels 14%, 8
/// panels 9%, 16 panels 5% at twice the sampling work (what remains is
/// inflections and corners, which no sampling resolves).
inline constexpr int kDensityPanels = 8;

/// The density model of a cubic (top of the file).
class CubicDensity {
  public:
    /// The density of the cubic with power-basis coefficients pc, at tolerance tol > 0.
    CubicDensity(const PowerCurve<3>& pc, double tol) noexcept {
        Samples w, dw, inv_w, speed_sq;
        const int slowest = sample(pc, tol, w, dw, inv_w, speed_sq);
        cum_[0] = 0;
        for (std::size_t i = 0; i < kDensityPanels; ++i) {
            // The trapezoid rule corrected by the end slopes (exact for a cubic
            // w), the correction kept within a third of the trapezoid: beside an
            // inflection w' is unbounded, and the true integral of w ~ sqrt(t)
            // is 4/3 of its trapezoid.
            const double trap = (w[i] + w[i + 1]) * (0.5 * kH);
            const double fix =
                std::clamp((dw[i] - dw[i + 1]) * (kH * kH / 12), -trap / 3, trap / 3);
            const double mass = trap + fix;
            cum_[i + 1] = cum_[i] + mass;
            inv_mass_[i] = mass > 0 ? 1 / mass : 0;
            // t(I) on the panel: the cubic Hermite with slopes dt/dI = 1 / w at
            // its ends, as multiples of the panel's mean slope kH / mass,
            // capped at 3, which keeps it monotone (Fritsch and Carlson, SIAM
            // J. Numer. Anal. 17(2), 1980: slopes in [0, 3] times the secant).
            const double a = std::min(mass * inv_w[i] * kDensityPanels, 3.0);
            const double b = std::min(mass * inv_w[i + 1] * kDensityPanels, 3.0);
            shape_[i] = {a, 3 - 2 * a - b, a + b - 2};
        }
        find_corner(pc, tol, slowest, speed_sq);
    }
    /// The integral of w over [0, 1].
    double total() const noexcept { return cum_[kDensityPanels]; }
    /// The parameter of a corner (top of the file), or 1 when there is none.
    double corner() const noexcept { return corner_; }
    /// The integral of w over [0, t]: the inverse of t_at, by Newton's method
    /// on the panel's cubic, kept in its bracket (for the flattener's
    /// corrections, not per vertex).
    double integral_at(double t) const noexcept {
        const std::size_t i = std::size_t(std::min(kDensityPanels - 1, int(t * kDensityPanels)));
        const double x = t * kDensityPanels - double(i);
        const Shape& c = shape_[i];
        double s = x, lo = 0, hi = 1;
        for (int step = 0; step < 16; ++step) {
            const double f = s * (c[0] + s * (c[1] + s * c[2])) - x;
            (f < 0 ? lo : hi) = s;
            const double slope = c[0] + s * (2 * c[1] + s * (3 * c[2]));
            double next = slope > 0 ? s - f / slope : 0.5 * (lo + hi);
            if (!(next >= lo && next <= hi)) next = 0.5 * (lo + hi);
            const bool close = std::fabs(next - s) <= 1e-13;
            s = next;
            if (close) break;
        }
        return cum_[i] + (cum_[i + 1] - cum_[i]) * s;
    }
    /// The parameter where the integral reaches I, in [0, 1]: no square root
    /// and no division, so that it costs a vertex little.
    double t_at(double I) const noexcept {
        // The panel by counting the panel ends at or below I, without a
        // branch: a walk's exit is data (how many chords a panel holds), and
        // mispredicted it cost a third of the flattener's branch misses.
        int panel = 0;
        for (std::size_t k = 1; k < kDensityPanels; ++k) panel += int(I >= cum_[k]);
        const std::size_t i = std::size_t(panel);
        const double s = std::clamp((I - cum_[i]) * inv_mass_[i], 0.0, 1.0);
        const Shape& c = shape_[i];
        return std::min((double(panel) + s * (c[0] + s * (c[1] + s * c[2]))) * kH, 1.0);
    }

  private:
    static constexpr double kH = 1.0 / kDensityPanels;
    using Samples = std::array<double, kDensityPanels + 1>;

    /// w, w', 1 / w and |B'|^2 at the panel ends; returns the sample where the speed is least.
    static int sample(const PowerCurve<3>& pc, double tol, Samples& w, Samples& dw, Samples& inv_w,
                      Samples& speed_sq) noexcept;
    /// Sets corner_ when the speed has an interior minimum near sample
    /// `slowest` whose radius of curvature is below kCornerRadius tol.
    void find_corner(const PowerCurve<3>& pc, double tol, int slowest,
                     const Samples& speed_sq) noexcept;

    using Shape = std::array<double, 3>; // t(I) on a panel: s (c0 + s (c1 + s c2)), s in [0, 1]
    std::array<double, kDensityPanels + 1> cum_;
    std::array<double, kDensityPanels> inv_mass_;
    std::array<Shape, kDensityPanels> shape_;
    double corner_ = 1.0;
};

/// The density model of each curve type the integral flattener takes.
template <int N>
struct DensityOf;
/// Lines.
template <>
struct DensityOf<1> {
    using type = LineDensity; ///< the model
};
/// Quadratics.
template <>
struct DensityOf<2> {
    using type = ParabolaDensity; ///< the model
};
/// Cubics.
template <>
struct DensityOf<3> {
    using type = CubicDensity; ///< the model
};

} // namespace casteljau
