// Editing: handle moves keep each joint's continuity (checked with the
// continuity query), and C2 interpolation through points.
#include "casteljau/curve/bspline.h"
#include "casteljau/curve/path_data.h"
#include "casteljau/edit/bezier_spline.h"
#include "casteljau/edit/interpolate.h"
#include "check.h"
#include "corpus.h"

#include <cmath>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

using testing::Rng;

std::vector<Point> random_points(Rng& rng, int n) {
    std::vector<Point> p;
    for (int i = 0; i < n; ++i) p.push_back(rng.point(500));
    return p;
}

// The weakest continuity a mode promises.
Continuity promised(JointMode m) {
    switch (m) {
    case JointMode::Corner:
        return Continuity::C0;
    case JointMode::Smooth:
        return Continuity::G1;
    case JointMode::Symmetric:
        return Continuity::C1;
    }
    return Continuity::None;
}

BezierSpline random_spline(Rng& rng, int anchors, bool closed) {
    BezierSpline s;
    for (int i = 0; i < anchors; ++i) {
        const Point p = rng.point(500);
        s.add_anchor({p, p + Vec2{rng.uniform(-50, 50), rng.uniform(-50, 50)},
                      p + Vec2{rng.uniform(-50, 50), rng.uniform(-50, 50)}, JointMode::Corner});
    }
    s.set_closed(closed);
    return s;
}

TEST(Interpolate, PassesThroughThePointsWithC2Joints) {
    Rng rng(11);
    for (bool closed : {false, true}) {
        for (int n : {2, 3, 4, 7, 30}) {
            if (closed && n == 2) continue; // a loop through two points is degenerate
            const std::vector<Point> pts = random_points(rng, n);
            Path path;
            const Subpath sp = interpolate_c2(pts, closed);
            ASSERT_EQ(sp.segments.size(), closed ? std::size_t(n) : std::size_t(n - 1));
            for (std::size_t i = 0; i < sp.segments.size(); ++i) {
                EXPECT_LE(distance(segment_start(sp.segments[i]), pts[i]), 1e-9)
                    << n << " closed " << closed << " segment " << i;
                EXPECT_LE(distance(segment_end(sp.segments[i]), pts[(i + 1) % pts.size()]), 1e-9);
            }
            const std::size_t joints = closed ? sp.segments.size() : sp.segments.size() - 1;
            for (std::size_t j = 0; j < joints; ++j)
                EXPECT_EQ(joint_continuity(sp.segments[j],
                                           sp.segments[(j + 1) % sp.segments.size()], 1e-7),
                          Continuity::C2)
                    << n << " closed " << closed << " joint " << j;
            if (!closed) { // natural ends
                EXPECT_LE(segment_deriv2(sp.segments.front(), 0).length(), 1e-8);
                EXPECT_LE(segment_deriv2(sp.segments.back(), 1).length(), 1e-8);
            }
        }
    }
}

TEST(Interpolate, FewPointsGiveAPointOrALine) {
    const std::vector<Point> one{{3, 4}};
    EXPECT_TRUE(interpolate_c2(one).segments.empty());
    const std::vector<Point> two{{0, 0}, {30, 0}};
    const Subpath line = interpolate_c2(two);
    ASSERT_EQ(line.segments.size(), 1u);
    EXPECT_NEAR(segment_eval(line.segments[0], 0.5).x, 15, 1e-12);
    EXPECT_NEAR(segment_eval(line.segments[0], 0.5).y, 0, 1e-12);
}

TEST(UniformBSpline, BezierPiecesMatchDeBoor) {
    // The same curve through the general B-spline code: uniform knots 0..n+3.
    Rng rng(2);
    const std::vector<Point> d = random_points(rng, 9);
    BSpline b{3, d, {}};
    for (std::size_t i = 0; i < d.size() + 4; ++i) b.knots.push_back(double(i));
    ASSERT_EQ(b.validate(), "");
    const std::vector<CubicBez> pieces = uniform_bspline_to_beziers(d, false);
    ASSERT_EQ(pieces.size(), d.size() - 3);
    for (std::size_t k = 0; k < pieces.size(); ++k)
        for (double t : {0.0, 0.3, 0.5, 0.9})
            EXPECT_LE(distance(pieces[k].eval(t), b.eval(3.0 + double(k) + t)), 1e-9)
                << k << " " << t;
}

TEST(BezierSpline, HandleMovesKeepEachJointsContinuity) {
    Rng rng(17);
    for (bool closed : {false, true}) {
        BezierSpline s = random_spline(rng, 8, closed);
        const JointMode modes[] = {JointMode::Corner, JointMode::Smooth, JointMode::Symmetric};
        for (std::size_t i = 0; i < s.anchor_count(); ++i) s.set_mode(i, modes[i % 3]);
        for (int move = 0; move < 500; ++move) {
            const std::size_t i = std::size_t(rng.integer(0, int(s.anchor_count()) - 1));
            const Point to = rng.point(500);
            switch (rng.integer(0, 2)) {
            case 0:
                s.move_anchor(i, to);
                break;
            case 1:
                s.move_handle(i, HandleSide::In, to);
                break;
            default:
                s.move_handle(i, HandleSide::Out, to);
                break;
            }
            for (std::size_t j = 0; j < s.anchor_count(); ++j) {
                if (!s.is_joint(j)) continue;
                EXPECT_GE(s.continuity(j, 1e-9), promised(s.anchor(j).mode))
                    << "move " << move << " anchor " << j << " closed " << closed;
            }
        }
    }
}

TEST(BezierSpline, SmoothIsG1NotC1AndCornerBreaksTangents) {
    BezierSpline s;
    s.add_anchor({{0, 0}, {0, 0}, {30, 0}, JointMode::Corner});
    s.add_anchor({{100, 0}, {70, 0}, {130, 0}, JointMode::Smooth});
    s.add_anchor({{200, 0}, {170, 50}, {200, 0}, JointMode::Corner});
    s.move_handle(1, HandleSide::Out, {100 + 60, 80}); // twin turns, keeps length 30
    EXPECT_EQ(s.continuity(1), Continuity::G1);
    EXPECT_NEAR(distance(s.anchor(1).in, s.anchor(1).point), 30, 1e-12);
    s.set_mode(1, JointMode::Symmetric);
    EXPECT_GE(s.continuity(1), Continuity::C1);
    s.set_mode(1, JointMode::Corner);
    s.move_handle(1, HandleSide::In, {100, -40});
    EXPECT_EQ(s.continuity(1), Continuity::C0);
    EXPECT_EQ(s.continuity(0), Continuity::None); // an open end is no joint
}

TEST(BezierSpline, MovingAnAnchorCarriesItsHandles) {
    Rng rng(4);
    BezierSpline s = random_spline(rng, 5, false);
    const Anchor before = s.anchor(2);
    s.move_anchor(2, before.point + Vec2{7, -3});
    EXPECT_EQ(s.anchor(2).in - s.anchor(2).point, before.in - before.point);
    EXPECT_EQ(s.anchor(2).out - s.anchor(2).point, before.out - before.point);
}

TEST(BezierSpline, SubpathRoundTripAndInferredModes) {
    // A C2 curve through points: every inner joint is inferred symmetric.
    Rng rng(9);
    const std::vector<Point> pts = random_points(rng, 6);
    const Subpath c2 = interpolate_c2(pts, true);
    const BezierSpline s = BezierSpline::from_subpath(c2);
    EXPECT_TRUE(s.closed());
    ASSERT_EQ(s.anchor_count(), pts.size());
    for (std::size_t i = 0; i < s.anchor_count(); ++i) {
        EXPECT_EQ(s.anchor(i).mode, JointMode::Symmetric) << i;
        EXPECT_EQ(s.continuity(i, 1e-7), Continuity::C2) << i;
    }
    Path path;
    path.add_subpath(s.to_subpath());
    ASSERT_EQ(path.subpaths().size(), 1u);
    const Subpath& back = path.subpaths()[0];
    EXPECT_TRUE(back.closed);
    ASSERT_EQ(back.segments.size(), c2.segments.size());
    for (std::size_t i = 0; i < back.segments.size(); ++i)
        EXPECT_TRUE(std::get<CubicBez>(back.segments[i]) == std::get<CubicBez>(c2.segments[i]));
}

TEST(BezierSpline, LinesQuadsAndConicsBecomeCubics) {
    const PathDataResult r = parse_path_data("M 0 0 L 90 0 Q 120 0 120 30 A 30 30 0 0 1 90 60 Z");
    ASSERT_FALSE(r.error);
    const Subpath& sp = r.path.subpaths()[0];
    const BezierSpline s = BezierSpline::from_subpath(sp);
    // Line and quadratic exactly; the arc within 1e-5 of its radius.
    const Subpath cubic = s.to_subpath();
    for (int i = 0; i <= 100; ++i) {
        const double t = i / 100.0;
        EXPECT_LE(distance(segment_eval(cubic.segments[0], t), segment_eval(sp.segments[0], t)),
                  1e-12);
        EXPECT_LE(distance(segment_eval(cubic.segments[1], t), segment_eval(sp.segments[1], t)),
                  1e-12);
        for (std::size_t k : {2u, 3u}) {
            const Point p = segment_eval(cubic.segments[k], t);
            EXPECT_NEAR(distance(p, {90, 30}), 30, 30 * 1e-5) << k << " " << t;
        }
    }
    // Line into quadratic: collinear handles of lengths 30 (a third of the
    // line) and 20 (two thirds of the quadratic's 30): G1, inferred smooth.
    EXPECT_EQ(s.anchor(1).mode, JointMode::Smooth);
    EXPECT_GE(s.continuity(3), Continuity::G1); // the halves of the arc
}

} // namespace
} // namespace casteljau
