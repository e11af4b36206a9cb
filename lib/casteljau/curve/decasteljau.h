// The de Casteljau construction and its relatives on control-point arrays.
//
// A degree-n Bezier curve B(t) = sum_i C(n,i) t^i (1-t)^(n-i) P_i is evaluated
// by repeated linear interpolation: P_i^(k) = lerp(P_i^(k-1), P_{i+1}^(k-1), t),
// B(t) = P_0^(n). The left edge of the triangle (P_0^(0), P_0^(1), ..., P_0^(n))
// is the control polygon of B on [0, t] and the right edge that of B on [t, 1]
// (Farin, "Curves and Surfaces for CAGD", 5th ed., section 4.6). The same code
// serves fixed degrees (compile-time extent, fully unrolled by the compiler) and
// runtime degrees (std::dynamic_extent, up to kMaxDegree), and any element type
// with a `lerp`: Point, Vec2 (hodographs) and HPoint (rational curves).
//
// Every function here is noexcept and allocation-free; the runtime-degree forms
// require p.size() <= kMaxDegree + 1.
#pragma once

#include "casteljau/geom/point.h"

#include <array>
#include <cstddef>
#include <span>
#include <utility>

namespace casteljau {

/// Highest degree of a general Bezier curve. Degree 24 is far beyond what
/// drawing and CAD data use (NURBS in practice stop at 7 to 9); beyond about
/// 25 the binomial coefficients of the Bernstein and power forms lose more
/// than half of double's mantissa, so higher degrees would be a false promise.
inline constexpr int kMaxDegree = 24;
inline constexpr std::size_t kMaxPoints = kMaxDegree + 1;

namespace detail {
template <class T, std::size_t E>
using Scratch = std::array<T, E == std::dynamic_extent ? kMaxPoints : E>;
}

template <class T, std::size_t E>
constexpr T decasteljau_eval(std::span<const T, E> p, double t) noexcept {
    detail::Scratch<T, E> q; // [0, n) only, each written before it is read
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) q[i] = p[i];
    for (std::size_t k = n - 1; k > 0; --k)
        for (std::size_t i = 0; i < k; ++i) q[i] = lerp(q[i], q[i + 1], t);
    return q[0];
}

/// Writes the control polygons of [0, t] and [t, 1]; left/right may not alias p.
template <class T, std::size_t E>
constexpr void decasteljau_split(std::span<const T, E> p, double t, std::span<T, E> left,
                                 std::span<T, E> right) noexcept {
    detail::Scratch<T, E> q; // [0, n) only, each written before it is read
    const std::size_t n = p.size();
    for (std::size_t i = 0; i < n; ++i) q[i] = p[i];
    left[0] = q[0];
    right[n - 1] = q[n - 1];
    for (std::size_t k = n - 1; k > 0; --k) {
        for (std::size_t i = 0; i < k; ++i) q[i] = lerp(q[i], q[i + 1], t);
        left[n - k] = q[0];
        right[k - 1] = q[k - 1];
    }
}

/// Control polygon of the piece [t0, t1]; t0 > t1 gives the piece reversed.
/// Two splits, ordered so that the second split's parameter is a ratio with a
/// denominator of at least 1/2: for lo < hi < 1/2, split at lo and then the
/// right part at (hi - lo) / (1 - lo); otherwise split at hi and then the left
/// part at lo / hi.
template <class T, std::size_t E>
constexpr void decasteljau_subsegment(std::span<const T, E> p, double t0, double t1,
                                      std::span<T, E> out) noexcept {
    detail::Scratch<T, E> a{}, b{};
    const std::size_t n = p.size();
    std::span<T, E> sa(a.data(), n), sb(b.data(), n);
    const double lo = t0 < t1 ? t0 : t1, hi = t0 < t1 ? t1 : t0;
    if (hi < 0.5) {
        decasteljau_split(p, lo, sa, sb); // sb = [lo, 1]
        decasteljau_split(std::span<const T, E>(sb), (hi - lo) / (1.0 - lo), out, sa);
    } else {
        decasteljau_split(p, hi, sa, sb); // sa = [0, hi]
        decasteljau_split(std::span<const T, E>(sa), lo / hi, sb, out);
    }
    if (t0 > t1)
        for (std::size_t i = 0, j = n - 1; i < j; ++i, --j) std::swap(out[i], out[j]);
}

/// Hodograph: the derivative of a degree-n curve is the degree-(n-1) Bezier curve
/// with vector coefficients n (P_{i+1} - P_i).
template <std::size_t E>
constexpr void hodograph(std::span<const Point, E> p, std::span<Vec2> out) noexcept {
    const std::size_t n = p.size() - 1;
    for (std::size_t i = 0; i < n; ++i) out[i] = (p[i + 1] - p[i]) * double(n);
}

/// Degree elevation (Farin 6.1): Q_i = (i/(n+1)) P_{i-1} + (1 - i/(n+1)) P_i.
/// `out` has p.size() + 1 entries.
template <std::size_t E>
constexpr void elevate_degree(std::span<const Point, E> p, std::span<Point> out) noexcept {
    const std::size_t n = p.size() - 1;
    out[0] = p[0];
    out[n + 1] = p[n];
    for (std::size_t i = 1; i <= n; ++i) out[i] = lerp(p[i], p[i - 1], double(i) / double(n + 1));
}

/// C(n, k) as a double; exact for every n <= kMaxDegree.
constexpr double binomial(int n, int k) noexcept {
    double r = 1;
    for (int i = 1; i <= k; ++i) r = r * double(n - k + i) / double(i);
    return r;
}

/// Direct Bernstein sum, with t^i and (1-t)^(n-i) built incrementally.
template <std::size_t E>
constexpr Point bernstein_eval(std::span<const Point, E> p, double t) noexcept {
    const int n = int(p.size()) - 1;
    const double s = 1.0 - t;
    std::array<double, kMaxPoints> spow{}; // spow[k] = s^k
    spow[0] = 1;
    for (int k = 1; k <= n; ++k) spow[k] = spow[k - 1] * s;
    double x = 0, y = 0, tp = 1;
    for (int i = 0; i <= n; ++i, tp *= t) {
        const double w = binomial(n, i) * tp * spow[n - i];
        x += w * p[i].x;
        y += w * p[i].y;
    }
    return {x, y};
}

/// Power-basis (monomial) coefficients: B(t) = c0 + sum_{j>=1} c_j t^j with
/// c_j = C(n,j) sum_{i<=j} (-1)^(j-i) C(j,i) P_i (the Bernstein-to-power basis
/// change matrix, Farin 4.3). `c` receives c_1..c_n.
template <std::size_t E>
constexpr Point power_coefficients(std::span<const Point, E> p, std::span<Vec2> c) noexcept {
    const int n = int(p.size()) - 1;
    for (int j = 1; j <= n; ++j) {
        Vec2 acc{};
        for (int i = 0; i <= j; ++i) {
            const double sign = ((j - i) & 1) ? -1.0 : 1.0;
            acc += (p[i] - p[0]) * (sign * binomial(j, i));
        }
        c[j - 1] = acc * binomial(n, j);
    }
    return p[0];
}

/// Horner evaluation of c0 + c_1 t + ... + c_n t^n.
constexpr Point horner_eval(Point c0, std::span<const Vec2> c, double t) noexcept {
    Vec2 acc{};
    for (std::size_t j = c.size(); j > 0; --j) acc = (acc + c[j - 1]) * t;
    return c0 + acc;
}

} // namespace casteljau
