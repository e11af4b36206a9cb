#include "casteljau/geom/affine.h"
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
    EXPECT_EQ(t * Vec2(1, 2), Vec2(1, 2));
    EXPECT_EQ(t * Point(1, 2), Point(6, 9));
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

} // namespace
} // namespace casteljau
