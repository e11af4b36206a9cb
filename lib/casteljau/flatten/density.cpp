#include "casteljau/flatten/density.h"

#include <cfloat>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace casteljau {

namespace {

// Two samples at a time, x and y of B' in one SSE2 register each (GCC's and
// Clang's vector extension): the sampling is a division, two square roots
// and another division a sample, which the packed forms halve.
typedef double Pair __attribute__((vector_size(16)));
typedef long long Mask __attribute__((vector_size(16)));

Pair sqrt_pair(Pair x) noexcept {
#if defined(__SSE2__)
    return Pair(_mm_sqrt_pd(__m128d(x)));
#else
    return Pair{std::sqrt(x[0]), std::sqrt(x[1])};
#endif
}

// The cubic's hodograph in the power basis: B'(t) = d0 + d1 t + d2 t^2,
// B''(t) = d1 + 2 d2 t, B'''(t) = f = 2 d2.
struct Hodograph {
    Vec2 d0, d1, d2, f;
    explicit Hodograph(const PowerCurve<3>& pc) noexcept
        : d0(pc.c[0]), d1(pc.c[1] * 2.0), d2(pc.c[2] * 3.0), f(d2 * 2.0) {}
    Vec2 deriv(double t) const noexcept { return d0 + (d1 + d2 * t) * t; }
    Vec2 deriv2(double t) const noexcept { return d1 + d2 * (2 * t); }
};

// The cubic term of the density (density.h): where the curve bends little
// and its third derivative dominates (beside inflections, near cusps),
// w3 = cbrt(|B' x B'''| / (9 sqrt(3) |B'| tol)) / 2 replaces w when larger,
// with no slope (w' of the other term would mislead the panel's correction).
// The test w3 > w is taken in twelfth powers, q3^4 |B'|^2 tol^2 > (243 * 64 /
// 512)^2 |q|^6 with q = B' x B'' and q3 = B' x B''', so that the square root
// and the cube root are paid only where w3 may be taken.
void take_cubic_term(double q, double q3, double p, double tol, double& w, double& dw,
                     double& inv_w) noexcept {
    constexpr double k9r3 = 15.588457268119896; // 9 sqrt(3)
    const double q3t = q3 * q3 * tol, q_3 = q * q * q;
    if (!(p > 0) || !(q3t * q3t * p > (30.375 * 30.375) * q_3 * q_3)) return;
    const double w3 = 0.5 * std::cbrt(std::fabs(q3) / (k9r3 * std::sqrt(p) * tol));
    if (!(w3 > w)) return;
    w = w3, dw = 0, inv_w = 1 / w3;
}

} // namespace

int CubicDensity::sample(const PowerCurve<3>& pc, double tol, Samples& w, Samples& dw,
                         Samples& inv_w, Samples& speed_sq) noexcept {
    const Hodograph hd(pc);
    const Vec2 d0 = hd.d0, d1 = hd.d1, d2 = hd.d2, f = hd.f;
    const double k = 1 / std::sqrt(8 * tol);
    const Pair zero = {0, 0}, one = {1, 1};
    int slowest = 0;
    double least = DBL_MAX;
    for (std::size_t i = 0; i <= kDensityPanels; i += 2) {
        const Pair t = {double(i) * kH, double(i + 1) * kH}; // the second past 1 at the end
        const Pair dx = d0.x + (d1.x + d2.x * t) * t, dy = d0.y + (d1.y + d2.y * t) * t;
        const Pair ex = d1.x + (2 * d2.x) * t, ey = d1.y + (2 * d2.y) * t;
        const Pair q = dx * ey - dy * ex, p = dx * dx + dy * dy;
        // Where q p = 0 the curve is straight, or has a cusp: w = 0 there
        // (integral.h finds cusps), and 1 / w a finite stand-in for infinity
        // (times a panel's mass: 0 for none, else past the cap of 3).
        const Mask live = (q != zero) & (p != zero);
        // One division for w, w' and 1 / w: w^4 = q^2 / p / (64 tol^2) =
        // q^3 A k^4 and w'/w = q' / (2q) - (B' . B'') / (2p) = (q' p - q B' . B'') A / 2,
        // with A = 1 / (q p) and q' = B' x B'''.
        const Pair A = one / (live ? q * p : one);
        const Pair root = sqrt_pair(sqrt_pair(live ? q * q * q * A : zero)) * k;
        const Pair slope = root * ((dx * f.y - dy * f.x) * p - q * (dx * ex + dy * ey)) * (0.5 * A);
        const Pair inverse = live ? one / (live ? root : one) : Pair{DBL_MAX, DBL_MAX};
        const Pair q3 = dx * f.y - dy * f.x; // B' x B'''
        for (std::size_t j = 0; j < 2 && i + j <= kDensityPanels; ++j) {
            w[i + j] = root[j];
            dw[i + j] = live[j] ? slope[j] : 0;
            inv_w[i + j] = inverse[j];
            speed_sq[i + j] = p[j];
            if (p[j] < least) least = p[j], slowest = int(i + j);
            take_cubic_term(q[j], q3[j], p[j], tol, w[i + j], dw[i + j], inv_w[i + j]);
        }
    }
    return slowest;
}

void CubicDensity::find_corner(const PowerCurve<3>& pc, double tol, int slowest,
                               const Samples& speed_sq) noexcept {
    const Hodograph hd(pc);
    const double r = kCornerRadius * tol;
    // A corner has |B'|^2 <= r |B''| at its minimum (below: |B' x B''| <= |B'| |B''|).
    // Most curves' speed stays far above that: the parabola through the three
    // samples around the slowest estimates the minimum, and a search starts
    // only when the estimate is within 16 times of it (a miss costs the
    // flattener corrections, never a wrong chord).
    const std::size_t k = std::size_t(std::clamp(slowest, 1, kDensityPanels - 1));
    const double a = speed_sq[k - 1], b = speed_sq[k], c = speed_sq[k + 1];
    const double curv = a - 2 * b + c; // twice the parabola's t^2 coefficient, in samples
    const double least = curv > 0 ? b - (c - a) * (c - a) / (8 * curv) : std::min({a, b, c});
    const double bend = std::max(hd.deriv2(double(k - 1) * kH).length_sq(),
                                 hd.deriv2(double(k + 1) * kH).length_sq()); // |B''|^2 at most
    if (least > 0 && least * least > 256 * r * r * bend) return;
    // |B'|^2 has a minimum inside the samples around the slowest one when
    // g = B' . B'' (half its derivative) changes sign from - to + there.
    double lo = double(std::max(slowest - 1, 0)) * kH;
    double hi = double(std::min(slowest + 1, kDensityPanels)) * kH;
    if (!(hd.deriv(lo).dot(hd.deriv2(lo)) < 0 && hd.deriv(hi).dot(hd.deriv2(hi)) > 0)) return;
    // Newton's method on g from the parabola's minimum (the estimate above,
    // a closer start than the bracket's middle: 10% fewer steps on the
    // bench/flatten corpus), kept inside the bracket (bisection when it
    // leaves): g' = |B''|^2 + B' . B''' > 0 near a minimum, so it converges in
    // a few steps; the corner need not be exact, only where the curve turns.
    double t = curv > 0 ? (double(k) + (a - c) / (2 * curv)) * kH : 0.5 * (lo + hi);
    if (!(t > lo && t < hi)) t = 0.5 * (lo + hi);
    for (int step = 0; step < 40; ++step) {
        const Vec2 d = hd.deriv(t), e = hd.deriv2(t);
        const double g = d.dot(e), slope = e.length_sq() + d.dot(hd.f);
        (g < 0 ? lo : hi) = t;
        const double next = slope > 0 ? t - g / slope : 0.5 * (lo + hi);
        const bool inside = next > lo && next < hi;
        // Converged: tested before the bracket, which t itself bounds once g
        // rounds to 0 there (hi = t), so that such a step is not taken for
        // one leaving the bracket (it bisected 37 times more, to the same t:
        // 11.8 steps a search on the bench/flatten corpus, 3.8 since).
        if (std::fabs(next - t) <= 1e-15) {
            if (inside) t = next;
            break;
        }
        t = inside ? next : 0.5 * (lo + hi);
    }
    // The radius of curvature |B'|^3 / |B' x B''| below kCornerRadius tol, as
    // squares; an exact cusp (B' = 0) is a corner.
    const Vec2 d = hd.deriv(t);
    const double p = d.length_sq(), q = d.cross(hd.deriv2(t));
    if (t > 0 && t < 1 && p * p * p <= r * r * q * q) corner_ = t;
}

} // namespace casteljau
