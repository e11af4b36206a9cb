// SVG and CSS error handling (SVG 2, 9.5.4 and "presentation attributes";
// CSS Syntax 3): each invalid value is ignored with one located warning and
// the spec's recovery, the element drawn as browsers draw it; with strict,
// the same problem is the error that stops the read.
#include "casteljau/svg/reader.h"

#include <functional>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

const std::vector<Node>& children(const Scene& s) { return s.root.children; }
const Shape& shape_at(const Scene& s, std::size_t i) {
    return std::get<Shape>(children(s).at(i).item);
}

struct Case {
    const char* body;
    const char* warning; // in "t.svg:LINE: <element>: what" form, a substring
    std::function<void(const Scene&)> check;
};

// Each case, in a 100 x 100 document, body on line 2: exactly one warning,
// the recovered scene as `check` says, and the warning's text as the error
// when strict.
void run(const Case& c, const char* root = R"svg(width="100" height="100")svg") {
    const std::string text = std::string("<svg xmlns=\"http://www.w3.org/2000/svg\" ") + root +
                             ">\n" + c.body + "\n</svg>";
    const SvgResult r = parse_svg(text, "t.svg");
    ASSERT_TRUE(r.scene) << c.body << ": " << r.error;
    ASSERT_EQ(r.warnings.size(), 1u) << c.body;
    EXPECT_NE(r.warnings[0].text().find(c.warning), std::string::npos)
        << c.body << "\n got: " << r.warnings[0].text();
    c.check(*r.scene);
    SvgOptions strict;
    strict.strict = true;
    const SvgResult s = parse_svg(text, "t.svg", strict);
    EXPECT_FALSE(s.scene) << c.body;
    EXPECT_EQ(s.error, r.warnings[0].text()) << c.body;
}

TEST(ErrorHandling, InvalidPropertyValuesAreIgnored) {
    const Case cases[] = {
        {R"svg(<g fill="red"><rect width="5" height="5" fill="blurple"/></g>)svg",
         "t.svg:2: <rect>: property fill: 'blurple' is not a paint",
         [](const Scene& s) {
             EXPECT_EQ(shape_at(s, 0).fill->color, (Rgba{1, 0, 0, 1}));
         }},
        {R"svg(<rect width="5" height="5" opacity="half"/>)svg", "property opacity: 'half'",
         [](const Scene& s) { EXPECT_EQ(shape_at(s, 0).opacity, 1.0f); }},
        // In a style attribute: that declaration is dropped, the next applies.
        {R"svg(<rect width="5" height="5" fill="lime" style="fill: blurple; stroke: blue"/>)svg",
         "t.svg:2: <rect>: style: property fill: 'blurple'",
         [](const Scene& s) {
             EXPECT_EQ(shape_at(s, 0).fill->color, (Rgba{0, 1, 0, 1}));
             EXPECT_EQ(shape_at(s, 0).stroke->color, (Rgba{0, 0, 1, 1}));
         }},
        {R"svg(<rect width="5" height="5" style="fill red; stroke: blue"/>)svg",
         "style: 'fill red' is not a declaration",
         [](const Scene& s) {
             EXPECT_EQ(shape_at(s, 0).stroke->color, (Rgba{0, 0, 1, 1}));
         }},
        {R"svg(<g stroke-width="3"><path d="M0 0 H5" stroke="red" stroke-width="-1"/></g>)svg",
         "property stroke-width: '-1'",
         [](const Scene& s) { EXPECT_EQ(shape_at(s, 0).stroke->geometry.width, 3); }},
        {R"svg(<path d="M0 0 H5" stroke="red" stroke-dasharray="5 -1"/>)svg",
         "property stroke-dasharray: '5 -1'",
         [](const Scene& s) { EXPECT_TRUE(shape_at(s, 0).stroke->geometry.dashes.empty()); }},
        {R"svg(<path d="M0 0 H5" stroke="red" stroke-linecap="rounded"/>)svg",
         "property stroke-linecap: 'rounded'",
         [](const Scene& s) { EXPECT_EQ(shape_at(s, 0).stroke->geometry.cap, LineCap::Butt); }},
        {R"svg(<rect width="5" height="5" visibility="invisible"/>)svg", "property visibility",
         [](const Scene& s) { EXPECT_EQ(children(s).size(), 1u); }},
        {R"svg(<rect width="5" height="5" stroke="red" stroke-width="2" font-size="-3" />)svg",
         "property font-size: '-3'", [](const Scene&) {}},
    };
    for (const Case& c : cases) run(c);
}

TEST(ErrorHandling, InvalidGeometryAndTransformsFollowTheSpec) {
    const auto none = [](const Scene& s) { EXPECT_TRUE(children(s).empty()); };
    const Case cases[] = {
        // An invalid length is ignored: width auto is 0, and nothing is drawn.
        {R"svg(<rect width="1x0" height="10"/>)svg", "t.svg:2: <rect>: attribute width: '1x0'",
         none},
        {R"svg(<rect x="abc" width="5" height="5"/>)svg", "attribute x: 'abc'",
         [](const Scene& s) { EXPECT_EQ(shape_at(s, 0).path.bounds().x0, 0); }},
        {R"svg(<circle r="nan"/>)svg", "t.svg:2: <circle>: attribute r: 'nan'", none},
        {R"svg(<ellipse rx="inf" ry="2"/>)svg", "t.svg:2: <ellipse>: attribute rx: 'inf'",
         // rx invalid, so auto: ry's value (SVG 2)
         [](const Scene& s) { EXPECT_NEAR(shape_at(s, 0).path.bounds().width(), 4, 1e-12); }},
        // Negative sizes are errors that disable the element.
        {R"svg(<rect width="-5" height="5"/>)svg", "attribute width: a negative value is an error",
         none},
        {R"svg(<circle r="-3"/>)svg", "attribute r: a negative value is an error", none},
        // A negative rx or ry is invalid, so auto: the other radius, or none
        // (SVG 2, 10.5; WPT's ellipse-006 and rect-007; before, nothing was
        // drawn, as SVG 1.1 had it).
        {R"svg(<ellipse rx="3" ry="-3"/>)svg", "attribute ry: a negative value is invalid; auto",
         [](const Scene& s) { EXPECT_NEAR(shape_at(s, 0).path.bounds().height(), 6, 1e-12); }},
        {R"svg(<ellipse rx="-3"/>)svg", "attribute rx: a negative value", none},
        {R"svg(<rect width="5" height="5" rx="-1"/>)svg", "attribute rx: a negative value",
         [](const Scene& s) { EXPECT_EQ(shape_at(s, 0).path.segment_count(), 4u); }},
        {R"svg(<rect width="8" height="8" rx="-1" ry="2"/>)svg", "attribute rx: a negative value",
         [](const Scene& s) { EXPECT_GT(shape_at(s, 0).path.segment_count(), 4u); }},
        {R"svg(<rect transform="rotate(1,2)" width="1" height="1"/>)svg",
         "t.svg:2: <rect>: transform: rotate()",
         [](const Scene& s) {
             EXPECT_EQ((shape_at(s, 0).transform * Point{1, 1}), (Point{1, 1}));
         }},
        // Odd coordinate counts drop the last number; one point draws nothing.
        {R"svg(<polygon points="0 0 10 0 10 10 5"/>)svg",
         "t.svg:2: <polygon>: attribute points: odd",
         [](const Scene& s) { EXPECT_EQ(shape_at(s, 0).path.segment_count(), 3u); }},
        {R"svg(<polyline points="0 0 10" stroke="red"/>)svg", "attribute points: odd", none},
    };
    for (const Case& c : cases) run(c);
}

TEST(ErrorHandling, RootAttributesInErrorTakeTheirInitialValues) {
    // An invalid viewBox is ignored: the rect maps one to one.
    run({"<rect width='5' height='5'/>", "t.svg:1: <svg>: viewBox: '0 0 ten 10'",
         [](const Scene& s) {
             EXPECT_EQ((shape_at(s, 0).transform * Point{5, 5}), (Point{5, 5}));
         }},
        R"svg(width="100" height="100" viewBox="0 0 ten 10")svg");
    run({"<rect width='5' height='5'/>", "viewBox: a negative width",
         [](const Scene& s) { EXPECT_EQ(s.width, 100); }},
        R"svg(viewBox="0 0 -1 5")svg");
    // xMidYMid meet instead: 0..10 into 200 x 100 is scaled by 10 and centred.
    run({"<rect width='10' height='10'/>", "preserveAspectRatio: 'xMidYMiddle'",
         [](const Scene& s) {
             EXPECT_EQ((shape_at(s, 0).transform * Point{0, 0}), (Point{50, 0}));
         }},
        R"svg(width="200" height="100" viewBox="0 0 10 10" preserveAspectRatio="xMidYMiddle")svg");
    // An invalid width is auto, 100%: the viewBox's.
    run({"<rect width='1' height='1'/>", "attribute width: 'wide'",
         [](const Scene& s) { EXPECT_EQ(s.width, 30); }},
        R"svg(width="wide" height="20" viewBox="0 0 30 20")svg");
}

TEST(ErrorHandling, ValidEdgeCasesDrawWithoutAWarning) {
    const std::pair<const char*, const char*> cases[] = {
        // No size and no viewBox: 100 x 100, as resvg does.
        {"", ""},
        {R"svg(<rect width="5" height="5" rx="auto"/><circle r="0"/><rect width="0" height="5"/>)svg",
         R"svg(width="10" height="10")svg"},
        {R"svg(<ellipse rx="3"/><ellipse ry="auto" rx="2"/>)svg",
         R"svg(width="10" height="10")svg"},
    };
    for (const auto& [body, root] : cases) {
        const SvgResult r = parse_svg(std::string("<svg ") + root + ">" + body + "</svg>", "v.svg");
        ASSERT_TRUE(r.scene) << body << r.error;
        EXPECT_TRUE(r.warnings.empty()) << body << ": " << r.warnings.at(0).text();
    }
    EXPECT_EQ(parse_svg("<svg/>", "v.svg").scene->width, 100);
    // rx absent on an ellipse: ry's value.
    const SvgResult e =
        parse_svg(R"svg(<svg width="10" height="10"><ellipse ry="3"/></svg>)svg", "e.svg");
    EXPECT_NEAR(shape_at(*e.scene, 0).path.bounds().width(), 6, 1e-12);
}

} // namespace
} // namespace casteljau
