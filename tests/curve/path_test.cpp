#include "casteljau/curve/path.h"
#include "corpus.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(Path, BuilderFollowsSvgSubpathRules) {
    Path p;
    p.line_to({10, 0}); // no move_to: starts at the origin
    p.quad_to({10, 10}, {0, 10});
    p.close();         // adds the closing line back to (0, 0)
    p.line_to({5, 5}); // after close: a new subpath from the old start
    ASSERT_EQ(p.subpaths().size(), 2u);
    const Subpath& a = p.subpaths()[0];
    EXPECT_TRUE(a.closed);
    EXPECT_EQ(a.segments.size(), 3u);
    EXPECT_EQ(segment_end(a.segments.back()), (Point{0, 0}));
    EXPECT_EQ(p.subpaths()[1].start, (Point{0, 0}));
    p.move_to({1, 1});
    p.move_to({2, 2}); // a lone move_to leaves no empty subpath behind
    p.cubic_to({3, 3}, {4, 3}, {5, 2});
    EXPECT_EQ(p.subpaths().size(), 3u);
    EXPECT_EQ(p.subpaths()[2].start, (Point{2, 2}));
}

TEST(Path, GlobalParameterisationWalksTheSegments) {
    Path p;
    p.move_to({0, 0});
    p.line_to({10, 0});
    p.cubic_to({10, 5}, {5, 10}, {0, 10});
    EXPECT_EQ(p.eval(0, 0.5), (Point{5, 0}));
    EXPECT_EQ(p.eval(0, 1.0), (Point{10, 0}));
    const CubicBez c{{10, 0}, {10, 5}, {5, 10}, {0, 10}};
    EXPECT_EQ(p.eval(0, 1.25), c.eval(0.25));
    EXPECT_EQ(p.eval(0, 2.0), (Point{0, 10}));
    EXPECT_EQ(p.eval(0, 7.0), (Point{0, 10})); // clamped
}

TEST(Path, TransformAndBounds) {
    Path p;
    p.move_to({0, 0});
    p.cubic_to({0, 100}, {100, 100}, {100, 0});
    const Rect b = p.bounds();
    EXPECT_NEAR(b.y1, 75, 1e-12);
    p.transform(Affine::translate({5, 5}) * Affine::scale(2));
    const Rect t = p.bounds();
    EXPECT_NEAR(t.y1, 155, 1e-12);
    EXPECT_NEAR(t.x1, 205, 1e-12);
}

// The box of every subpath's start and control points, from scratch.
Rect control_box_of(const Path& p) {
    Rect r = Rect::empty();
    for (const Subpath& s : p.subpaths()) {
        r = r.united(s.start);
        for (const Segment& seg : s.segments) r = r.united(segment_control_bounds(seg));
    }
    return r;
}

// control_bounds() is kept as the path is built; it equals the box computed
// from scratch after every call, lone move_tos (dropped by the next one),
// empty closes and transforms included.
TEST(Path, KeptControlBoundsEqualTheBoxFromScratch) {
    testing::Rng rng(11);
    for (int i = 0; i < 200; ++i) {
        Path p;
        for (int step = 0; step < 12; ++step) {
            const Point a = rng.point(100) - Vec2{50, 50}, b = rng.point(100), c = rng.point(300);
            switch (rng.integer(0, 6)) {
            case 0:
                p.move_to(a);
                break;
            case 1:
                p.line_to(a);
                break;
            case 2:
                p.cubic_to(a, b, c);
                break;
            case 3:
                p.conic_to(b, c, 2.0);
                break;
            case 4:
                p.close();
                break;
            case 5:
                p.append(Line{{c, a}});
                break;
            default:
                p.transform(Affine::translate({-20, 7}) * Affine::scale(1.5));
                break;
            }
            const Rect want = control_box_of(p), got = p.control_bounds();
            ASSERT_EQ(got.is_empty(), want.is_empty()) << "path " << i << " step " << step;
            if (!want.is_empty()) {
                ASSERT_EQ(got.min(), want.min()) << "path " << i << " step " << step;
                ASSERT_EQ(got.max(), want.max()) << "path " << i << " step " << step;
            }
        }
    }
}

// add_subpath (copying or taking the segments' storage) builds the path that
// its documented builder calls build: move_to, append each segment, close()
// when closed; in every state the next call sees.
TEST(Path, AddedSubpathsBuildThePathOfTheBuilderCalls) {
    testing::Rng rng(29);
    const auto same = [](const Path& got, const Path& want) {
        if (got.subpaths().size() != want.subpaths().size()) return false;
        for (std::size_t k = 0; k < want.subpaths().size(); ++k) {
            const Subpath &a = want.subpaths()[k], &b = got.subpaths()[k];
            if (b.start != a.start || b.closed != a.closed ||
                b.segments.size() != a.segments.size())
                return false;
            for (std::size_t j = 0; j < a.segments.size(); ++j)
                if (segment_end(b.segments[j]) != segment_end(a.segments[j])) return false;
        }
        const Rect wb = want.control_bounds(), gb = got.control_bounds();
        return got.current_point() == want.current_point() && gb.is_empty() == wb.is_empty() &&
               (wb.is_empty() || (gb.min() == wb.min() && gb.max() == wb.max()));
    };
    for (int i = 0; i < 300; ++i) {
        Path built, copied, moved;
        for (int step = 0; step < 6; ++step) {
            Subpath sp{rng.point(100), {}, rng.integer(0, 1) == 1};
            const int n = rng.integer(0, 3); // empty subpaths too
            Point at = sp.start;
            for (int k = 0; k < n; ++k) {
                const Point to = k == n - 1 && rng.integer(0, 2) == 0 ? sp.start : rng.point(100);
                if (rng.integer(0, 1) == 0)
                    sp.segments.push_back(Line{{at, to}});
                else
                    sp.segments.push_back(CubicBez{{at, rng.point(200), rng.point(200), to}});
                at = to;
            }
            built.move_to(sp.start);
            for (const Segment& seg : sp.segments) built.append(seg);
            if (sp.closed) built.close();
            copied.add_subpath(sp);
            moved.add_subpath(std::move(sp));
            if (rng.integer(0, 2) == 0) { // the state the next builder call starts from
                const Point p = rng.point(100);
                for (Path* path : {&built, &copied, &moved}) path->line_to(p);
            }
            ASSERT_TRUE(same(copied, built)) << "path " << i << " step " << step;
            ASSERT_TRUE(same(moved, built)) << "path " << i << " step " << step;
        }
    }
}

TEST(Path, ContinuityOfConstructedJoints) {
    // Two cubics meeting at (10, 0); the second one's handles set each level.
    const CubicBez a{{0, 0}, {3, 4}, {7, -2}, {10, 0}};
    const Vec2 d = a.p[3] - a.p[2];                        // a'(1) / 3
    const Vec2 dd = (a.p[3] - a.p[2]) - (a.p[2] - a.p[1]); // a''(1) / 6
    const Point j = a.p[3];
    // C2: b1 = j + d, b2 = j + 2d + dd (matching first and second derivatives).
    const CubicBez c2{{j, j + d, j + d * 2 + dd, {20, 5}}};
    const CubicBez c1{{j, j + d, {15, 9}, {20, 5}}};
    const CubicBez g1{{j, j + d * 2.5, {15, 9}, {20, 5}}};
    const CubicBez c0{{j, j + Vec2{1, 1}, {15, 9}, {20, 5}}};
    const CubicBez gap{{10, 0.5}, {12, 1}, {15, 9}, {20, 5}};
    EXPECT_EQ(joint_continuity(a, c2), Continuity::C2);
    EXPECT_EQ(joint_continuity(a, c1), Continuity::C1);
    EXPECT_EQ(joint_continuity(a, g1), Continuity::G1);
    EXPECT_EQ(joint_continuity(a, c0), Continuity::C0);
    EXPECT_EQ(joint_continuity(a, gap), Continuity::None);
    // Opposite tangent (a cusp at the joint) is not G1.
    const CubicBez cusp{{j, j - d, {15, 9}, {20, 5}}};
    EXPECT_EQ(joint_continuity(a, cusp), Continuity::C0);
    // A degenerate handle falls back to the limit direction: still G1.
    const CubicBez degenerate{{j, j, j + d * 3, {20, 5}}};
    EXPECT_EQ(joint_continuity(a, degenerate), Continuity::G1);
}

TEST(Path, ContinuityOfAClosedCircleOfConics) {
    Path p;
    p.move_to({10, 0});
    p.arc_to({10, 10}, 0, false, true, {-10, 0});
    p.arc_to({10, 10}, 0, false, true, {10, 0});
    p.close();
    const auto joints = p.continuity(0, 1e-9);
    ASSERT_EQ(joints.size(), 4u); // four quarter conics, closing joint included
    for (Continuity c : joints) EXPECT_GE(c, Continuity::G1) << to_string(c);
}

} // namespace
} // namespace casteljau
