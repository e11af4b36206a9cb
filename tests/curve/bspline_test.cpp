#include "casteljau/curve/bspline.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

// A random valid knot vector: clamped (end multiplicity p + 1) or not, with
// interior knots repeated up to multiplicity p.
std::vector<double> random_knots(testing::Rng& rng, int p, std::size_t n, bool clamped) {
    const std::size_t total = n + std::size_t(p) + 1;
    std::vector<double> t;
    double u = 0;
    if (clamped) t.assign(std::size_t(p) + 1, 0.0);
    const std::size_t interior_end = clamped ? total - std::size_t(p) - 1 : total;
    while (t.size() < interior_end) {
        u += rng.uniform(0.2, 1.5);
        const std::size_t mult =
            std::min<std::size_t>(std::size_t(rng.integer(1, p)), interior_end - t.size());
        t.insert(t.end(), mult, u);
    }
    if (clamped) t.insert(t.end(), std::size_t(p) + 1, u + rng.uniform(0.2, 1.5));
    return t;
}

BSpline random_bspline(testing::Rng& rng) {
    BSpline s;
    do { // a few draws have an empty domain; draw again
        s.degree = rng.integer(1, 5);
        const std::size_t n = std::size_t(s.degree) + 1 + std::size_t(rng.integer(0, 6));
        s.points.clear();
        for (std::size_t i = 0; i < n; ++i) s.points.push_back(rng.point(100));
        s.knots = random_knots(rng, s.degree, n, rng.integer(0, 1) == 1);
    } while (!s.validate().empty());
    return s;
}

// Evaluates the Bezier pieces at global u: piece k covers the k-th nonempty span.
template <class Spline, class Pieces>
Point eval_pieces(const Spline& s, const Pieces& pieces, double u) {
    std::vector<double> breaks;
    for (std::size_t k = std::size_t(s.degree); k < s.points.size(); ++k)
        if (s.knots[k] < s.knots[k + 1]) breaks.push_back(s.knots[k]);
    breaks.push_back(s.domain_end());
    std::size_t k = 0;
    while (k + 2 < breaks.size() && u >= breaks[k + 1]) ++k;
    return pieces[k].eval((u - breaks[k]) / (breaks[k + 1] - breaks[k]));
}

TEST(BSpline, ValidationNamesTheProblem) {
    BSpline s{3, {{0, 0}, {1, 1}, {2, 0}, {3, 1}}, {0, 0, 0, 0, 1, 1, 1}};
    EXPECT_NE(s.validate().find("expected 8 knots"), std::string::npos) << s.validate();
    s.knots = {0, 0, 0, 0, 1, 1, 1, 1};
    EXPECT_EQ(s.validate(), "");
    s.knots = {0, 0, 0, 1, 0, 1, 1, 1};
    EXPECT_NE(s.validate().find("decrease"), std::string::npos);
    s.degree = 0;
    EXPECT_NE(s.validate().find("degree"), std::string::npos);
    Nurbs n = Nurbs::circle({0, 0}, 1);
    n.weights[3] = -1;
    EXPECT_NE(n.validate().find("weight 3"), std::string::npos);
}

TEST(BSpline, ClampedCubicIsItsBezier) {
    // A clamped cubic with four points is exactly the Bezier curve.
    const BSpline s{3, {{0, 0}, {10, 30}, {40, 30}, {50, 0}}, clamped_uniform_knots(3, 4)};
    const CubicBez c{{0, 0}, {10, 30}, {40, 30}, {50, 0}};
    for (double u = 0; u <= 1.0; u += 0.05) {
        EXPECT_NEAR(s.eval(u).x, c.eval(u).x, 1e-12);
        EXPECT_NEAR(s.eval(u).y, c.eval(u).y, 1e-12);
    }
}

TEST(BSpline, KnotInsertionAndBezierConversionPreserveTheCurve) {
    testing::Rng rng(51);
    for (int i = 0; i < 300; ++i) {
        const BSpline s = random_bspline(rng);
        ASSERT_EQ(s.validate(), "") << "case " << i;
        BSpline inserted = s;
        inserted.insert_knot(rng.uniform(s.domain_start(), s.domain_end()));
        ASSERT_EQ(inserted.validate(), "");
        const auto pieces = s.to_beziers();
        for (int k = 0; k <= 50; ++k) {
            const double u = s.domain_start() + (s.domain_end() - s.domain_start()) * k / 50;
            const Point a = s.eval(u), b = inserted.eval(u), c = eval_pieces(s, pieces, u);
            EXPECT_NEAR(a.x, b.x, 1e-9) << "case " << i << " degree " << s.degree << " u=" << u;
            EXPECT_NEAR(a.y, b.y, 1e-9) << "case " << i << " u=" << u;
            EXPECT_NEAR(a.x, c.x, 1e-9) << "case " << i << " degree " << s.degree << " u=" << u;
            EXPECT_NEAR(a.y, c.y, 1e-9) << "case " << i << " u=" << u;
        }
        // Pieces join end to end (C0 at least).
        for (std::size_t k = 1; k < pieces.size(); ++k) {
            EXPECT_NEAR(pieces[k - 1].end().x, pieces[k].start().x, 1e-9);
            EXPECT_NEAR(pieces[k - 1].end().y, pieces[k].start().y, 1e-9);
        }
    }
}

TEST(Nurbs, CircleRadiusIsExact) {
    for (const auto& [c, r] : {std::pair{Point{0, 0}, 1.0}, std::pair{Point{3, -4}, 2.5}}) {
        const Nurbs n = Nurbs::circle(c, r);
        ASSERT_EQ(n.validate(), "");
        for (int k = 0; k <= 1000; ++k)
            EXPECT_NEAR(distance(n.eval(k / 1000.0), c), r, 1e-12 * std::max(1.0, r)) << k;
        const auto pieces = n.to_beziers();
        EXPECT_EQ(pieces.size(), 4u);
        for (const RationalBezier& b : pieces)
            for (double t = 0; t <= 1.0; t += 0.01)
                EXPECT_NEAR(distance(b.eval(t), c), r, 1e-12 * 4);
    }
}

TEST(Nurbs, RandomWeightsConvertAndInsertExactly) {
    testing::Rng rng(52);
    for (int i = 0; i < 200; ++i) {
        const BSpline s = random_bspline(rng);
        Nurbs n{s.degree, s.points, {}, s.knots};
        for (std::size_t k = 0; k < n.points.size(); ++k)
            n.weights.push_back(rng.log_uniform(0.1, 10));
        ASSERT_EQ(n.validate(), "");
        Nurbs inserted = n;
        inserted.insert_knot(rng.uniform(n.domain_start(), n.domain_end()));
        const auto pieces = n.to_beziers();
        for (int k = 0; k <= 40; ++k) {
            const double u = n.domain_start() + (n.domain_end() - n.domain_start()) * k / 40;
            const Point a = n.eval(u), b = inserted.eval(u), c = eval_pieces(n, pieces, u);
            EXPECT_NEAR(a.x, b.x, 1e-9) << "case " << i;
            EXPECT_NEAR(a.y, c.y, 1e-9) << "case " << i << " degree " << n.degree;
            EXPECT_NEAR(a.x, c.x, 1e-9) << "case " << i << " degree " << n.degree;
        }
    }
}

} // namespace
} // namespace casteljau
