// Conics (exact circles, split, bounds) and SVG arcs against the spec's notes.
#include "casteljau/curve/arc.h"
#include "casteljau/curve/conic.h"
#include "casteljau/curve/path.h"
#include "corpus.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <numbers>

namespace casteljau {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Conic, CircularArcIsExact) {
    testing::Rng rng(41);
    for (int i = 0; i < 100; ++i) {
        const Point c = rng.point(100);
        const double r = rng.log_uniform(0.1, 1000);
        const double a0 = rng.uniform(-kPi, kPi), a1 = a0 + rng.uniform(-2.5, 2.5);
        const Conic arc = Conic::circular_arc(c, r, a0, a1);
        for (double t = 0; t <= 1.0; t += 1.0 / 64)
            EXPECT_NEAR(distance(arc.eval(t), c), r, 1e-12 * r * 4) << "t=" << t;
    }
}

TEST(Conic, SplitSubsegmentAndDerivatives) {
    testing::Rng rng(42);
    for (int i = 0; i < 200; ++i) {
        const Conic c = testing::random_conic(rng, 100);
        const double t = rng.uniform(0.05, 0.95);
        const auto h = c.split(t);
        EXPECT_EQ(h[0].start(), c.start());
        EXPECT_EQ(h[1].end(), c.end());
        // The halves are the same point set: each half's samples lie on the
        // whole curve at some parameter; compare through the shared points.
        EXPECT_NEAR(h[0].end().x, c.eval(t).x, 1e-9);
        EXPECT_NEAR(h[0].end().y, c.eval(t).y, 1e-9);
        const Conic sub = c.subsegment(0.2, 0.7);
        EXPECT_NEAR(sub.start().x, c.eval(0.2).x, 1e-9);
        EXPECT_NEAR(sub.end().y, c.eval(0.7).y, 1e-9);
        for (double s = 0.05; s < 1.0; s += 0.1) {
            const double eps = 1e-5, eps2 = 1e-3;
            const Vec2 fd = (c.eval(s + eps) - c.eval(s - eps)) / (2 * eps);
            const Vec2 fd2 =
                ((c.eval(s + eps2) - c.eval(s)) - (c.eval(s) - c.eval(s - eps2))) / (eps2 * eps2);
            const double scale = 1 + c.deriv(s).length();
            EXPECT_NEAR(c.deriv(s).x, fd.x, 1e-5 * scale) << i;
            EXPECT_NEAR(c.deriv(s).y, fd.y, 1e-5 * scale) << i;
            const double scale2 = 1 + c.deriv2(s).length();
            EXPECT_NEAR(c.deriv2(s).x, fd2.x, 1e-3 * scale2) << i << " s=" << s;
            EXPECT_NEAR(c.deriv2(s).y, fd2.y, 1e-3 * scale2) << i << " s=" << s;
        }
    }
}

TEST(Conic, HalvesLieOnTheOriginalConic) {
    // In barycentric coordinates (b0, b1, b2) of the control triangle, the
    // conic C(t) has b0 = (1-t)^2 / D, b1 = 2wt(1-t) / D, b2 = t^2 / D, so it
    // satisfies b1^2 = 4 w^2 b0 b2 with every b >= 0: the implicit equation.
    testing::Rng rng(43);
    int checked = 0;
    for (int i = 0; i < 200; ++i) {
        const Conic c = testing::random_conic(rng, 100);
        const double area = (c.p1 - c.p0).cross(c.p2 - c.p0);
        if (std::fabs(area) < 100) continue; // nearly collinear: barycentrics ill-conditioned
        const auto h = c.split(rng.uniform(0.1, 0.9));
        for (const Conic& half : h) {
            for (double s = 0; s <= 1.0; s += 0.125) {
                const Point p = half.eval(s);
                const double b1 = (p - c.p0).cross(c.p2 - c.p0) / area;
                const double b2 = (c.p1 - c.p0).cross(p - c.p0) / area;
                const double b0 = 1 - b1 - b2;
                EXPECT_NEAR(b1 * b1, 4 * c.w * c.w * b0 * b2, 1e-9 * (1 + c.w * c.w)) << i;
                EXPECT_GE(std::min({b0, b1, b2}), -1e-9) << i;
                ++checked;
            }
        }
    }
    EXPECT_GT(checked, 1000);
}

TEST(Conic, BoundsContainAndTouch) {
    testing::Rng rng(44);
    for (int i = 0; i < 100; ++i) {
        const Conic c = testing::random_conic(rng, 100);
        const Rect b = c.bounds();
        Rect s = Rect::empty();
        for (int k = 0; k <= 20000; ++k) s = s.united(c.eval(k / 20000.0));
        EXPECT_NEAR(b.x0, s.x0, 1e-3) << i;
        EXPECT_NEAR(b.x1, s.x1, 1e-3) << i;
        EXPECT_NEAR(b.y0, s.y0, 1e-3) << i;
        EXPECT_NEAR(b.y1, s.y1, 1e-3) << i;
        EXPECT_LE(b.x0, s.x0 + 1e-9);
        EXPECT_GE(b.y1, s.y1 - 1e-9);
    }
}

TEST(SvgArc, SpecExampleLargeArcAroundKnownCentre) {
    // SVG 1.1 section 8.3.8's first example: "M300,200 h-150 a150,150 0 1,0 150,-150 z".
    const EllipseArc a = svg_arc({{150, 200}, {300, 50}, {150, 150}, 0, true, false});
    ASSERT_EQ(a.kind, EllipseArc::Kind::Arc);
    EXPECT_NEAR(a.center.x, 300, 1e-9);
    EXPECT_NEAR(a.center.y, 200, 1e-9);
    EXPECT_NEAR(a.dtheta, -1.5 * kPi, 1e-12);
    EXPECT_NEAR(a.theta1, kPi, 1e-12);
    // Same arc, other flags: the small arc around the other centre.
    const EllipseArc b = svg_arc({{150, 200}, {300, 50}, {150, 150}, 0, false, true});
    EXPECT_NEAR(b.center.x, 300, 1e-9);
    EXPECT_NEAR(b.dtheta, 0.5 * kPi, 1e-12);
    const EllipseArc c = svg_arc({{150, 200}, {300, 50}, {150, 150}, 0, false, false});
    EXPECT_NEAR(c.center.x, 150, 1e-9);
    EXPECT_NEAR(c.center.y, 50, 1e-9);
}

TEST(SvgArc, OutOfRangeRadiiAreScaledUp) {
    // F.6.6: radius 1 cannot span 10 units; it becomes 5, a half circle.
    const EllipseArc a = svg_arc({{0, 0}, {10, 0}, {1, 1}, 0, false, true});
    EXPECT_NEAR(a.radii.x, 5, 1e-12);
    EXPECT_NEAR(a.radii.y, 5, 1e-12);
    EXPECT_NEAR(a.center.x, 5, 1e-12);
    EXPECT_NEAR(a.center.y, 0, 1e-12);
    EXPECT_NEAR(std::fabs(a.dtheta), kPi, 1e-12);
    // Negative radii take their absolute value.
    const EllipseArc n = svg_arc({{0, 0}, {10, 0}, {-1, -1}, 0, false, true});
    EXPECT_NEAR(n.radii.x, 5, 1e-12);
    // Elliptic radii keep their ratio.
    const EllipseArc e = svg_arc({{0, 0}, {10, 0}, {1, 2}, 0, false, true});
    EXPECT_NEAR(e.radii.y / e.radii.x, 2, 1e-12);
}

TEST(SvgArc, ZeroRadiusIsALineAndCoincidentEndsAreNothing) {
    EXPECT_EQ(svg_arc({{0, 0}, {10, 0}, {0, 5}, 0, false, true}).kind, EllipseArc::Kind::Line);
    EXPECT_EQ(svg_arc({{3, 3}, {3, 3}, {5, 5}, 0, false, true}).kind, EllipseArc::Kind::Nothing);
    Path p;
    p.move_to({0, 0});
    p.arc_to({0, 5}, 0, false, true, {10, 0});
    ASSERT_EQ(p.segment_count(), 1u);
    EXPECT_TRUE(std::holds_alternative<Line>(p.subpaths()[0].segments[0]));
}

TEST(SvgArc, ConicsLieOnTheEllipseAndCubicsClose) {
    testing::Rng rng(45);
    for (int i = 0; i < 200; ++i) {
        const SvgArcInput in{rng.point(100),
                             rng.point(100),
                             {rng.uniform(1, 80), rng.uniform(1, 80)},
                             rng.uniform(-180, 180),
                             rng.integer(0, 1) == 1,
                             rng.integer(0, 1) == 1};
        const EllipseArc arc = svg_arc(in);
        const Affine to_unit = arc.unit_circle_map().inverse();
        std::array<Conic, 4> conics;
        std::array<CubicBez, 4> cubics;
        const int n = svg_arc_to_conics(in, conics);
        ASSERT_EQ(svg_arc_to_cubics(in, cubics), n);
        EXPECT_EQ(conics[0].start(), in.from);
        EXPECT_EQ(conics[n - 1].end(), in.to);
        EXPECT_EQ(cubics[n - 1].end(), in.to);
        for (int k = 0; k < n; ++k) {
            for (double t = 0; t <= 1.0; t += 0.125) {
                const double rc = (to_unit * conics[k].eval(t)).to_vec().length();
                const double rq = (to_unit * cubics[k].eval(t)).to_vec().length();
                EXPECT_NEAR(rc, 1.0, 1e-9) << "arc " << i << " piece " << k;
                EXPECT_NEAR(rq, 1.0, 3e-4) << "arc " << i << " piece " << k;
            }
        }
    }
}

} // namespace
} // namespace casteljau
