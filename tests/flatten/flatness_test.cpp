// The flatness bounds against the exact error measure: exact forms must equal
// the measured deviation, bounds must never be below it.
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/flatness.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

template <class C>
double measured(const C& c) {
    return piece_error(c, 0.0, 1.0, c.start(), c.end());
}

TEST(Flatness, ExactFormsEqualTheMeasuredDeviation) {
    testing::Rng rng(61);
    int exact_quads = 0, exact_cubics = 0, exact_conics = 0;
    for (int i = 0; i < 2000; ++i) {
        const QuadBez q = testing::random_quad(rng, 100);
        const CubicBez c = testing::random_cubic(rng, 100);
        const Conic k = testing::random_conic(rng, 100);
        const double mq = measured(q), mc = measured(c), mk = measured(k);
        // Never below the truth (that would break the tolerance guarantee) ...
        EXPECT_GE(chord_deviation(q), mq - 1e-9) << i;
        EXPECT_GE(chord_deviation(c), mc - 1e-9) << i;
        EXPECT_GE(chord_deviation(k), mk - 1e-9) << i;
        // ... and equal to it whenever the exact form applies.
        exact_quads += std::fabs(chord_deviation(q) - mq) < 1e-9;
        exact_cubics += std::fabs(chord_deviation(c) - mc) < 1e-9;
        exact_conics += std::fabs(chord_deviation(k) - mk) < 1e-9;
    }
    // Random control points often project outside the chord (then the hull
    // bound is used); the exact form must still cover a good share.
    EXPECT_GT(exact_quads, 600);
    EXPECT_GT(exact_cubics, 300);
    EXPECT_GT(exact_conics, 600);
}

TEST(Flatness, ExactOnPiecesThatProjectInside) {
    testing::Rng rng(62);
    for (int i = 0; i < 2000; ++i) {
        // Inner points between the ends: the exact form must apply.
        const Point a{0, 0}, b{100, 0};
        const CubicBez c{{a,
                          {rng.uniform(0, 100), rng.uniform(-30, 30)},
                          {rng.uniform(0, 100), rng.uniform(-30, 30)},
                          b}};
        EXPECT_NEAR(chord_deviation(c), measured(c), 1e-9) << i;
        const Conic k{a, {rng.uniform(0, 100), rng.uniform(-30, 30)}, b, rng.log_uniform(0.05, 20)};
        EXPECT_NEAR(chord_deviation(k), measured(k), 1e-9) << i;
    }
}

TEST(Flatness, HullBoundIsAnUpperBoundForEveryType) {
    testing::Rng rng(63);
    for (int i = 0; i < 500; ++i) {
        const Bezier b = testing::random_bezier(rng, rng.integer(2, 8), 100);
        EXPECT_GE(chord_deviation(b), measured(b) - 1e-9);
        const RationalBezier r = testing::random_conic(rng, 100).to_rational();
        EXPECT_GE(chord_deviation(r), measured(r) - 1e-9);
    }
}

TEST(Flatness, KnownValues) {
    // Quadratic apex: half the control point's offset.
    EXPECT_DOUBLE_EQ(chord_deviation(QuadBez{{0, 0}, {50, 40}, {100, 0}}), 20.0);
    // Symmetric cubic arch: 3/4 of the offset.
    EXPECT_DOUBLE_EQ(chord_deviation(CubicBez{{0, 0}, {0, 40}, {100, 40}, {100, 0}}), 30.0);
    // Antisymmetric S: 4/9 / ... the extremum of 3t(1-t)(1-2t) d is d/(2 sqrt 3).
    EXPECT_NEAR(chord_deviation(CubicBez{{0, 0}, {30, 40}, {70, -40}, {100, 0}}),
                40.0 / (2 * std::sqrt(3.0)), 1e-12);
    // Quarter circle as a conic: 1 - cos(45 deg) of the radius.
    const Conic quarter = Conic::circular_arc({0, 0}, 100, 0, std::numbers::pi / 2);
    EXPECT_NEAR(chord_deviation(quarter), 100 * (1 - std::cos(std::numbers::pi / 4)), 1e-12);
    EXPECT_EQ(chord_deviation(Line{{0, 0}, {5, 5}}), 0.0);
}

} // namespace
} // namespace casteljau
