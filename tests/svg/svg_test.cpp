#include "casteljau/svg/reader.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/transform_list.h"
#include "check.h"

#include <gtest/gtest.h>
#include <numbers>

namespace casteljau {
namespace {

SvgResult parse(const std::string& body, const std::string& root = R"(width="100" height="100")") {
    return parse_svg(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" " + root + ">\n" + body + "\n</svg>", "t.svg");
}

const Shape& first_shape(const Scene& s) { return std::get<Shape>(s.root.children.at(0).item); }

TEST(TransformList, EveryFunctionAndErrors) {
    const auto near = [](const Affine& a, const Affine& b) {
        return std::fabs(a.a - b.a) + std::fabs(a.b - b.b) + std::fabs(a.c - b.c) +
                   std::fabs(a.d - b.d) + std::fabs(a.e - b.e) + std::fabs(a.f - b.f) <
               1e-12;
    };
    EXPECT_TRUE(near(parse_transform_list("translate(10) scale(2,3)").transform,
                     Affine::translate({10, 0}) * Affine::scale(2, 3)));
    EXPECT_TRUE(near(parse_transform_list("rotate(90 10 10)").transform,
                     Affine::translate({10, 10}) * Affine::rotate(std::numbers::pi / 2) *
                         Affine::translate({-10, -10})));
    EXPECT_TRUE(
        near(parse_transform_list("matrix(1,2,3,4,5,6)").transform, Affine{1, 2, 3, 4, 5, 6}));
    EXPECT_TRUE(near(parse_transform_list("skewX(45)skewY(0)").transform,
                     Affine::skew_x(std::numbers::pi / 4)));
    for (const char* bad : {"translate(1,2,3)", "rotate(1,2)", "scale()", "spin(3)", "translate(1",
                            "matrix(1 2 3 4 5 nan)", "scale(1e999)"})
        EXPECT_FALSE(parse_transform_list(bad).error.empty()) << bad;
}

TEST(TransformList, CssSyntaxAndTheAttributesUnits) {
    // Where (1, 1) goes, with percentages of a 200 x 100 box.
    const auto expect_at = [](std::string_view text, TransformSyntax syntax, Point want) {
        const TransformParse p = parse_transform(text, syntax, LengthContext{});
        EXPECT_TRUE(p.error.empty()) << text << ": " << p.error;
        const Point got = p.value.at(200, 100) * Point{1, 1};
        EXPECT_NEAR(got.x, want.x, 1e-12) << text;
        EXPECT_NEAR(got.y, want.y, 1e-12) << text;
    };
    const auto css = TransformSyntax::Css, attr = TransformSyntax::Attribute;
    expect_at("translate(10px, 1in)", css, {11, 97});
    expect_at("TRANSLATEX(50%) scaleY(200%)", css, {101, 2});
    expect_at("translate(0) scale(2,3)", css, {2, 3});
    expect_at("none", css, {1, 1});
    expect_at("skew(0, 45deg)", css, {1, 2});
    expect_at("translate(5px,5px)", attr, {6, 6});
    expect_at("translate(1 2)scale(2)", attr, {3, 4});
    expect_at("rotate(0.5turn)", attr, {-1, -1});
    expect_at("", attr, {1, 1});
    for (const char* bad :
         {"translate(10, 20)", "translate(10px 20px)", "rotate(90)", "translate(1px,,2px)",
          "translate(1px),scale(2)", "rotate(90deg 1 2)", "", "matrix(1,0,0,1,0,0px)"})
        EXPECT_FALSE(parse_transform(bad, css, LengthContext{}).error.empty()) << bad;
    for (const char* bad : {"translate(5pz)", "rotate(1 2 3 4)", "scale(1deg)", "translate(,1)",
                            "translate(1,)", "translate(1,,2)"})
        EXPECT_FALSE(parse_transform(bad, attr, LengthContext{}).error.empty()) << bad;
    EXPECT_FALSE(parse_transform_list("translate(50%)").error.empty()) << "no box there";
}

TEST(Style, InheritanceAndStylePrecedence) {
    const SvgResult r = parse(R"(<g fill="red" fill-rule="evenodd" opacity="1">
      <rect width="10" height="10" style="fill: blue; fill-opacity: 50%"/>
      <rect width="10" height="10"/>
      <rect width="10" height="10" fill="lime" style="fill:inherit"/>
      <rect width="10" height="10" color="#00f" fill="currentColor"/>
      </g>)");
    ASSERT_TRUE(r.scene) << r.error;
    const auto& c = r.scene->root.children;
    ASSERT_EQ(c.size(), 4u); // a group of opacity 1 is flattened away
    const Fill& a = *std::get<Shape>(c[0].item).fill;
    EXPECT_EQ(a.color, (Rgba{0, 0, 1, 1}));
    EXPECT_EQ(a.opacity, 0.5f);
    EXPECT_EQ(a.rule, FillRule::EvenOdd);
    EXPECT_EQ(std::get<Shape>(c[1].item).fill->color, (Rgba{1, 0, 0, 1}));
    EXPECT_EQ(std::get<Shape>(c[2].item).fill->color, (Rgba{1, 0, 0, 1}));
    EXPECT_EQ(std::get<Shape>(c[3].item).fill->color, (Rgba{0, 0, 1, 1}));
}

TEST(Reader, ViewBoxAndPreserveAspectRatio) {
    // 0..10 mapped into 200 x 100, meet, centred: scale 10, x offset 50.
    const SvgResult r = parse(R"(<rect width="10" height="10"/>)",
                              R"(width="200" height="100" viewBox="0 0 10 10")");
    ASSERT_TRUE(r.scene) << r.error;
    const Affine& m = first_shape(*r.scene).transform;
    EXPECT_EQ((m * Point{0, 0}), (Point{50, 0}));
    EXPECT_EQ((m * Point{10, 10}), (Point{150, 100}));
    const SvgResult s = parse(
        R"(<rect width="10" height="10"/>)",
        R"(width="200" height="100" viewBox="0 0 10 10" preserveAspectRatio="xMinYMax slice")");
    EXPECT_EQ((first_shape(*s.scene).transform * Point{10, 10}), (Point{200, 200 - 100}));
    const SvgResult n =
        parse(R"(<rect width="10" height="10"/>)",
              R"(width="200" height="100" viewBox="0 0 10 10" preserveAspectRatio="none")");
    EXPECT_EQ((first_shape(*n.scene).transform * Point{10, 10}), (Point{200, 100}));
    // No width/height: the viewBox size.
    const SvgResult v = parse("", R"(viewBox="0 0 30 20")");
    EXPECT_EQ(v.scene->width, 30);
}

TEST(Reader, OneAbsoluteSideTakesTheOtherFromTheViewBoxRatio) {
    // graphviz writes width="250pt" and no height: as an <img>, and as
    // librsvg draws it, the height keeps the viewBox's 363:342.
    const std::pair<const char*, std::pair<double, double>> cases[] = {
        {R"(width="250pt")", {250 * 4.0 / 3, 250 * 4.0 / 3 * 342 / 363}},
        {R"(height="150pt")", {200.0 * 363 / 342, 200}},
        {R"(width="200" height="auto")", {200, 200.0 * 342 / 363}},
        {R"(width="200" height="50%")", {200, 200.0 * 342 / 363}},
        {R"(width="200" height="-x")", {200, 200.0 * 342 / 363}}, // invalid: auto
        {R"(width="200" height="100")", {200, 100}},              // both given: as given
        {R"(width="50%" height="50%")", {181.5, 171}},            // neither: of the viewBox
    };
    for (const auto& [attrs, size] : cases) {
        const SvgResult r = parse("", std::string(attrs) + R"( viewBox="0 0 363 342")");
        ASSERT_TRUE(r.scene) << attrs << ": " << r.error;
        EXPECT_NEAR(r.scene->width, size.first, 1e-9) << attrs;
        EXPECT_NEAR(r.scene->height, size.second, 1e-9) << attrs;
    }
    // Without a viewBox there is no ratio: the absent side is 100.
    const SvgResult none = parse("", R"(width="250")");
    EXPECT_EQ(none.scene->height, 100);
}

TEST(Reader, RootTransformAppliesInViewportPixelsAroundItsOrigin) {
    // The root's transform after the viewBox mapping (200 px for 100 user
    // units), around 50% 50% of the viewport unless transform-origin says.
    const std::string root =
        R"svg(width="200" height="200" viewBox="0 0 100 100" transform="scale(0.5)")svg";
    const std::pair<const char*, std::pair<Point, Point>> cases[] = {
        {"", {{50, 50}, {150, 150}}},
        {R"( transform-origin="0 0")", {{0, 0}, {100, 100}}},
        {R"( transform-origin="25% 75%")", {{25, 75}, {125, 175}}},
        {R"( style="transform-origin: right bottom")", {{100, 100}, {200, 200}}},
    };
    for (const auto& [origin, corners] : cases) {
        const SvgResult r = parse(R"(<rect width="100" height="100"/>)", root + origin);
        ASSERT_TRUE(r.scene) << origin << ": " << r.error;
        const Affine& m = first_shape(*r.scene).transform;
        EXPECT_EQ((m * Point{0, 0}), corners.first) << origin;
        EXPECT_EQ((m * Point{100, 100}), corners.second) << origin;
        EXPECT_TRUE(r.warnings.empty()) << origin;
    }
    const SvgResult moved = parse(R"(<rect width="10" height="10"/>)",
                                  R"svg(width="100" height="100" transform="translate(30 5)")svg");
    EXPECT_EQ((first_shape(*moved.scene).transform * Point{0, 0}), (Point{30, 5}));
    const SvgResult bad = parse(R"(<rect width="10" height="10"/>)",
                                R"svg(width="100" height="100" transform="translate(30,")svg");
    EXPECT_EQ((first_shape(*bad.scene).transform * Point{0, 0}), (Point{0, 0}));
    ASSERT_EQ(bad.warnings.size(), 1u);
    EXPECT_NE(bad.warnings[0].text().find("transform"), std::string::npos);
}

TEST(Reader, RectCornersFollowTheSpecRules) {
    // Only rx given: ry = rx; rx larger than half the width: clamped.
    const SvgResult r = parse(R"(<rect x="0" y="0" width="20" height="100" rx="15"/>)");
    const Rect b = first_shape(*r.scene).path.bounds();
    EXPECT_NEAR(b.x1, 20, 1e-12);
    EXPECT_NEAR(b.y1, 100, 1e-12);
    // 4 lines + 4 corner arcs (one conic each)
    EXPECT_EQ(first_shape(*r.scene).path.segment_count(), 8u);
}

// resvg's structure/svg/negative-size: a negative width or height is an
// invalid value, ignored as an unparsable one is (auto: the viewBox's size,
// else 100), with a warning; it was an error (exit 2). Zero stays one.
// resvg's a-display-007: display: none on the root draws nothing, at the
// document's size; before, it was drawn.
TEST(Reader, DisplayNoneOnTheRootDrawsNothing) {
    for (const char* root : {R"(width="40" height="30" display="none")",
                             R"(width="40" height="30" style="display: none")"}) {
        const SvgResult r = parse(R"(<rect width="5" height="5"/>)", root);
        ASSERT_TRUE(r.scene) << r.error;
        EXPECT_EQ(r.scene->width, 40);
        EXPECT_TRUE(r.scene->root.children.empty()) << root;
    }
}

TEST(Reader, ANegativeDocumentSizeIsIgnored) {
    const SvgResult r = parse(R"(<rect width="5" height="5"/>)", R"(width="-5" height="10")");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(r.scene->width, 100);
    EXPECT_EQ(r.scene->height, 10);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].text(), "t.svg:1: <svg>: attribute width: '-5' is negative; ignored");
    const SvgResult boxed = parse("", R"(width="30" height="-1%" viewBox="0 0 60 40")");
    ASSERT_TRUE(boxed.scene) << boxed.error;
    EXPECT_EQ(boxed.scene->height, 20); // the viewBox's aspect ratio from the width
}

TEST(Reader, OnlyFilesThatCannotBeDrawnAreErrors) {
    const std::pair<const char*, const char*> cases[] = {
        {R"(width="0" height="10")", "t.svg:1: <svg>: the document size 0 must be positive"},
        {R"(width="100000" height="10")", "exceeds the limit"},
        {R"(viewBox="0 0 0 5")", "must be positive"}, // its size is the zero-width viewBox's
    };
    for (const auto& [root, expect] : cases) {
        const SvgResult r = parse("", root);
        EXPECT_FALSE(r.scene) << root;
        EXPECT_NE(r.error.find(expect), std::string::npos) << root << " got: " << r.error;
    }
    const SvgResult xml = parse("<rect");
    EXPECT_NE(xml.error.find("malformed XML"), std::string::npos) << xml.error;
    const SvgResult notsvg = parse_svg("<html/>", "x.svg");
    EXPECT_NE(notsvg.error.find("x.svg:1: the root element is <html>"), std::string::npos)
        << notsvg.error;
}

TEST(Reader, BadPathDataIsDrawnUpToTheErrorOrWithStrictAnError) {
    const char* bad[] = {R"(<path d="M0 0 L10 0 L10 10 L x 5"/>)",
                         R"(<polyline points="0 0 10 0 10 10 x 5"/>)"};
    const char* where[] = {"t.svg:2: <path>: attribute d: path data: at offset 20",
                           "t.svg:2: <polyline>: attribute points:"};
    SvgOptions strict;
    strict.strict = true;
    for (int i = 0; i < 2; ++i) {
        const std::string text =
            std::string("<svg width='100' height='100'>\n") + bad[i] + "</svg>";
        const SvgResult r = parse_svg(text, "t.svg");
        ASSERT_TRUE(r.scene) << r.error;
        EXPECT_EQ(first_shape(*r.scene).path.segment_count(), 2u) << bad[i];
        ASSERT_EQ(r.warnings.size(), 1u);
        EXPECT_EQ(r.warnings[0].line, 2);
        EXPECT_EQ(r.warnings[0].element, i == 0 ? "path" : "polyline");
        EXPECT_NE(r.warnings[0].text().find(where[i]), std::string::npos) << r.warnings[0].text();
        const SvgResult s = parse_svg(text, "t.svg", strict);
        EXPECT_FALSE(s.scene);
        EXPECT_NE(s.error.find(where[i]), std::string::npos) << s.error;
    }
}

TEST(Reader, UnsupportedElementsAreSkippedWithOneWarningEach) {
    // foreignObject is SVG, not drawn: a warning; a filter is drawn only
    // where an element refers to it; blink is not SVG: not rendered, as
    // unknown elements are not (no warning). An image without an href draws
    // nothing, as the spec says, with no warning.
    const SvgResult r = parse("<foreignObject/><filter/><image/><defs><linearGradient/></defs>"
                              "<title>t</title><blink/><rect width='1' height='1'/>");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(r.scene->root.children.size(), 1u);
    EXPECT_EQ(r.warnings.size(), 1u);
}

TEST(Reader, LimitsOnNestingAndElementCount) {
    std::string deep;
    for (int i = 0; i < 300; ++i) deep += "<g>";
    for (int i = 0; i < 300; ++i) deep += "</g>";
    EXPECT_NE(parse(deep).error.find("nested deeper than 256"), std::string::npos);
    SvgOptions few;
    few.max_elements = 10;
    std::string many;
    for (int i = 0; i < 20; ++i) many += "<rect width='1' height='1'/>";
    const SvgResult r = parse_svg("<svg width='10' height='10'>" + many + "</svg>", "m.svg", few);
    EXPECT_NE(r.error.find("more than 10 elements"), std::string::npos) << r.error;
}

TEST(Reader, AnAttributeOverTheLengthLimitIsAnError) {
    SvgOptions small;
    small.max_attribute_bytes = 100;
    const std::string d(101, 'M');
    const SvgResult r =
        parse_svg("<svg width='1' height='1'>\n<path d='" + d + "'/></svg>", "a.svg", small);
    EXPECT_NE(r.error.find("a.svg:2: <path>: attribute d is 101 bytes, over the limit of 100"),
              std::string::npos)
        << r.error;
}

} // namespace
} // namespace casteljau
