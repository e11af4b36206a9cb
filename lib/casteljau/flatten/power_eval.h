// A Bez<N> and its derivative evaluated in the power basis, as the flatteners
// that build pieces from their ends (guided.h, integral.h) need them at every
// vertex.
//
// B and B' by Horner's rule, x and y side by side in one SSE2 register (GCC's
// and Clang's vector extension): the flatteners spend most of their
// instructions here, and the plain Vec2 code compiled to scalar operations,
// one per coordinate. The operations and their order are those of
// PowerCurve::eval (horner_eval), so the same bits: 0.92x the instructions of
// the guided flattener on the bench/flatten corpus (callgrind). At t = 1 the
// end point and the end derivative are the control points' own (exact), not
// the power basis's sums.
#pragma once

#include "casteljau/curve/bez.h"

#include <array>

namespace casteljau {

/// B(t) and B'(t) of a Bez<N> in the power basis.
template <int N>
class PowerEval {
  public:
    /// A point of the curve and the derivative there.
    struct Sample {
        Point p; ///< B(t)
        Vec2 d;  ///< B'(t)
    };

    /// The evaluator of c.
    explicit PowerEval(const Bez<N>& c) noexcept : power_(c.power()), end_(c.end()) {
        for (int j = 0; j < N; ++j) dpower_[j] = power_.c[j] * double(j + 1);
        end_deriv_ = (c.p[N] - c.p[N - 1]) * double(N);
    }
    /// B(t), by the power basis; at t = 1 the exact end point (the sum
    /// rounds there), so a flattener's last vertex is the curve's end bit for bit.
    /// This and at() are inlined by force: they are every flattener's
    /// per-vertex work, which a call would double (guided.h's probe).
    [[gnu::always_inline]] Point point(double t) const noexcept {
        if (t == 1.0) return end_;
        const Pair tt = {t, t};
        Pair a = {0, 0};
        for (int j = N; j > 0; --j) a = (a + pair(power_.c[std::size_t(j - 1)])) * tt;
        return power_.c0 + Vec2{a[0], a[1]};
    }
    /// B(t) and B'(t); at t = 1 the exact end point and end derivative.
    [[gnu::always_inline]] Sample at(double t) const noexcept {
        if (t == 1.0) return {end_, end_deriv_};
        const Pair tt = {t, t};
        Pair d = pair(dpower_[N - 1]);
        for (int j = N - 2; j >= 0; --j) d = d * tt + pair(dpower_[std::size_t(j)]);
        return {point(t), Vec2{d[0], d[1]}};
    }
    /// B(0) and B'(0).
    Sample start() const noexcept { return {power_.c0, power_.c[0]}; }
    /// The end point, exact.
    Point end() const noexcept { return end_; }
    /// The curve in the power basis.
    const PowerCurve<N>& power() const noexcept { return power_; }

  private:
    typedef double Pair __attribute__((vector_size(16)));
    static Pair pair(Vec2 a) noexcept { return Pair{a.x, a.y}; }
    PowerCurve<N> power_;
    std::array<Vec2, N> dpower_; ///< B' in the power basis
    Point end_;                  ///< exact at t = 1, not the power basis's sum
    Vec2 end_deriv_;
};

} // namespace casteljau
