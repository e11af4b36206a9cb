#include "casteljau/curve/roots.h"

#include "casteljau/curve/decasteljau.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace casteljau {

int solve_quadratic(double a, double b, double c, double roots[2]) noexcept {
    // |a| this small against b and c means the t^2 term cannot matter for
    // parameters in a bounded range: treat the equation as linear.
    const double scale = std::fabs(b) + std::fabs(c);
    if (std::fabs(a) <= 1e-14 * scale || a == 0.0) {
        if (b == 0.0) return 0;
        roots[0] = -c / b;
        return 1;
    }
    const double disc = b * b - 4.0 * a * c;
    if (disc < 0.0) return 0;
    if (disc == 0.0) {
        roots[0] = -b / (2.0 * a);
        return 1;
    }
    const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    double r0 = q / a, r1 = q != 0.0 ? c / q : -r0;
    if (r0 > r1) std::swap(r0, r1);
    roots[0] = r0;
    roots[1] = r1;
    return 2;
}

namespace {

// A Bernstein coefficient value, so the generic de Casteljau code can split it.
// No initializer: the stack of pieces below is 9 KB, which a default would
// zero on every call (a third of a point-in-fill test's time).
struct Scalar {
    double v;
};
constexpr Scalar lerp(Scalar a, Scalar b, double t) { return {(1.0 - t) * a.v + t * b.v}; }

struct Piece {
    std::array<Scalar, kMaxPoints> c;
    double t0, t1;
    int depth;
};

bool has_sign_change(const Piece& p, std::size_t n) {
    bool neg = false, pos = false;
    for (std::size_t i = 0; i < n; ++i) {
        neg |= p.c[i].v <= 0.0;
        pos |= p.c[i].v >= 0.0;
    }
    return neg && pos;
}

// Whether the piece holds exactly one root, a simple one (roots.h): its ends
// are nonzero and of opposite signs, and its coefficients change sign once,
// zeros skipped.
bool isolates_one_root(const Piece& p, std::size_t n) {
    // Signs, not the product, which underflows to -0 for tiny coefficients.
    const double first = p.c[0].v, end = p.c[n - 1].v;
    if (first == 0.0 || end == 0.0 || (first < 0.0) == (end < 0.0)) return false;
    int changes = 0;
    double last = p.c[0].v;
    for (std::size_t i = 1; i < n; ++i) {
        const double v = p.c[i].v;
        if (v == 0.0) continue;
        changes += (v < 0.0) != (last < 0.0);
        last = v;
    }
    return changes == 1;
}

// de Casteljau on the first n values of b, in place.
template <std::size_t N>
double casteljau(std::array<double, N>& b, std::size_t n, double t) noexcept {
    for (std::size_t r = n - 1; r > 0; --r)
        for (std::size_t i = 0; i < r; ++i) b[i] = (1.0 - t) * b[i] + t * b[i + 1];
    return b[0];
}

// The same on N values in registers: with N a constant the loops unroll and
// nothing is stored. (The loop over a buffer of any length vectorizes into
// loads of pairs that straddle the pairs its last level stored, a
// store-forwarding stall each: a third of a point-in-fill test's samples.)
template <std::size_t N>
double bernstein_value_of(const double* c, double t) noexcept {
    std::array<double, N> b;
    std::copy_n(c, N, b.begin());
    return casteljau(b, N, t);
}

} // namespace

double bernstein_value(std::span<const double> c, double t) noexcept {
    switch (c.size()) { // the degrees hit testing meets: up to 8 (nearest.h)
    case 0:
        return 0;
    case 1:
        return c[0];
    case 2:
        return bernstein_value_of<2>(c.data(), t);
    case 3:
        return bernstein_value_of<3>(c.data(), t);
    case 4:
        return bernstein_value_of<4>(c.data(), t);
    case 5:
        return bernstein_value_of<5>(c.data(), t);
    case 6:
        return bernstein_value_of<6>(c.data(), t);
    case 7:
        return bernstein_value_of<7>(c.data(), t);
    case 8:
        return bernstein_value_of<8>(c.data(), t);
    case 9:
        return bernstein_value_of<9>(c.data(), t);
    default: {
        std::array<double, kMaxPoints> b;
        std::copy(c.begin(), c.end(), b.begin());
        return casteljau(b, c.size(), t);
    }
    }
}

int bernstein_roots(std::span<const double> coeff, std::span<double> out) noexcept {
    const std::size_t n = coeff.size();
    if (n < 2 || out.empty()) return 0;
    // The zero polynomial "changes sign" everywhere; it has no isolated roots.
    bool all_zero = true;
    for (double c : coeff) all_zero &= c == 0.0;
    if (all_zero) return 0;
    // Depth-first, right half pushed first, so roots come out ascending; the
    // stack never holds more than one pending piece per level.
    std::array<Piece, kRootDepth + 2> stack;
    int top = 0;
    stack[0].t0 = 0;
    stack[0].t1 = 1;
    stack[0].depth = 0;
    for (std::size_t i = 0; i < n; ++i) stack[0].c[i].v = coeff[i];
    top = 1;
    int count = 0;
    double last = -1.0;
    // Near a root of high multiplicity many tiny pieces straddle zero through
    // rounding; the budget bounds that work whatever the input.
    int budget = 64 * kRootDepth * int(n);
    while (top > 0 && count < int(out.size()) && budget-- > 0) {
        Piece p; // the n coefficients in use, not all kMaxPoints
        const Piece& popped = stack[--top];
        p.t0 = popped.t0, p.t1 = popped.t1, p.depth = popped.depth;
        std::copy_n(popped.c.begin(), n, p.c.begin());
        if (!has_sign_change(p, n)) continue;
        if (isolates_one_root(p, n)) {
            // To 2^-kRootDepth in t, as the subdivision's depth cap resolves.
            const double width = std::ldexp(1.0, -kRootDepth) / (p.t1 - p.t0);
            std::array<double, kMaxPoints> values;
            for (std::size_t i = 0; i < n; ++i) values[i] = p.c[i].v;
            const double u = bracketed_root(
                [&](double x) {
                    return bernstein_value({values.data(), n}, x);
                },
                0.0, 1.0, values[0], values[n - 1], width);
            out[count++] = last = p.t0 + (p.t1 - p.t0) * u;
            continue;
        }
        if (p.depth == kRootDepth) {
            const double t = 0.5 * (p.t0 + p.t1);
            // Adjacent pieces of the last level can both straddle one root.
            if (t - last > 4.0 * (p.t1 - p.t0)) out[count++] = last = t;
            continue;
        }
        Piece& right = stack[top++];
        Piece& left = stack[top++];
        const double mid = 0.5 * (p.t0 + p.t1);
        decasteljau_split(std::span<const Scalar>(p.c.data(), n), 0.5,
                          std::span<Scalar>(left.c.data(), n),
                          std::span<Scalar>(right.c.data(), n));
        left.t0 = p.t0, left.t1 = mid, left.depth = p.depth + 1;
        right.t0 = mid, right.t1 = p.t1, right.depth = p.depth + 1;
    }
    return count;
}

} // namespace casteljau
