// Properties of the fixed-degree curves (Line, QuadBez, CubicBez), each test
// run for every degree on seeded random control points.
#include "casteljau/curve/bez.h"
#include "check.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

template <class C>
class BezTest : public ::testing::Test {
  protected:
    static C random(testing::Rng& rng) {
        C c;
        for (Point& p : c.p) p = rng.point(100);
        return c;
    }
};
using Degrees = ::testing::Types<Line, QuadBez, CubicBez>;
TYPED_TEST_SUITE(BezTest, Degrees);

constexpr double kEps = 1e-9; // relative to coordinates of size ~100

TYPED_TEST(BezTest, EndpointsInterpolateExactly) {
    testing::Rng rng(11);
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        EXPECT_EQ(c.eval(0), c.start());
        EXPECT_EQ(c.eval(1), c.end());
        EXPECT_EQ(c.eval_bernstein(0), c.start());
        EXPECT_EQ(c.eval_bernstein(1), c.end());
        const auto halves = c.split(rng.uniform(0, 1));
        EXPECT_EQ(halves[0].start(), c.start());
        EXPECT_EQ(halves[1].end(), c.end());
        EXPECT_EQ(halves[0].end(), halves[1].start());
    }
}

TYPED_TEST(BezTest, ThreeEvaluationsAgree) {
    testing::Rng rng(12);
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        const auto power = c.power();
        for (double t = 0; t <= 1.0; t += 0.0625) {
            const Point a = c.eval(t), b = c.eval_bernstein(t), p = power.eval(t);
            EXPECT_NEAR(a.x, b.x, kEps) << "t=" << t;
            EXPECT_NEAR(a.y, b.y, kEps) << "t=" << t;
            EXPECT_NEAR(a.x, p.x, kEps) << "t=" << t;
            EXPECT_NEAR(a.y, p.y, kEps) << "t=" << t;
        }
    }
}

TYPED_TEST(BezTest, SamplesLieInTheControlHull) {
    testing::Rng rng(13);
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        const auto hull = testing::convex_hull({c.p.begin(), c.p.end()});
        for (double t = 0; t <= 1.0; t += 1.0 / 64)
            EXPECT_LE(testing::distance_outside(hull, c.eval(t)), kEps)
                << "curve " << i << " t=" << t;
    }
}

TYPED_TEST(BezTest, AffineInvariance) {
    testing::Rng rng(14);
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        const Affine m{rng.uniform(-3, 3), rng.uniform(-3, 3),   rng.uniform(-3, 3),
                       rng.uniform(-3, 3), rng.uniform(-50, 50), rng.uniform(-50, 50)};
        const TypeParam mc = c.transformed(m);
        for (double t = 0; t <= 1.0; t += 0.1) {
            const Point a = mc.eval(t), b = m * c.eval(t);
            EXPECT_NEAR(a.x, b.x, kEps) << i;
            EXPECT_NEAR(a.y, b.y, kEps) << i;
        }
    }
}

TYPED_TEST(BezTest, SplitAndSubsegmentReproduceTheCurve) {
    testing::Rng rng(15);
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        const double t = rng.uniform(0.01, 0.99);
        const auto h = c.split(t);
        const double t0 = rng.uniform(0, 1), t1 = rng.uniform(0, 1);
        const TypeParam sub = c.subsegment(t0, t1);
        for (double s = 0; s <= 1.0; s += 0.125) {
            const Point l = h[0].eval(s), r = h[1].eval(s), ls = c.eval(s * t),
                        rs = c.eval(t + s * (1 - t));
            EXPECT_NEAR(l.x, ls.x, kEps);
            EXPECT_NEAR(l.y, ls.y, kEps);
            EXPECT_NEAR(r.x, rs.x, kEps);
            EXPECT_NEAR(r.y, rs.y, kEps);
            const Point a = sub.eval(s), b = c.eval(t0 + s * (t1 - t0));
            EXPECT_NEAR(a.x, b.x, 1e-8) << "t0=" << t0 << " t1=" << t1 << " s=" << s;
            EXPECT_NEAR(a.y, b.y, 1e-8) << "t0=" << t0 << " t1=" << t1 << " s=" << s;
        }
    }
}

TYPED_TEST(BezTest, DerivativesMatchFiniteDifferences) {
    testing::Rng rng(16);
    const double h = 1e-5;
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        for (double t = 0.05; t < 1.0; t += 0.1) {
            const Vec2 fd = (c.eval(t + h) - c.eval(t - h)) / (2 * h);
            const double h2 = 1e-3; // central second difference: exact for cubics up to rounding
            const Vec2 fd2 =
                ((c.eval(t + h2) - c.eval(t)) - (c.eval(t) - c.eval(t - h2))) / (h2 * h2);
            EXPECT_NEAR(c.deriv(t).x, fd.x, 1e-5) << "t=" << t;
            EXPECT_NEAR(c.deriv(t).y, fd.y, 1e-5) << "t=" << t;
            EXPECT_NEAR(c.deriv2(t).x, fd2.x, 1e-4) << "t=" << t;
            EXPECT_NEAR(c.deriv2(t).y, fd2.y, 1e-4) << "t=" << t;
        }
    }
}

TYPED_TEST(BezTest, BoundsContainAllSamplesAndAreTouched) {
    testing::Rng rng(17);
    for (int i = 0; i < 200; ++i) {
        const TypeParam c = this->random(rng);
        const Rect b = c.bounds();
        Rect sampled = Rect::empty();
        for (int k = 0; k <= 20000; ++k) sampled = sampled.united(c.eval(k / 20000.0));
        EXPECT_LE(b.x0, sampled.x0 + kEps);
        EXPECT_LE(b.y0, sampled.y0 + kEps);
        EXPECT_GE(b.x1, sampled.x1 - kEps);
        EXPECT_GE(b.y1, sampled.y1 - kEps);
        // Touched: dense sampling reaches every side (to its resolution).
        EXPECT_NEAR(b.x0, sampled.x0, 1e-5) << i;
        EXPECT_NEAR(b.y0, sampled.y0, 1e-5) << i;
        EXPECT_NEAR(b.x1, sampled.x1, 1e-5) << i;
        EXPECT_NEAR(b.y1, sampled.y1, 1e-5) << i;
    }
}

TEST(Bez, DegreeElevationPreservesTheCurve) {
    testing::Rng rng(18);
    for (int i = 0; i < 100; ++i) {
        const QuadBez q = testing::random_quad(rng, 100);
        const CubicBez c = q.elevate();
        for (double t = 0; t <= 1.0; t += 0.05) {
            EXPECT_NEAR(c.eval(t).x, q.eval(t).x, kEps);
            EXPECT_NEAR(c.eval(t).y, q.eval(t).y, kEps);
        }
    }
}

TEST(Bez, BoundsOfAKnownCubic) {
    // x(t) = 3t(1-t)^2 * 0 + ...: symmetric arch with apex y = 0.75 * 100.
    const CubicBez c{{0, 0}, {0, 100}, {100, 100}, {100, 0}};
    const Rect b = c.bounds();
    EXPECT_NEAR(b.y1, 75.0, 1e-12);
    EXPECT_EQ(b.x0, 0.0);
    EXPECT_EQ(b.x1, 100.0);
}

} // namespace
} // namespace casteljau
