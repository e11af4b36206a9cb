// Hit tests against references that share no code with them: dense sampling
// of the curves, the rasterizer's coverage, and closed forms.
#include "casteljau/curve/path_data.h"
#include "casteljau/hit/nearest.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/stroke_hit.h"
#include "casteljau/hit/winding.h"
#include "casteljau/raster/path_edges.h"
#include "casteljau/raster/rasterizer.h"
#include "check.h"
#include "corpus.h"
#include "coverage.h"

#include <cmath>
#include <gtest/gtest.h>
#include <limits>
#include <numbers>
#include <vector>

namespace casteljau {
namespace {

using testing::random_blob;
using testing::Rng;

Path parse(const char* d) {
    const PathDataResult r = parse_path_data(d);
    EXPECT_FALSE(r.error) << d;
    return r.path;
}

Segment random_segment(Rng& rng, double w) {
    switch (rng.integer(0, 3)) {
    case 0:
        return Line{rng.point(w), rng.point(w)};
    case 1:
        return testing::random_quad(rng, w);
    case 2:
        return testing::random_cubic(rng, w);
    default:
        return testing::random_conic(rng, w);
    }
}

// Minimum distance over n + 1 uniform samples, and the largest step between
// consecutive samples (the brute force's own resolution).
std::pair<double, double> sampled_distance(const Segment& s, Point q, int n) {
    double best = distance(segment_eval(s, 0.0), q), step = 0;
    Point prev = segment_eval(s, 0.0);
    for (int i = 1; i <= n; ++i) {
        const Point p = segment_eval(s, double(i) / n);
        best = std::min(best, distance(p, q));
        step = std::max(step, distance(p, prev));
        prev = p;
    }
    return {best, step};
}

TEST(Winding, ExactOnTheCircleNotOnAFlattening) {
    // A flattening at 0.25 px would misclassify points 1e-6 inside the arcs
    // between its vertices; the exact test does not.
    const Path circle = parse("M 100 0 A 100 100 0 1 1 -100 0 A 100 100 0 1 1 100 0 Z");
    for (int i = 0; i < 360; ++i) {
        const double a = (i + 0.37) * std::numbers::pi / 180;
        const Vec2 u{std::cos(a), std::sin(a)};
        EXPECT_TRUE(fill_contains(circle, Point{} + u * (100 - 1e-6))) << i;
        EXPECT_FALSE(fill_contains(circle, Point{} + u * (100 + 1e-6))) << i;
    }
    EXPECT_EQ(winding_number(circle, {0, 0}), winding_number(circle, {99.9, 0}));
    EXPECT_NE(winding_number(circle, {0, 0}), 0);
}

TEST(Winding, RayThroughVerticesAndTangentsCountsOnce) {
    // The ray from the centre of a diamond passes exactly through its right
    // vertex; from below a cubic's extremum it touches without crossing.
    const Path diamond = parse("M 0 -10 L 10 0 L 0 10 L -10 0 Z");
    EXPECT_EQ(std::abs(winding_number(diamond, {0, 0})), 1);
    EXPECT_EQ(winding_number(diamond, {-20, 0}), 0);
    const Path bump = parse("M 0 0 C 0 -40 40 -40 40 0 Z"); // extremum at y = -30
    EXPECT_EQ(winding_number(bump, {-10, -30}), 0);
    EXPECT_EQ(std::abs(winding_number(bump, {20, -29.999})), 1);
    EXPECT_EQ(winding_number(bump, {20, -30.001}), 0);
}

TEST(Winding, FillRulesOnOverlappingLoops) {
    // Two concentric squares drawn the same way: winding 2 in the middle.
    const Path p = parse("M 0 0 H 100 V 100 H 0 Z M 25 25 H 75 V 75 H 25 Z");
    EXPECT_EQ(std::abs(winding_number(p, {50, 50})), 2);
    EXPECT_TRUE(fill_contains(p, {50, 50}, FillRule::NonZero));
    EXPECT_FALSE(fill_contains(p, {50, 50}, FillRule::EvenOdd));
    EXPECT_TRUE(fill_contains(p, {10, 50}, FillRule::EvenOdd));
}

TEST(Winding, OpenSubpathsAreClosedForTheFill) {
    const Path p = parse("M 0 0 L 100 0 L 100 100");
    EXPECT_TRUE(fill_contains(p, {90, 10}));
    EXPECT_FALSE(fill_contains(p, {10, 90}));
}

TEST(Winding, AgreesWithRasterCoverageWellInsideAndOutside) {
    // Pixels the antialiased rasterizer covers fully or not at all must test
    // inside / outside, unless their centres are within a pixel of the outline.
    Rng rng(8);
    const int w = 64;
    int inside = 0, outside = 0;
    for (int trial = 0; trial < 24; ++trial) {
        const Path p = random_blob(rng, w, rng.integer(2, 6));
        for (FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
            EdgeList edges;
            edges.reset(w, w);
            add_path_edges(p, Affine::identity(), {}, edges);
            testing::CoverageImage img(w, w);
            Rasterizer().fill(edges, rule, true, img);
            for (int y = 0; y < w; ++y)
                for (int x = 0; x < w; ++x) {
                    const Point c{x + 0.5, y + 0.5};
                    const float cov = img.at(x, y);
                    if (cov > 1e-6f && cov < 1 - 1e-6f) continue;
                    const bool in = fill_contains(p, c, rule);
                    // Disagreement is allowed only within a pixel of the outline.
                    if (in != (cov > 0.5f))
                        EXPECT_LT(nearest_point(p, c).nearest.distance, 1)
                            << "trial " << trial << " rule " << int(rule) << " pixel " << x << ","
                            << y << " inside " << in << " coverage " << cov;
                    else
                        (in ? inside : outside) += 1;
                }
        }
    }
    EXPECT_GT(inside, 10000);
    EXPECT_GT(outside, 10000);
}

TEST(Nearest, MatchesDenseSamplingOnEveryKind) {
    Rng rng(21);
    for (int i = 0; i < 400; ++i) {
        const Segment s = random_segment(rng, 200);
        const Point q = {rng.uniform(-50, 250), rng.uniform(-50, 250)};
        const NearestPoint n = nearest_point(s, q);
        const auto [brute, step] = sampled_distance(s, q, 20000);
        EXPECT_LE(n.distance, brute + 1e-9) << i;
        EXPECT_GE(n.distance, brute - step) << i;
        EXPECT_GE(n.t, 0.0);
        EXPECT_LE(n.t, 1.0);
        EXPECT_LE(distance(n.point, segment_eval(s, n.t)), 1e-9) << i;
        EXPECT_NEAR(distance(n.point, q), n.distance, 1e-9) << i;
    }
}

TEST(Nearest, PicksTheGlobalMinimumAmongSeveral) {
    // An S-curve symmetric about (50, 0): from (50, 30) the distance has two
    // local minima of which only one is global once the point moves right.
    const CubicBez s{{0, 0}, {50, 100}, {50, -100}, {100, 0}};
    const NearestPoint right = nearest_point(s, {60, 30});
    const auto [brute, step] = sampled_distance(s, {60, 30}, 100000);
    EXPECT_NEAR(right.distance, brute, step);
    // End points: beyond the curve's end, the end is nearest.
    const NearestPoint end = nearest_point(s, {200, 0});
    EXPECT_EQ(end.t, 1.0);
    EXPECT_EQ(end.point, (Point{100, 0}));
    // Every point of a circular arc is nearest to its centre.
    const Conic arc = Conic::circular_arc({0, 0}, 10, 0, 2);
    EXPECT_NEAR(nearest_point(arc, {0, 0}).distance, 10, 1e-9);
}

TEST(Nearest, PathReportsSegmentAndParameter) {
    const Path p = parse("M 0 0 L 100 0 L 100 100");
    const PathNearestPoint n = nearest_point(p, {110, 40});
    EXPECT_EQ(n.segment, 1u);
    EXPECT_NEAR(n.nearest.t, 0.4, 1e-12);
    EXPECT_NEAR(n.nearest.distance, 10, 1e-12);
    EXPECT_TRUE(std::isinf(nearest_point(Path{}, {0, 0}).nearest.distance));
}

TEST(RectHit, MatchesDenseSampling) {
    Rng rng(5);
    int hits = 0, misses = 0;
    const int n = 20000;
    std::vector<Point> samples(n + 1); // each evaluated once (the test's cost)
    for (int i = 0; i < 2000; ++i) {
        const Segment s = random_segment(rng, 100);
        const Point a = rng.point(100);
        const Rect r = Rect::from_points(a, a + Vec2{rng.uniform(0, 30), rng.uniform(0, 30)});
        const bool hit = segment_intersects_rect(s, r);
        bool sampled_in = false, sampled_near = false;
        double step = 0;
        for (int k = 0; k <= n; ++k) {
            samples[std::size_t(k)] = segment_eval(s, double(k) / n);
            if (k > 0)
                step =
                    std::max(step, distance(samples[std::size_t(k)], samples[std::size_t(k - 1)]));
            sampled_in |= r.contains(samples[std::size_t(k)]);
        }
        const Rect near = r.inflated(step);
        for (int k = 0; k <= n && !sampled_near; ++k)
            sampled_near |= near.contains(samples[std::size_t(k)]);
        if (sampled_in) {
            EXPECT_TRUE(hit) << i;
        }
        if (!sampled_near) {
            EXPECT_FALSE(hit) << i;
        }
        (hit ? hits : misses) += 1;
    }
    EXPECT_GT(hits, 200);
    EXPECT_GT(misses, 200);
}

TEST(RectHit, CurveThroughRectWithEndsAndControlPointsOutside) {
    // The cubic bulges through the rectangle; no control point is in it.
    const CubicBez s{{0, 0}, {0, 100}, {100, 100}, {100, 0}};
    EXPECT_TRUE(segment_intersects_rect(s, {40, 70, 60, 80}));  // around the apex at y = 75
    EXPECT_FALSE(segment_intersects_rect(s, {40, 76, 60, 90})); // just above it
    EXPECT_FALSE(segment_intersects_rect(s, {40, 40, 60, 60})); // in the hull, under the curve
}

TEST(RectHit, FillContainsTheRectOrNot) {
    const Path circle = parse("M 100 0 A 100 100 0 1 1 -100 0 A 100 100 0 1 1 100 0 Z");
    EXPECT_TRUE(fill_intersects_rect(circle, {-10, -10, 10, 10}));
    EXPECT_FALSE(outline_intersects_rect(circle, {-10, -10, 10, 10}));
    EXPECT_FALSE(fill_intersects_rect(circle, {80, 80, 90, 90})); // corner outside the circle
    EXPECT_TRUE(fill_intersects_rect(circle, {-500, -500, 500, 500}));
}

TEST(StrokeHit, RoundStrokeDistanceIsCentrelineDistanceMinusHalfWidth) {
    StrokeGeometry g;
    g.width = 12;
    g.cap = LineCap::Round;
    g.join = LineJoin::Round;
    const Path p = parse("M 10 10 C 60 120 90 -60 150 60 L 60 90");
    Rng rng(3);
    for (int i = 0; i < 300; ++i) {
        const Point q{rng.uniform(-20, 180), rng.uniform(-20, 130)};
        const double expect = std::max(0.0, nearest_point(p, q).nearest.distance - 6);
        EXPECT_NEAR(stroke_distance(p, g, q, 1e-3), expect, 1.01e-3) << i;
    }
}

TEST(StrokeHit, DashGapsAndButtCapsAreOutside) {
    StrokeGeometry g;
    g.width = 10;
    g.dashes = {10, 10};
    const Path p = parse("M 0 0 L 100 0");
    EXPECT_NEAR(stroke_distance(p, g, {15, 0}), 5, 1e-9); // middle of the first gap
    EXPECT_EQ(stroke_distance(p, g, {5, 4}), 0);
    EXPECT_NEAR(stroke_distance(p, g, {-3, 0}), 3, 1e-9); // butt cap: no reach past the end
}

// Regression: an infinite tolerance made the stroker's sample steps NaN, and
// stroke_distance never returned. No outline is built: nothing is near.
TEST(StrokeHit, ANonFiniteToleranceOrWidthHasNoOutline) {
    StrokeGeometry g;
    g.width = 6;
    const Path p = parse("M 0 0 C 10 0 10 10 0 10");
    const double inf = std::numeric_limits<double>::infinity();
    for (const double tol : {inf, std::numeric_limits<double>::quiet_NaN(), 0.0}) {
        EXPECT_EQ(stroke_distance(p, g, {5, 5}, tol), inf) << tol;
        EXPECT_TRUE(stroke_bounds(p, g, tol).is_empty()) << tol;
    }
    EXPECT_TRUE(std::isfinite(stroke_distance(p, g, {5, 5}, 1e300))) << "a finite one draws";
    g.width = inf;
    EXPECT_EQ(stroke_distance(p, g, {5, 5}), inf);
    g.width = 6;
    EXPECT_EQ(stroke_distance(parse("M 5 5 L 5 5"), g, {5, 5}), inf) << "butt caps: nothing";
}

TEST(StrokeHit, BoundsAreTightWithinTolerance) {
    StrokeGeometry g;
    g.width = 10;
    // Miter joins and butt caps: the corner's miter tip reaches (105, -5).
    const Rect miter = stroke_bounds(parse("M 0 0 L 100 0 L 100 100"), g, 1e-3);
    const Rect expect_miter{0, -5, 105, 100};
    EXPECT_NEAR(miter.x0, expect_miter.x0, 1.01e-3);
    EXPECT_NEAR(miter.y0, expect_miter.y0, 1.01e-3);
    EXPECT_NEAR(miter.x1, expect_miter.x1, 1.01e-3);
    EXPECT_NEAR(miter.y1, expect_miter.y1, 1.01e-3);
    // Round caps and joins: the curve's tight bounds grown by the half width.
    g.cap = LineCap::Round;
    g.join = LineJoin::Round;
    const Path curve = parse("M 10 10 C 60 120 90 -60 150 60 Q 100 200 20 100");
    const Rect b = stroke_bounds(curve, g, 1e-3), c = fill_bounds(curve).inflated(5);
    EXPECT_GE(c.x0, b.x0);
    EXPECT_LE(c.x1, b.x1);
    EXPECT_NEAR(b.x0, c.x0, 1.01e-3);
    EXPECT_NEAR(b.y0, c.y0, 1.01e-3);
    EXPECT_NEAR(b.x1, c.x1, 1.01e-3);
    EXPECT_NEAR(b.y1, c.y1, 1.01e-3);
}

TEST(FillBounds, CircleIsExact) {
    const Rect b = fill_bounds(parse("M 100 0 A 100 100 0 1 1 -100 0 A 100 100 0 1 1 100 0 Z"));
    EXPECT_NEAR(b.x0, -100, 1e-9);
    EXPECT_NEAR(b.y0, -100, 1e-9);
    EXPECT_NEAR(b.x1, 100, 1e-9);
    EXPECT_NEAR(b.y1, 100, 1e-9);
}

} // namespace
} // namespace casteljau
