#include "casteljau/geom/affine.h"
#include "casteljau/geom/line_clip.h"
#include "casteljau/geom/rect.h"
#include "corpus.h"

#include <gtest/gtest.h>
#include <numbers>
#include <type_traits>

namespace casteljau {
namespace {

template <class A, class B>
concept Addable = requires(A a, B b) {
    a + b;
};

TEST(Point, AffineAlgebraKeepsPointsAndVectorsApart) {
    static_assert(std::is_same_v<decltype(Point{} - Point{}), Vec2>);
    static_assert(std::is_same_v<decltype(Point{} + Vec2{}), Point>);
    static_assert(!Addable<Point, Point>, "point + point has no meaning");
    static_assert(lerp(Point{1, 2}, Point{3, 6}, 0.0) == Point{1, 2});
    static_assert(lerp(Point{1, 2}, Point{3, 6}, 1.0) == Point{3, 6});
    EXPECT_DOUBLE_EQ((Vec2{3, 4}).length(), 5.0);
    EXPECT_DOUBLE_EQ((Vec2{1, 0}).cross({0, 1}), 1.0);
}

TEST(Point, DistanceToSegmentCoversEndsAndInterior) {
    EXPECT_DOUBLE_EQ(distance_to_segment({5, 3}, {0, 0}, {10, 0}), 3.0);
    EXPECT_DOUBLE_EQ(distance_to_segment({-3, 4}, {0, 0}, {10, 0}), 5.0);
    EXPECT_DOUBLE_EQ(distance_to_segment({13, 4}, {0, 0}, {10, 0}), 5.0);
    EXPECT_DOUBLE_EQ(distance_to_segment({3, 4}, {0, 0}, {0, 0}), 5.0);
}

// The division-free form agrees with distance_to_segment, squared, on the
// ends, the interior and a segment that is a point.
TEST(Point, SquaredDistanceToSegmentIsTheDistanceSquared) {
    testing::Rng rng(2);
    for (int i = 0; i < 2000; ++i) {
        const Point a = rng.point(100), b = i % 10 ? rng.point(100) : a, p = rng.point(100);
        const SquaredDistance d = segment_distance_sq(p - a, b - a);
        const double want = distance_to_segment(p, a, b);
        ASSERT_GT(d.den, 0) << "case " << i;
        EXPECT_NEAR(d.num / d.den, want * want, 1e-9 * (1 + want * want)) << "case " << i;
    }
}

TEST(Affine, CompositionAppliesRightToLeft) {
    testing::Rng rng(1);
    for (int i = 0; i < 100; ++i) {
        const Affine a{rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2),
                       rng.uniform(-2, 2), rng.uniform(-9, 9), rng.uniform(-9, 9)};
        const Affine b = Affine::rotate(rng.uniform(0, 6)) * Affine::scale(2, 0.5);
        const Point p = rng.point(10);
        const Point x = (a * b) * p, y = a * (b * p);
        EXPECT_NEAR(x.x, y.x, 1e-12) << i;
        EXPECT_NEAR(x.y, y.y, 1e-12) << i;
        if (std::fabs(a.determinant()) > 1e-3) {
            const Point back = a.inverse() * (a * p);
            EXPECT_NEAR(back.x, p.x, 1e-9) << i;
            EXPECT_NEAR(back.y, p.y, 1e-9) << i;
        }
    }
}

TEST(Affine, VectorsIgnoreTranslationAndMaxScaleIsLargestStretch) {
    const Affine t = Affine::translate({5, 7});
    EXPECT_EQ(t * (Vec2{1, 2}), (Vec2{1, 2}));
    EXPECT_EQ(t * (Point{1, 2}), (Point{6, 9}));
    EXPECT_NEAR((Affine::rotate(0.3) * Affine::scale(3, 0.5)).max_scale(), 3.0, 1e-12);
    EXPECT_NEAR(Affine::skew_x(std::numbers::pi / 4).max_scale(),
                std::sqrt((3 + std::sqrt(5.0)) / 2), 1e-12);
}

TEST(Rect, StaysOrderedAndEmptyIsTheUnionIdentity) {
    const Rect r = Rect::from_points({5, -1}, {2, 3});
    EXPECT_EQ(r, (Rect{2, -1, 5, 3}));
    EXPECT_TRUE(Rect::empty().is_empty());
    EXPECT_EQ(Rect::empty().united(r), r);
    EXPECT_TRUE(r.contains({2, 3}));
    EXPECT_FALSE(r.contains({1.9, 0}));
}

// Clipping against brute force: the clipped part holds exactly the sample
// points of the segment that lie in the box, for random segments around it.
TEST(LineClip, KeepsExactlyThePartInTheBox) {
    const Rect box{-10, -5, 30, 25};
    testing::Rng rng(17);
    for (int i = 0; i < 2000; ++i) {
        const Point a{rng.uniform(-60, 80), rng.uniform(-60, 80)};
        const Point b = i % 7 == 0 ? Point{a.x, rng.uniform(-60, 80)}
                                   : Point{rng.uniform(-60, 80), rng.uniform(-60, 80)};
        const auto part = clip_line(a, b, box);
        for (int k = 0; k <= 200; ++k) {
            const Point p = lerp(a, b, k / 200.0);
            const bool in = box.inflated(-1e-9).contains(p);
            const bool out = !box.inflated(1e-9).contains(p);
            if (in) {
                ASSERT_TRUE(part) << "a " << a.x << "," << a.y << " b " << b.x << "," << b.y;
                EXPECT_LT(distance_to_segment(p, part->front(), part->back()), 1e-9) << i;
            }
            if (out && part) {
                EXPECT_GT(distance_to_segment(p, part->front(), part->back()), 0) << i;
            }
        }
        if (box.contains(a) && part) {
            EXPECT_EQ(part->front(), a) << "an end inside is kept exactly";
        }
    }
}

// End points near 1e308, where b - a overflows: the crossing of a nearly
// horizontal line is found at the right height.
TEST(LineClip, EndPointsNear1e308) {
    const auto part = clip_line({-1e308, 100}, {1e308, 200}, Rect{0, 0, 300, 300});
    ASSERT_TRUE(part);
    EXPECT_EQ(part->front().x, 0);
    EXPECT_EQ(part->back().x, 300);
    EXPECT_NEAR(part->front().y, 150, 1e-9);
    EXPECT_NEAR(part->back().y, 150, 1e-9);
    EXPECT_FALSE(clip_line({-1e308, -1e308}, {1e308, -1e308}, Rect{0, 0, 300, 300}));
}

} // namespace
} // namespace casteljau
