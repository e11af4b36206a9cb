// The guided flattener's parts (flatten/guided.h): the cut count, the Hermite
// forms of a piece (polynomial and conic) against de Casteljau's subsegment,
// and the test that lets a whole cut through untested. The flattener as a
// whole is in flatten_test.cpp.
#include "casteljau/flatten/guided.h"
#include "corpus.h"

#include <cmath>
#include <gtest/gtest.h>
#include <vector>

namespace casteljau {
namespace {

TEST(Guided, CutCountIsTheFourthRootRoundedUpAndCapped) {
    for (int j = 1; j <= kGuidedMaxCut + 2; ++j) {
        const double e = double(j) * j * j * j;
        const int want = std::min(j, kGuidedMaxCut);
        EXPECT_EQ(guided_cut({e}), want) << "excess " << e;
        EXPECT_EQ(guided_cut({std::nextafter(e, 0.0)}), want) << "just below " << e;
        EXPECT_EQ(guided_cut({std::nextafter(e, 1e300)}), std::min(j + 1, kGuidedMaxCut))
            << "just above " << e;
    }
    // The excess as a fraction with any denominator (the chord's squared
    // length scales it when the perpendicular bound is the tighter one).
    testing::Rng rng(5);
    for (int i = 0; i < 1000; ++i) {
        const double e = rng.log_uniform(1.0001, 1e4), den = rng.log_uniform(1e-6, 1e6);
        const double want = std::min(std::ceil(std::sqrt(std::sqrt(e))), double(kGuidedMaxCut));
        EXPECT_EQ(guided_cut({e * den, den}), int(want)) << "excess " << e << " as x/" << den;
    }
}

// The largest squared parametric offset max_i |P_i - L_i|^2 (the top of guided.h).
template <int N>
double parametric_sq(const Bez<N>& b) {
    double m = 0;
    for (int i = 1; i < N; ++i)
        m = std::max(m, (b.p[i] - lerp(b.p[0], b.p[N], double(i) / N)).length_sq());
    return m;
}

// A piece built from the points and derivatives at its ends measures as the
// same piece cut by de Casteljau, also after moves that skip the derivative
// (inside a cut known flat) before the last one that takes it.
template <int N>
void expect_hermite_matches_subsegment(const Bez<N>& c, testing::Rng& rng) {
    const double t0 = rng.uniform(0, 0.9), t1 = rng.integer(0, 3) ? rng.uniform(t0, 1) : 1.0;
    const double scaled_tol = rng.log_uniform(1e-4, 10);
    HermitePieces<N> pieces(c);
    if (t0 > 0) {
        const double tm = 0.5 * t0;
        EXPECT_LE(distance(pieces.advance(tm, false), c.eval(tm)),
                  1e-9 * (1 + c.start().to_vec().length()));
        pieces.advance(t0, true);
    }
    const double hermite = pieces.probe(t0, t1, scaled_tol).value();
    const double direct = guided_excess(c.subsegment(t0, t1), scaled_tol).value();
    // Equal up to rounding, where a flat piece reports 0 on either side of 1.
    if (hermite > 1.001 || direct > 1.001) {
        EXPECT_NEAR(hermite, direct, 1e-6 * direct)
            << "degree " << N << " [" << t0 << ", " << t1 << "]";
    } else {
        EXPECT_LE(std::max(hermite, direct), 1.001);
    }
    if (t1 == 1.0) {
        EXPECT_EQ(pieces.accept(), c.end()) << "the end point is exact";
    }
}

TEST(Guided, HermitePiecesMeasureAsDeCasteljauSubsegments) {
    testing::Rng rng(6);
    for (int i = 0; i < 2000; ++i) {
        const double size = rng.log_uniform(1, 2000);
        expect_hermite_matches_subsegment(testing::random_quad(rng, size), rng);
        expect_hermite_matches_subsegment(testing::random_cubic(rng, size), rng);
    }
}

// A conic's piece built from the homogeneous values at its ends measures as
// the same piece cut by de Casteljau and tested by hull_deviation, also after
// a move.
TEST(Guided, ConicPiecesMeasureAsDeCasteljauSubsegments) {
    testing::Rng rng(8);
    for (int i = 0; i < 4000; ++i) {
        const HConic c = HConic::from(testing::random_conic(rng, rng.log_uniform(1, 2000)));
        const double t0 = rng.uniform(0, 0.9), t1 = rng.integer(0, 3) ? rng.uniform(t0, 1) : 1.0;
        const double tol = rng.log_uniform(1e-2, 10);
        ConicPieces pieces(c);
        if (t0 > 0) {
            EXPECT_LE(distance(pieces.advance(t0, false), c.eval(t0)),
                      1e-9 * (1 + c.start().to_vec().length()));
        }
        const double hermite = pieces.probe(t0, t1, tol * tol).value();
        const double direct = guided_excess(c.subsegment(t0, t1), tol * tol).value();
        EXPECT_NEAR(hermite, direct, 1e-6 * direct + 1e-12)
            << "conic " << i << " [" << t0 << ", " << t1 << "] tol " << tol;
        const Point end = pieces.accept();
        if (t1 == 1.0) {
            EXPECT_EQ(end, c.end()) << "the end point is exact";
        } else {
            EXPECT_LE(distance(end, c.eval(t1)), 1e-9 * (1 + c.start().to_vec().length()));
        }
    }
}

// Whole conics flattened through ConicPieces and through the reference
// SubsegmentPieces: the same cuts (counts and parameters), the same points up
// to rounding, and the same exact end.
TEST(Guided, ConicPiecesFlattenAsSubsegmentPieces) {
    testing::Rng rng(9);
    for (int i = 0; i < 2000; ++i) {
        const HConic c = HConic::from(testing::random_conic(rng, rng.log_uniform(1, 2000)));
        const double tol = rng.log_uniform(0.05, 2);
        std::vector<FlatVertex> fast, reference;
        for (const FlatVertex& v : GuidedFlattener<HConic>(c, tol)) fast.push_back(v);
        for (const FlatVertex& v : GuidedFlattener<HConic, SubsegmentPieces<HConic>>(c, tol))
            reference.push_back(v);
        ASSERT_EQ(fast.size(), reference.size()) << "conic " << i << " tol " << tol;
        for (std::size_t j = 0; j < fast.size(); ++j) {
            EXPECT_EQ(fast[j].t, reference[j].t) << "conic " << i << " vertex " << j;
            EXPECT_LE(distance(fast[j].p, reference[j].p),
                      1e-9 * (1 + reference[j].p.to_vec().length()))
                << "conic " << i << " vertex " << j;
        }
        EXPECT_EQ(fast.back().p, c.end()) << "conic " << i;
    }
}

// even_cut_is_flat says exactly whether every piece of the cut passes the
// parametric test (up to rounding): it is a bound, and it is tight.
template <int N>
void expect_even_cut_test_is_exact(const Bez<N>& c, testing::Rng& rng, int& flat, int& not_flat) {
    const double t0 = rng.uniform(0, 0.9), t1 = rng.uniform(t0 + 0.01, 1);
    const int k = rng.integer(1, kGuidedMaxCut);
    double worst = 0;
    for (int j = 0; j < k; ++j) {
        const double a = t0 + (t1 - t0) * j / k, b = t0 + (t1 - t0) * (j + 1) / k;
        worst = std::max(worst, parametric_sq(c.subsegment(a, b)));
    }
    // A tolerance around the worst piece, so that both outcomes are exercised.
    const double scaled_tol = worst * rng.log_uniform(0.25, 4);
    const bool claimed = HermitePieces<N>(c).even_cut_is_flat((t1 - t0) / k, t0, t1, scaled_tol);
    if (worst <= scaled_tol * (1 - 1e-9)) {
        EXPECT_TRUE(claimed) << "tight; worst " << worst;
    }
    if (worst >= scaled_tol * (1 + 1e-9)) {
        EXPECT_FALSE(claimed) << "a bound; worst " << worst;
    }
    ++(claimed ? flat : not_flat);
}

TEST(Guided, EvenCutsKnownFlatAreExactlyTheFlatOnes) {
    testing::Rng rng(7);
    int flat = 0, not_flat = 0;
    for (int i = 0; i < 2000; ++i) {
        const double size = rng.log_uniform(1, 2000);
        expect_even_cut_test_is_exact(testing::random_quad(rng, size), rng, flat, not_flat);
        expect_even_cut_test_is_exact(testing::random_cubic(rng, size), rng, flat, not_flat);
    }
    EXPECT_GT(flat, 1000);
    EXPECT_GT(not_flat, 1000);
}

} // namespace
} // namespace casteljau
