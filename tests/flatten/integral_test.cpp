// The integral flattener (flatten/integral.h) and its density models
// (flatten/density.h): the tolerance on adversarial curves, corners, the
// chord count against the optimum and the greedy flattener, range = sink,
// and the cap when the tolerance is below rounding.
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/flatten.h"
#include "corpus.h"

#include <cmath>
#include <gtest/gtest.h>
#include <numbers>

namespace casteljau {
namespace {

template <int N>
std::vector<FlatVertex> flatten(const Bez<N>& c, double tol) {
    std::vector<FlatVertex> v;
    flatten_integral(c, tol, [&](const FlatVertex& x) { v.push_back(x); });
    return v;
}

// Rounding in the curve arithmetic, relative to the curve's size.
template <int N>
double slack(const Bez<N>& c) {
    const Rect r = c.control_bounds();
    return 1e-12 * (1 + std::fabs(r.x0) + std::fabs(r.y0) + r.width() + r.height());
}

template <int N>
void expect_valid(const Bez<N>& c, double tol, const std::string& what) {
    const std::vector<FlatVertex> v = flatten(c, tol);
    ASSERT_FALSE(v.empty()) << what;
    EXPECT_EQ(v.back().p, c.end()) << what;
    EXPECT_EQ(v.back().t, 1.0) << what;
    for (std::size_t i = 1; i < v.size(); ++i) EXPECT_GT(v[i].t, v[i - 1].t) << what << " " << i;
    EXPECT_LE(polyline_error(c, c.start(), v), tol + slack(c))
        << what << ", " << v.size() << " segments";
}

// A copy of a unit shape at a random place, angle and size.
template <int N>
Bez<N> placed(testing::Rng& rng, const Bez<N>& unit, double size) {
    return unit.transformed(
        Affine::translate({rng.uniform(-1, 1) * size, rng.uniform(-1, 1) * size}) *
        Affine::rotate(rng.uniform(0, 2 * std::numbers::pi)) * Affine::scale(size));
}

// The curves a density model gets wrong: exact and near cusps, loops,
// inflections, collinear turnarounds, coincident control points.
CubicBez nasty_cubic(testing::Rng& rng, double size) {
    const double e = rng.log_uniform(1e-9, 1e-1) * (rng.integer(0, 1) ? 1 : -1);
    switch (rng.integer(0, 7)) {
    case 0: // an exact cusp (B'(1/2) = 0)
        return placed(rng, CubicBez{{0, 0}, {1, 1}, {0, 1}, {1, 0}}, size);
    case 1: // a near cusp, either side of it
        return placed(rng, CubicBez{{0, 0}, {1, 1}, {e, 1}, {1, 0}}, size);
    case 2: // a loop, or a tight one
        return placed(rng, CubicBez{{0, 0}, {1.2 + e * 10, 1}, {-0.2 - e * 10, 1}, {1, 0}}, size);
    case 3: // an S: an inflection
        return placed(rng, CubicBez{{0, 0}, {0.5, 0.6 + e}, {0.5, -0.6}, {1, e}}, size);
    case 4: { // collinear, in any order: turnarounds with w = 0
        const Point a{rng.uniform(-1, 1), 0}, b{rng.uniform(-1, 1), 0};
        return placed(rng, CubicBez{{0, 0}, a, b, {1, e}}, size);
    }
    case 5: // coincident handles
        return placed(rng, CubicBez{{0, 0}, {0, 0}, {1, 1}, {1, 1 + e}}, size);
    case 6: // a handle on its end, and a near-straight curve
        return placed(rng, CubicBez{{0, 0}, {0.5, e}, {1, 0}, {1, 0}}, size);
    default:
        return testing::random_cubic(rng, size);
    }
}

QuadBez nasty_quad(testing::Rng& rng, double size) {
    const double e = rng.log_uniform(1e-9, 1e-1);
    switch (rng.integer(0, 3)) {
    case 0: // a sharp apex
        return placed(rng, QuadBez{{0, 0}, {0.5, 1}, {1, e}}, size);
    case 1: // a collinear turnaround
        return placed(rng, QuadBez{{0, 0}, {2, e}, {1, 0}}, size);
    case 2: // nearly straight
        return placed(rng, QuadBez{{0, 0}, {0.5, e}, {1, 0}}, size);
    default:
        return testing::random_quad(rng, size);
    }
}

TEST(Integral, ErrorWithinToleranceOnAdversarialCurves) {
    testing::Rng rng(91);
    for (int i = 0; i < 4000; ++i) {
        // Tiny to huge: 1e-3 px to 1e7 px (the largest fewer, at coarser
        // tolerances, for the error measure's time: it samples every chord).
        const bool huge = i % 20 == 0;
        const double tol = rng.log_uniform(huge ? 0.1 : 0.01, 1);
        const double size = huge ? rng.log_uniform(1e5, 1e7) : rng.log_uniform(1e-3, 1e5);
        const std::string what = "curve " + std::to_string(i) + " tol " + std::to_string(tol) +
                                 " size " + std::to_string(size);
        expect_valid(nasty_cubic(rng, size), tol, "cubic " + what);
        expect_valid(nasty_quad(rng, size), tol, "quad " + what);
    }
    expect_valid(Line{{3, 4}, {1e6, -2}}, 0.25, "line");
    expect_valid(Line{{3, 4}, {3, 4}}, 0.25, "point");
}

TEST(Integral, ExactCuspGetsAVertex) {
    // B'(1/2) = 0: a chord across the cusp deviates by about the curve's
    // size, whatever the density says there; the cusp is a corner (density.h).
    const CubicBez cusp{{0, 0}, {100, 100}, {0, 100}, {100, 0}};
    for (double tol : {0.01, 0.25, 1.0}) {
        const std::vector<FlatVertex> v = flatten(cusp, tol);
        bool found = false;
        for (const FlatVertex& x : v) found = found || std::fabs(x.t - 0.5) < 1e-12;
        EXPECT_TRUE(found) << "tol " << tol;
    }
}

TEST(Integral, CornerSearchFindsNearCuspsAndNothingElse) {
    // The speed minimum by brute force (a fine grid) against the corner search
    // (density.h), a screen and then Newton's method from the sampled speeds:
    // a near cusp or a tight loop with a radius of curvature below half of
    // kCornerRadius tol must get its corner at the minimum, and no curve whose
    // radius is above twice that may get one.
    int found = 0;
    for (double tol : {0.1, 0.25, 1.0}) {
        for (const auto& [kind, c] : testing::cubic_corpus(11, 40)) {
            double least = 1e300, at = 0;
            for (int i = 1; i < 20000; ++i) {
                const double t = i / 20000.0, p = c.deriv(t).length_sq();
                if (p < least) least = p, at = t;
            }
            const Vec2 d = c.deriv(at);
            const double radius = std::pow(d.length_sq(), 1.5) / std::fabs(d.cross(c.deriv2(at)));
            const double corner = CubicDensity(c.power(), tol).corner();
            found += corner < 1;
            const std::string what = kind + " tol " + std::to_string(tol) + " radius " +
                                     std::to_string(radius) + " minimum at " + std::to_string(at);
            if (radius > 2 * kCornerRadius * tol) {
                EXPECT_EQ(corner, 1.0) << what;
            }
            if (radius < 0.5 * kCornerRadius * tol && (kind == "near_cusp" || kind == "loop")) {
                EXPECT_NEAR(corner, at, 1e-4) << what;
            }
        }
    }
    EXPECT_GT(found, 100); // the corpus's near cusps at every tolerance
}

TEST(Integral, RangeFormEqualsSinkForm) {
    testing::Rng rng(92);
    for (int i = 0; i < 500; ++i) {
        const double size = rng.log_uniform(1, 1000), tol = rng.log_uniform(0.01, 1);
        const CubicBez c = nasty_cubic(rng, size);
        const QuadBez q = nasty_quad(rng, size);
        std::vector<FlatVertex> range;
        for (const FlatVertex& v : IntegralFlattener<3>(c, tol)) range.push_back(v);
        EXPECT_EQ(flatten(c, tol), range) << "cubic " << i;
        range.clear();
        for (const FlatVertex& v : IntegralFlattener<2>(q, tol)) range.push_back(v);
        EXPECT_EQ(flatten(q, tol), range) << "quad " << i;
    }
}

// The target on the benchmark corpus (deterministic counts, no
// timing): at most 1.05x the optimal count at 0.25 px and 0.1 px, and at
// every tolerance no more than the greedy (adaptive) flattener, at a
// measured error within the tolerance.
TEST(Integral, NearOptimalCountOnTheBenchmarkCorpus) {
    const auto corpus = testing::cubic_corpus(2026, 40);
    for (double tol : {1.0, 0.5, 0.25, 0.1}) {
        double integral = 0, adaptive = 0, optimal = 0, max_err = 0;
        for (const auto& [kind, c] : corpus) {
            const std::vector<FlatVertex> v = flatten(c, tol);
            integral += double(v.size());
            max_err = std::max(max_err, polyline_error(c, c.start(), v));
            flatten_adaptive(c, tol, [&](const FlatVertex&) { adaptive += 1; });
            optimal += testing::optimal_segments(c, tol);
        }
        EXPECT_LE(integral, adaptive) << "tol " << tol;
        if (tol <= 0.25) {
            EXPECT_LE(integral, 1.05 * optimal) << "tol " << tol;
        }
        EXPECT_LE(max_err, tol + 1e-9) << "tol " << tol;
        std::printf("tol %.2f: integral/optimal %.4f, adaptive/optimal %.4f\n", tol,
                    integral / optimal, adaptive / optimal);
    }
}

TEST(Integral, ChordCountIsCappedWhenTheToleranceIsBelowRounding) {
    // At 1e15 px a double resolves ~0.1 px: a 1e-4 px tolerance is
    // unreachable, and the flattener must stop at its shortest chords.
    const CubicBez c{{1e15, 1e15}, {1e15 + 4e14, 2e15}, {2e15, 0}, {3e15, 1e15}};
    const QuadBez q{{1e15, 1e15}, {2e15, 3e15}, {3e15, 1e15}};
    const std::size_t cap = std::size_t(1.0 / kIntegralMinStep) + 2;
    std::size_t nc = 0, nq = 0;
    flatten_integral(c, 1e-4, [&](const FlatVertex&) { ++nc; });
    flatten_integral(q, 1e-4, [&](const FlatVertex&) { ++nq; });
    EXPECT_LE(nc, cap);
    EXPECT_LE(nq, cap);
    EXPECT_GT(nc, 1000u);
}

TEST(Integral, DensityModelsIntegrateTheDensity) {
    // Against the density integrated by testing::optimal_segments (adaptive
    // Simpson). The parabola's closed form: within 0.3%, its inverse's slope
    // error (parabola.h) integrated. The cubic's samples: exact where the
    // curvature is even (quarter circles), within 5% elsewhere, where a peak
    // of the density between samples (loops, near cusps) or an inflection's
    // square-root zero is modelled approximately (the flattener's check
    // corrects the chords there).
    testing::Rng rng(93);
    for (int i = 0; i < 300; ++i) {
        const double tol = rng.log_uniform(0.05, 1);
        const QuadBez q = testing::random_quad(rng, rng.log_uniform(10, 1000));
        const ParabolaDensity d(q.power(), tol);
        const double want = testing::optimal_segments(q.elevate(), tol);
        EXPECT_NEAR(d.total(), want, 0.003 * want + 1e-9) << i;
        // And from the start to inner points (what the plan inverts), as
        // the integral over the piece [0, t].
        for (double t : {0.2, 0.5, 0.8}) {
            const double part = testing::optimal_segments(q.elevate().subsegment(0, t), tol);
            EXPECT_NEAR(d.integral_at(t), part, 0.003 * want + 1e-9) << i << " t " << t;
        }
    }
    for (const auto& [kind, c] : testing::cubic_corpus(7, 20)) {
        const CubicDensity d(c.power(), 0.25);
        const double want = testing::optimal_segments(c, 0.25);
        const double within = (kind == "quarter_circle" ? 0.001 : 0.05) * want;
        EXPECT_NEAR(d.total(), want, within) << kind;
        for (double t : {0.2, 0.5, 0.8})
            EXPECT_NEAR(d.integral_at(t), testing::optimal_segments(c.subsegment(0, t), 0.25),
                        within)
                << kind << " t " << t;
    }
}

// The inverse (the plan's vertices) against the integral, which the test
// above checks against an independent quadrature.
TEST(Integral, DensityInverseMatchesItsIntegral) {
    testing::Rng rng(94);
    for (int i = 0; i < 300; ++i) {
        const CubicBez c = nasty_cubic(rng, 100);
        const QuadBez q = nasty_quad(rng, 100);
        const CubicDensity dc(c.power(), 0.1);
        const ParabolaDensity dq(q.power(), 0.1);
        double last_c = 0, last_q = 0;
        for (int k = 1; k < 50; ++k) {
            const double Ic = dc.total() * k / 50, Iq = dq.total() * k / 50;
            const double tc = dc.t_at(Ic), tq = dq.t_at(Iq);
            EXPECT_GE(tc, last_c) << i; // monotone
            EXPECT_GE(tq, last_q) << i;
            last_c = tc, last_q = tq;
            EXPECT_NEAR(dc.integral_at(tc), Ic, 1e-6 * (1 + dc.total())) << i << " " << k;
            EXPECT_NEAR(dq.integral_at(tq), Iq, 1e-6 * (1 + dq.total())) << i << " " << k;
        }
    }
}

} // namespace
} // namespace casteljau
