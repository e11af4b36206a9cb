// Levien's flattener (flatten/levien.h), the baseline: its vertices, range =
// sink, the count and error its model gives where the curvature keeps its
// sign, the measured overshoot across inflections that no chord check
// corrects, and the chunked plan of a huge cubic.
#include "casteljau/flatten/error.h"
#include "casteljau/flatten/levien.h"
#include "corpus.h"

#include <gtest/gtest.h>
#include <map>
#include <numbers>

namespace casteljau {
namespace {

std::vector<FlatVertex> flatten(const CubicBez& c, double tol) {
    std::vector<FlatVertex> v;
    flatten_levien(c, tol, [&](const FlatVertex& x) { v.push_back(x); });
    return v;
}

TEST(Levien, VerticesLieOnTheCurveInOrderEndingAtItsEnd) {
    testing::Rng rng(5);
    for (int i = 0; i < 500; ++i) {
        const CubicBez c = testing::random_cubic(rng, rng.log_uniform(1, 1e4));
        const std::vector<FlatVertex> v = flatten(c, 0.25);
        ASSERT_FALSE(v.empty()) << i;
        EXPECT_EQ(v.back().p, c.end()) << i;
        EXPECT_EQ(v.back().t, 1.0) << i;
        for (std::size_t j = 0; j < v.size(); ++j) {
            if (j > 0) {
                EXPECT_GT(v[j].t, v[j - 1].t) << i << " " << j;
            }
            EXPECT_LT(distance(v[j].p, c.eval(v[j].t)), 1e-9 * (1 + c.control_bounds().width()))
                << i << " " << j;
        }
    }
}

TEST(Levien, RangeFormEqualsSinkForm) {
    testing::Rng rng(6);
    for (int i = 0; i < 200; ++i) {
        const CubicBez c = testing::random_cubic(rng, 300);
        std::vector<FlatVertex> range;
        for (const FlatVertex& v : LevienFlattener(c, 0.1)) range.push_back(v);
        EXPECT_EQ(range, flatten(c, 0.1)) << i;
    }
}

TEST(Levien, StraightCurvesAndPointsTakeOneChord) {
    for (const CubicBez& c :
         {CubicBez{{0, 0}, {1, 1}, {2, 2}, {3, 3}}, CubicBez{{0, 0}, {3, 0}, {-1, 0}, {2, 0}},
          CubicBez{{4, 4}, {4, 4}, {4, 4}, {4, 4}}}) {
        const std::vector<FlatVertex> v = flatten(c, 0.25);
        ASSERT_EQ(v.size(), 1u) << c.p[1].x;
        EXPECT_EQ(v[0].p, c.end());
    }
}

// Where the curvature keeps its sign (arcs, loops) the count is the model's
// integral and the error within its closed forms' accuracy: a few percent
// over the tolerance, at a few percent over the optimal count.
TEST(Levien, ArcsAndLoopsMeetTheToleranceToItsClosedFormsAccuracy) {
    for (double tol : {0.25, 0.1}) {
        double count = 0, optimal = 0, worst = 0;
        for (const auto& [kind, c] : testing::cubic_corpus(2026, 50)) {
            if (kind != "quarter_circle" && kind != "loop") continue;
            const std::vector<FlatVertex> v = flatten(c, tol);
            worst = std::max(worst, polyline_error(c, c.start(), v) / tol);
            count += double(v.size());
            optimal += testing::optimal_segments(c, tol);
        }
        EXPECT_LE(worst, 1.05) << tol;
        EXPECT_LE(count / optimal, 1.06) << tol;
    }
}

// Across an inflection no quadratic has curvature to count, and nothing checks
// the chords: the measured overshoot that bench/flatten's levien_equal
// compensates by asking for a lower tolerance (bench/README.md).
TEST(Levien, InflectionsOvershootTheToleranceByAtMostHalf) {
    std::map<std::string, double> worst;
    for (const auto& [kind, c] : testing::cubic_corpus(2026, 50))
        worst[kind] = std::max(worst[kind], polyline_error(c, c.start(), flatten(c, 0.25)) / 0.25);
    EXPECT_GT(worst["s_curve"], 1.2);
    for (const auto& [kind, w] : worst) EXPECT_LE(w, 1.55) << kind;
}

// A cubic needing more than kLevienMaxQuads quadratics is planned in chunks,
// each ending on a vertex: an arc of radius 1e6 px (with no inflection) keeps
// the arcs' error and count.
TEST(Levien, AHugeArcIsPlannedInChunks) {
    const double k = 4.0 / 3.0 * (std::numbers::sqrt2 - 1), r = 1e6;
    const CubicBez arc{{r, 0}, {r, k * r}, {k * r, r}, {0, r}};
    const std::vector<FlatVertex> v = flatten(arc, 0.25);
    EXPECT_GT(v.size(), 100u);
    EXPECT_LE(polyline_error(arc, arc.start(), v), 1.05 * 0.25);
    EXPECT_LE(double(v.size()), 1.06 * testing::optimal_segments(arc, 0.25));
    EXPECT_GT(levien_quadratics(arc, 0.25), kLevienMaxQuads); // the case is the chunked one
}

} // namespace
} // namespace casteljau
