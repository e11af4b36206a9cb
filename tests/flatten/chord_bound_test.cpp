// The integral flattener's chord check (flatten/chord_bound.h) against the
// exact error measure (flatten/error.h): never below the measured deviation,
// and tight where the flattener uses it.
#include "casteljau/flatten/chord_bound.h"
#include "casteljau/flatten/error.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

// The measured deviation of c's piece [a, a + h] from its chord.
template <class C>
double measured(const C& c, double a, double h) {
    const double b = a + h;
    return piece_error(c, a, b, c.eval(a), c.eval(b));
}

template <int N>
double bound_of(const Bez<N>& c, double a, double h) {
    const PowerCurve<N> pc = c.power();
    const Vec2 v = c.eval(a + h) - c.eval(a);
    if constexpr (N == 2) {
        return std::sqrt(quad_chord_bound(v, h, pc.c[1]).value());
    } else {
        return std::sqrt(cubic_chord_bound(v, a, h, pc.c[1], pc.c[2]).value());
    }
}

// Whether the piece's inner control points project inside its chord, and
// whether its offsets change sign (an inflection): the cases of the bound.
template <int N>
std::pair<bool, bool> shape_of(const Bez<N>& piece) {
    const Vec2 v = piece.end() - piece.start();
    bool inside = v.length_sq() > 0;
    double lo = 0, hi = 0;
    for (int i = 1; i < N; ++i) {
        const Vec2 u = piece.p[i] - piece.start();
        inside = inside && u.dot(v) >= 0 && u.dot(v) <= v.length_sq();
        lo = std::min(lo, u.cross(v)), hi = std::max(hi, u.cross(v));
    }
    return {inside, lo < 0 && hi > 0};
}

template <int N>
void expect_bound_holds(const Bez<N>& c, testing::Rng& rng, int& tight_cases) {
    // Pieces of all lengths, the short ones the flattener makes most often.
    const double h = rng.log_uniform(1e-4, 1), a = rng.uniform(0, 1 - h);
    const double got = bound_of(c, a, h), truth = measured(c, a, h);
    const double slack = 1e-9 * (1 + c.control_bounds().width() + c.control_bounds().height());
    EXPECT_GE(got, truth - slack) << "degree " << N << " piece [" << a << ", " << a + h << "]";
    const auto [inside, inflected] = shape_of(c.subsegment(a, a + h));
    if (inside && !inflected && truth > slack * 1e3) {
        // The proven worst case (|E| = |M|, chord_bound.h): 5.5% high.
        EXPECT_LE(got, 1.0547 * truth + slack)
            << "degree " << N << " [" << a << ", " << a + h << "]";
        ++tight_cases;
    }
    if (inside && inflected && truth > slack * 1e3) {
        // Straddling an inflection: taken exactly.
        EXPECT_NEAR(got, truth, 1e-6 * truth) << "[" << a << ", " << a + h << "]";
    }
}

TEST(ChordBound, NeverBelowTheMeasuredDeviationAndTightInside) {
    testing::Rng rng(81);
    int tight_quads = 0, tight_cubics = 0;
    for (int i = 0; i < 3000; ++i) {
        const double size = rng.log_uniform(1e-2, 1e5);
        expect_bound_holds(testing::random_quad(rng, size), rng, tight_quads);
        expect_bound_holds(testing::random_cubic(rng, size), rng, tight_cubics);
    }
    EXPECT_GT(tight_quads, 1000);
    EXPECT_GT(tight_cubics, 1000);
}

TEST(ChordBound, ExactWhenTheCurvatureIsEven) {
    // A quadratic's pieces, and a cubic that is a degree-raised quadratic
    // (c3 = 0, so E = 0): the bound is the exact deviation.
    testing::Rng rng(82);
    for (int i = 0; i < 500; ++i) {
        const QuadBez q = testing::random_quad(rng, 300);
        const CubicBez c = q.elevate();
        const double h = rng.log_uniform(1e-3, 0.5), a = rng.uniform(0, 1 - h);
        if (!shape_of(q.subsegment(a, a + h)).first) continue;
        EXPECT_NEAR(bound_of(q, a, h), measured(q, a, h), 1e-9 * (1 + measured(q, a, h))) << i;
        EXPECT_NEAR(bound_of(c, a, h), measured(c, a, h), 1e-9 * (1 + measured(c, a, h))) << i;
    }
}

TEST(ChordBound, OvershootingPiecesAreBounded) {
    // Collinear control points whose curve runs past its chord's end, and a
    // zero chord: the bound must cover the overshoot, measured against the
    // chord segment.
    const CubicBez overshoot{{0, 0}, {200, 0}, {-100, 0}, {100, 0}};
    const CubicBez closed{{0, 0}, {100, 100}, {-100, 100}, {0, 0}};
    const QuadBez back{{0, 0}, {300, 0}, {100, 0}};
    for (double a : {0.0, 0.2}) {
        for (double h : {0.8, 0.5, 0.1}) {
            if (a + h > 1) continue;
            EXPECT_GE(bound_of(overshoot, a, h), measured(overshoot, a, h) - 1e-9) << a << " " << h;
            EXPECT_GE(bound_of(back, a, h), measured(back, a, h) - 1e-9) << a << " " << h;
        }
    }
    EXPECT_GE(bound_of(closed, 0, 1), measured(closed, 0, 1) - 1e-9);
    EXPECT_GE(bound_of(back, 0, 1), measured(back, 0, 1) - 1e-9);
    // The cases really overshoot: x runs to 72 over [0, 0.5] whose chord ends
    // at 50, and the quadratic to 180 past its end at 100.
    EXPECT_NEAR(measured(overshoot, 0, 0.5), 22.3, 0.1);
    EXPECT_NEAR(measured(back, 0, 1), 80, 1e-6);
}

} // namespace
} // namespace casteljau
