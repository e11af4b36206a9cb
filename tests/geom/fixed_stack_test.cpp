// FixedStack: last in, first out, to its full capacity, with values whose
// default constructors would have zeroed them (it never runs them).
#include "casteljau/curve/bez.h"
#include "casteljau/geom/fixed_stack.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(FixedStack, PopsInReverseOrderToFullCapacity) {
    struct Piece {
        CubicBez c;
        int depth;
    };
    FixedStack<Piece, 41> stack;
    EXPECT_TRUE(stack.empty());
    for (int i = 0; i < 41; ++i)
        stack.push({CubicBez{{double(i), 0}, {1, 2}, {3, 4}, {5, double(-i)}}, i});
    for (int i = 40; i >= 0; --i) {
        ASSERT_FALSE(stack.empty());
        const Piece p = stack.pop();
        EXPECT_EQ(p.depth, i);
        EXPECT_EQ(p.c.start(), (Point{double(i), 0}));
        EXPECT_EQ(p.c.end(), (Point{5, double(-i)}));
    }
    EXPECT_TRUE(stack.empty());
    stack.push({CubicBez{}, 7}); // reusable after emptying
    EXPECT_EQ(stack.pop().depth, 7);
}

} // namespace
} // namespace casteljau
