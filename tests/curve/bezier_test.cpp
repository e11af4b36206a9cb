// The runtime-degree Bezier against its own three evaluations, against the
// fixed-degree types, and through split, elevation and bounds.
#include "casteljau/curve/bez.h"
#include "casteljau/curve/bezier.h"
#include "check.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(Bezier, DeCasteljauBernsteinAndPowerFormAgreeUpToDegree12) {
    testing::Rng rng(21);
    for (int degree = 1; degree <= 12; ++degree) {
        for (int i = 0; i < 30; ++i) {
            const Bezier b = testing::random_bezier(rng, degree, 100);
            const PowerForm pf = b.power();
            // The power basis loses digits as the degree grows (its coefficients
            // reach C(n, n/2) 2^n times the point size): the bound follows that.
            const double tol = 1e-12 * 100 * binomial(degree, degree / 2) * double(1 << degree);
            for (double t = 0; t <= 1.0; t += 1.0 / 32) {
                const Point a = b.eval(t), c = b.eval_bernstein(t), p = pf.eval(t);
                EXPECT_NEAR(a.x, c.x, 1e-9) << "degree " << degree << " t=" << t;
                EXPECT_NEAR(a.y, c.y, 1e-9) << "degree " << degree << " t=" << t;
                EXPECT_NEAR(a.x, p.x, tol) << "degree " << degree << " t=" << t;
                EXPECT_NEAR(a.y, p.y, tol) << "degree " << degree << " t=" << t;
            }
            EXPECT_EQ(b.eval(0), b.start());
            EXPECT_EQ(b.eval(1), b.end());
        }
    }
}

TEST(Bezier, MatchesTheFixedCubic) {
    testing::Rng rng(22);
    for (int i = 0; i < 100; ++i) {
        const CubicBez c = testing::random_cubic(rng, 100);
        const Bezier b = Bezier::from(c.p);
        for (double t = 0; t <= 1.0; t += 0.1) {
            EXPECT_EQ(b.eval(t), c.eval(t));
            EXPECT_NEAR(b.deriv(t).x, c.deriv(t).x, 1e-9);
            EXPECT_NEAR(b.deriv2(t).y, c.deriv2(t).y, 1e-9);
        }
        const Rect rb = b.bounds(), rc = c.bounds();
        EXPECT_NEAR(rb.x0, rc.x0, 1e-9);
        EXPECT_NEAR(rb.y1, rc.y1, 1e-9);
    }
}

TEST(Bezier, HullSplitElevationAndBoundsAtHighDegree) {
    testing::Rng rng(23);
    for (int degree : {4, 5, 7, 10}) {
        for (int i = 0; i < 20; ++i) {
            const Bezier b = testing::random_bezier(rng, degree, 100);
            const auto pts = b.points();
            const auto hull = testing::convex_hull({pts.begin(), pts.end()});
            const Bezier e = b.elevate();
            const double t = rng.uniform(0.1, 0.9);
            const auto h = b.split(t);
            const Rect box = b.bounds();
            Rect sampled = Rect::empty();
            for (int k = 0; k <= 4000; ++k) {
                const double s = k / 4000.0;
                const Point p = b.eval(s);
                sampled = sampled.united(p);
                EXPECT_LE(testing::distance_outside(hull, p), 1e-9);
                EXPECT_NEAR(e.eval(s).x, p.x, 1e-9) << "degree " << degree;
                const Point l = h[0].eval(s), ls = b.eval(s * t);
                EXPECT_NEAR(l.x, ls.x, 1e-9);
                EXPECT_NEAR(l.y, ls.y, 1e-9);
            }
            EXPECT_NEAR(box.x0, sampled.x0, 1e-4) << "degree " << degree;
            EXPECT_NEAR(box.x1, sampled.x1, 1e-4) << "degree " << degree;
            EXPECT_NEAR(box.y0, sampled.y0, 1e-4) << "degree " << degree;
            EXPECT_NEAR(box.y1, sampled.y1, 1e-4) << "degree " << degree;
            EXPECT_LE(box.x0, sampled.x0 + 1e-9);
            EXPECT_GE(box.y1, sampled.y1 - 1e-9);
        }
    }
}

TEST(Bezier, DerivativesMatchFiniteDifferencesAtDegree6) {
    testing::Rng rng(24);
    for (int i = 0; i < 30; ++i) {
        const Bezier b = testing::random_bezier(rng, 6, 100);
        for (double t = 0.05; t < 1.0; t += 0.1) {
            const double h = 1e-5, h2 = 1e-4;
            const Vec2 fd = (b.eval(t + h) - b.eval(t - h)) / (2 * h);
            const Vec2 fd2 =
                ((b.eval(t + h2) - b.eval(t)) - (b.eval(t) - b.eval(t - h2))) / (h2 * h2);
            EXPECT_NEAR(b.deriv(t).x, fd.x, 1e-4);
            EXPECT_NEAR(b.deriv(t).y, fd.y, 1e-4);
            EXPECT_NEAR(b.deriv2(t).x, fd2.x, 0.05) << t;
            EXPECT_NEAR(b.deriv2(t).y, fd2.y, 0.05) << t;
        }
    }
}

} // namespace
} // namespace casteljau
