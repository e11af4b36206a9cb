// CSS basic shapes (svg/basic_shape.h): what parses, and each shape's
// outline against its reference box.
#include "casteljau/svg/basic_shape.h"
#include "casteljau/svg/style.h"

#include <cmath>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

std::optional<BasicShape> parse(std::string_view v) {
    return parse_basic_shape(v, LengthContext{});
}

void expect_bounds(std::string_view value, const Rect& box, const Rect& want) {
    const std::optional<BasicShape> s = parse(value);
    ASSERT_TRUE(s) << value;
    const Rect b = shape_path(*s, box).bounds();
    EXPECT_NEAR(b.x0, want.x0, 1e-9) << value;
    EXPECT_NEAR(b.y0, want.y0, 1e-9) << value;
    EXPECT_NEAR(b.x1, want.x1, 1e-9) << value;
    EXPECT_NEAR(b.y1, want.y1, 1e-9) << value;
}

TEST(BasicShape, ValuesAndTheirBoxes) {
    for (const char* ok : {"circle()", "CIRCLE(closest-side)", "fill-box", "view-box circle()",
                           "circle() stroke-box", "ellipse(1px 2% at left top)",
                           "inset(1px 2px 3px 4px round 1px 2px / 3px)", "polygon(1px 2px)",
                           "polygon(evenodd, 0 0, 1px 0, 0 1em)", "path(evenodd, 'M0 0 H5 V5')",
                           "path(\"M 0 0 L 1 1\") margin-box"})
        EXPECT_TRUE(parse(ok)) << ok;
    for (const char* bad :
         {"circle(50)", "circle(-5px)", "ellipse(10px)", "inset()", "inset(1px 2px 3px 4px 5px)",
          "polygon()", "polygon(1px)", "polygon(1px 2px 3px)", "path(M 0 0)", "path('M 0 0 L')",
          "fill-box fill-box", "circle() ellipse()", "bogus", "circle(at)",
          "circle(1px at 1px 2px 3px)", "none", "url(#c)", "inset(1px round)", ""})
        EXPECT_FALSE(parse(bad)) << bad;
    EXPECT_EQ(parse("circle()")->box, ShapeBox::Stroke) << "border-box, SVG's stroke box";
    EXPECT_EQ(parse("content-box circle()")->box, ShapeBox::Fill);
    EXPECT_EQ(parse("path(evenodd, 'M0 0 H5 V5')")->fill_rule, FillRule::EvenOdd);
}

TEST(BasicShape, OutlinesInTheReferenceBox) {
    const Rect box{10, 20, 70, 60}; // 60 x 40, centre (40, 40)
    expect_bounds("fill-box", box, box);
    expect_bounds("circle()", box, {20, 20, 60, 60}); // closest side: 20
    // At (20, 50), 50 from the farthest side.
    expect_bounds("circle(farthest-side at 10px 30px)", box, {-30, 0, 70, 100});
    // 10% of the normalised diagonal sqrt((60^2 + 40^2) / 2) = sqrt(2600).
    const double r = 0.1 * std::sqrt(2600.0);
    expect_bounds("circle(10% at right bottom)", box, {70 - r, 60 - r, 70 + r, 60 + r});
    expect_bounds("ellipse(farthest-side closest-side at 25% 50%)", box, {-20, 20, 70, 60});
    expect_bounds("ellipse(10px 50%)", box, {30, 20, 50, 60});
    expect_bounds("inset(5px 10% round 50%)", box, {16, 25, 64, 55});
    EXPECT_TRUE(shape_path(*parse("inset(60% 0 50% 0)"), box).empty()) << "insets overlap";
    EXPECT_TRUE(shape_path(*parse("circle(0)"), box).empty());
    expect_bounds("polygon(0 0, 100% 0, 50% 100%)", box, {10, 20, 70, 60});
    expect_bounds("path('M 5 5 h 10 v 10')", box, {15, 25, 25, 35});
}

TEST(BasicShape, RoundedInsetCornersShrinkTogetherWhenTheyOverlap) {
    // round 40px on a 60 x 40 rectangle: the radii scale by 40 / 80 = 0.5,
    // so each corner is a 20 px quarter circle and the sides' middles stay.
    const std::optional<BasicShape> s = parse("inset(0 round 40px)");
    ASSERT_TRUE(s);
    const Path p = shape_path(*s, {0, 0, 60, 40});
    const Rect b = p.bounds();
    EXPECT_NEAR(b.x1, 60, 1e-9);
    EXPECT_NEAR(b.y1, 40, 1e-9);
    // The corner arc's middle: (20, 20) minus 20 / sqrt 2 on each axis.
    bool found = false;
    const double d = 20 - 20 / std::sqrt(2.0);
    for (const Subpath& sp : p.subpaths())
        for (const Segment& seg : sp.segments)
            for (double t = 0; t <= 1; t += 1.0 / 64) {
                const Point q = segment_eval(seg, t);
                found = found || (std::fabs(q.x - d) < 0.01 && std::fabs(q.y - d) < 0.01);
            }
    EXPECT_TRUE(found) << "the top-left corner is the 20 px arc";
}

} // namespace
} // namespace casteljau
