// Structure as SVG resolves it at read time: use (and symbol and svg through
// it), nested viewports, switch and conditional attributes, transform-origin,
// and the element limit counted after <use> is expanded.
#include "casteljau/svg/conditional.h"
#include "casteljau/svg/reader.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace casteljau {
namespace {

SvgResult read(const std::string& body, const SvgOptions& o = {}) {
    return parse_svg(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="200" height="200">)svg" +
                         body + "</svg>",
                     "s.svg", o);
}

// Every shape of the scene in drawing order, with its device bounds.
void collect(const Group& g, std::vector<const Shape*>& out) {
    for (const Node& n : g.children) {
        if (const Shape* s = std::get_if<Shape>(&n.item))
            out.push_back(s);
        else
            collect(std::get<Group>(n.item), out);
    }
}
std::vector<const Shape*> shapes(const Scene& s) {
    std::vector<const Shape*> out;
    collect(s.root, out);
    return out;
}
Rect device_bounds(const Shape& s) {
    const Rect b = s.path.bounds();
    return Rect::from_points(s.transform * b.min(), s.transform * b.max());
}
void expect_box(const Shape& s, Rect want, const char* what) {
    const Rect b = device_bounds(s);
    EXPECT_NEAR(b.x0, want.x0, 1e-9) << what;
    EXPECT_NEAR(b.y0, want.y0, 1e-9) << what;
    EXPECT_NEAR(b.x1, want.x1, 1e-9) << what;
    EXPECT_NEAR(b.y1, want.y1, 1e-9) << what;
}

TEST(Use, DrawsItsTargetMovedAndInheritingItsStyle) {
    const SvgResult r = read(R"svg(<defs><rect id="r" width="10" height="5"/></defs>
        <use href="#r" x="20" y="30" fill="blue"/>
        <use xlink:href="#r" transform="scale(2)" x="5" fill="lime" opacity="0.5"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty());
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 2u);
    expect_box(*s[0], {20, 30, 30, 35}, "moved by x, y");
    EXPECT_EQ(s[0]->fill->color, (Rgba{0, 0, 1, 1}));
    expect_box(*s[1], {10, 0, 30, 10}, "the use's transform, then x");
    EXPECT_EQ(s[1]->fill->color, (Rgba{0, 1, 0, 1}));
    // The use's opacity makes a group (a layer).
    ASSERT_TRUE(std::holds_alternative<Group>(r.scene->root.children.at(1).item));
    EXPECT_EQ(std::get<Group>(r.scene->root.children[1].item).opacity, 0.5f);
}

TEST(Use, SymbolsAndSvgsBecomeViewportsOfTheUsesSize) {
    // A 10 x 10 view box into 40 x 20, centred (xMidYMid meet): scale 2,
    // moved right by 10; with refX/refY the symbol's point lands on x, y.
    const SvgResult r = read(R"svg(
        <symbol id="s" viewBox="0 0 10 10"><rect width="10" height="10"/></symbol>
        <symbol id="t" viewBox="0 0 10 10" refX="5" refY="5"><rect width="10" height="10"/></symbol>
        <svg id="v" viewBox="0 0 10 10" width="5" height="5"><rect width="10" height="10"/></svg>
        <use href="#s" x="100" y="10" width="40" height="20"/>
        <use href="#t" x="100" y="100" width="40" height="20"/>
        <use href="#v" x="50" y="50" width="30" height="30"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 4u); // the nested svg itself, then the three instances
    expect_box(*s[0], {0, 0, 5, 5}, "nested svg, its own size");
    expect_box(*s[1], {110, 10, 130, 30}, "symbol, meet, centred");
    expect_box(*s[2], {90, 90, 110, 110}, "symbol, refX/refY on x, y");
    expect_box(*s[3], {50, 50, 80, 80}, "svg, the use's size wins");
}

TEST(NestedSvg, ViewportPercentagesAndDisabling) {
    const SvgResult r = read(R"svg(
        <svg x="10" y="20" width="50" height="40"><rect width="50%" height="50%"/></svg>
        <svg width="0" height="10"><rect width="5" height="5"/></svg>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 1u);
    expect_box(*s[0], {10, 20, 35, 40}, "percentages of the nested viewport");
}

TEST(Use, CyclesAndMissingTargetsAreSkippedWithAWarning) {
    const SvgResult r = read(R"svg(<g id="a"><rect width="1" height="1"/><use href="#a"/></g>
        <g id="b"><use href="#c"/></g><g id="c"><use href="#b"/></g><use href="#nothing"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(shapes(*r.scene).size(), 1u);
    ASSERT_EQ(r.warnings.size(), 4u); // a; b -> c -> b and c -> b -> c; nothing
    EXPECT_NE(r.warnings[0].text().find("s.svg:1: <use>: href '#a' contains the use itself"),
              std::string::npos)
        << r.warnings[0].text();
    EXPECT_NE(r.warnings[1].text().find("makes a cycle"), std::string::npos);
    EXPECT_NE(r.warnings[3].text().find("'#nothing' names no element"), std::string::npos);
}

TEST(Use, TheElementLimitCountsInstancesBeforeAnyIsBuilt) {
    // Ten levels of ten uses: 10^10 rectangles. Refused by the count alone.
    std::string defs = R"svg(<defs><rect id="a0" width="1" height="1"/>)svg";
    for (int i = 1; i < 10; ++i) {
        defs += "<g id='a" + std::to_string(i) + "'>";
        for (int k = 0; k < 10; ++k) defs += "<use href='#a" + std::to_string(i - 1) + "'/>";
        defs += "</g>";
    }
    const SvgResult bomb = read(defs + "</defs><use href='#a9'/>");
    EXPECT_FALSE(bomb.scene);
    EXPECT_NE(bomb.error.find("more than 1000000 elements once <use> is expanded"),
              std::string::npos)
        << bomb.error;
    // Three levels (1000 rectangles) is fine, and each is drawn.
    const SvgResult ok = read(defs + "</defs><use href='#a3'/>");
    ASSERT_TRUE(ok.scene) << ok.error;
    EXPECT_EQ(shapes(*ok.scene).size(), 1000u);
}

TEST(Switch, DrawsTheFirstChildWhoseConditionsHold) {
    const std::string body = R"svg(<switch>
        <rect systemLanguage="fr" width="1" height="1" fill="red"/>
        <rect systemLanguage="de, en-US" width="2" height="2" fill="lime"/>
        <rect width="3" height="3" fill="blue"/></switch>
        <rect requiredExtensions="" width="9" height="9"/>
        <rect systemLanguage="fr" width="9" height="9"/>)svg";
    const SvgResult en = read(body);
    ASSERT_TRUE(en.scene) << en.error;
    ASSERT_EQ(shapes(*en.scene).size(), 1u);
    EXPECT_EQ(shapes(*en.scene)[0]->fill->color, (Rgba{0, 1, 0, 1}));
    SvgOptions french;
    french.languages = {"fr-CA"};
    const SvgResult fr = read(body, french);
    ASSERT_EQ(shapes(*fr.scene).size(), 2u); // the switch's first, the last rect
    EXPECT_EQ(shapes(*fr.scene)[0]->fill->color, (Rgba{1, 0, 0, 1}));
    SvgOptions none;
    none.languages = {"ja"};
    EXPECT_EQ(shapes(*read(body, none).scene)[0]->fill->color, (Rgba{0, 0, 1, 1}));
}

// draw.io's labels: a foreignObject of HTML (requiredFeatures, which SVG 2
// no longer evaluates, so its conditions hold) and the same label as text
// after it. A reader that cannot draw the foreignObject draws the text, as
// librsvg and resvg do; before, the switch drew nothing (and warned).
TEST(Switch, PassesOverAChildItCannotDraw) {
    const SvgResult r = read(R"svg(<switch>
        <foreignObject requiredFeatures="http://www.w3.org/TR/SVG11/feature#Extensibility"
          width="10" height="10"><div xmlns="http://www.w3.org/1999/xhtml">Label</div></foreignObject>
        <rect width="2" height="2" fill="lime"/></switch>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0].text();
    ASSERT_EQ(shapes(*r.scene).size(), 1u);
    EXPECT_EQ(shapes(*r.scene)[0]->fill->color, (Rgba{0, 1, 0, 1}));
    // Without another child, the foreignObject is the one skipped, with its warning.
    const SvgResult alone = read(R"svg(<switch><foreignObject width="1" height="1"/></switch>)svg");
    ASSERT_TRUE(alone.scene) << alone.error;
    ASSERT_EQ(alone.warnings.size(), 1u);
    EXPECT_NE(alone.warnings[0].message.find("not supported yet"), std::string::npos);
}

TEST(Conditional, LanguageTagsMatchByPrefixEitherWay) {
    const std::vector<std::string> en{"en"}, en_gb{"EN-gb"};
    EXPECT_TRUE(conditions_hold({"en-US", {}}, en));
    EXPECT_TRUE(conditions_hold({"fr, en", {}}, en_gb));
    EXPECT_FALSE(conditions_hold({"eng", {}}, en));
    EXPECT_FALSE(conditions_hold({"", {}}, en));
    EXPECT_FALSE(conditions_hold({{}, ""}, en));
    EXPECT_TRUE(conditions_hold({}, en));
}

TEST(Markers, DrawnAtEachVertexTurnedAndScaledByTheStroke) {
    // A 2 x 2 marker box (markerUnits strokeWidth, stroke 3: 6 x 6 px) whose
    // 10 x 10 view box puts its centre (refX, refY) on each vertex.
    const SvgResult r = read(R"svg(<marker id="m" viewBox="0 0 10 10" refX="5" refY="5"
        markerWidth="2" markerHeight="2" orient="auto"><rect width="10" height="4"/></marker>
        <polyline points="10,10 50,10 50,50" fill="none" stroke="black" stroke-width="3"
        marker-start="url(#m)" marker-mid="url(#m)" marker-end="url(#m)" opacity="0.5"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty()) << r.warnings.at(0).text();
    // One group (the element's opacity) holding the polyline and 3 markers.
    ASSERT_EQ(r.scene->root.children.size(), 1u);
    EXPECT_EQ(std::get<Group>(r.scene->root.children[0].item).opacity, 0.5f);
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_EQ(s[0]->opacity, 1.0f);
    // Start: along +x; the rect spans the box's top 0.4: x 7..13, y 7..9.4.
    expect_box(*s[1], {7, 7, 13, 9.4}, "start marker");
    // End: turned to +y (90 degrees): the rect's top edge is now at x = 53.
    expect_box(*s[3], {50.6, 47, 53, 53}, "end marker, turned");
    const Rect mid = device_bounds(*s[2]); // 45 degrees at the corner
    EXPECT_NEAR((mid.x0 + mid.x1) / 2, 50 + 0.8 * std::cos(3.14159265358979 / 4) * 3, 3);
}

TEST(Markers, BrokenReferencesAndExpansionPastTheLimit) {
    const SvgResult r = read(R"svg(<path d="M0 0 H10" stroke="red" marker-end="url(#none)"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("url(#none) names no marker"), std::string::npos);
    // 300 vertices x a marker of 5 elements: over a limit of 1000.
    std::string d = "M0 0";
    for (int i = 0; i < 300; ++i) d += " L" + std::to_string(i) + " 1";
    SvgOptions few;
    few.max_elements = 1000;
    const SvgResult big = read(R"svg(<marker id="m"><g><rect width="1" height="1"/><rect/><rect/>
        </g></marker><path d=")svg" +
                                   d + R"svg(" marker-mid="url(#m)"/>)svg",
                               few);
    EXPECT_FALSE(big.scene);
    EXPECT_NE(big.error.find("more than 1000 elements once its markers are drawn"),
              std::string::npos)
        << big.error;
}

TEST(Markers, TheMarkerShorthandIsCssOnly) {
    // SVG 2, 6.6: marker is no presentation attribute; found on WPT's
    // marker-004, where the attribute drew red markers.
    const SvgResult r = read(R"svg(<marker id="m"><rect width="1" height="1"/></marker>
        <path d="M0 0 H10" stroke="red" marker="url(#m)"/>
        <path d="M0 0 H10" stroke="red" style="marker: url(#m)"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_EQ(shapes(*r.scene).size(), 4u) << "the first path alone, the second and 2 markers";
}

TEST(PathLength, DashesAreInItsUnits) {
    // SVG 2, 9.1.4: a 100 px line with pathLength 10 dashes "1 1" as 10 10.
    const SvgResult r = read(R"svg(<g stroke="black" stroke-dasharray="1 1" stroke-dashoffset="0.5">
        <path d="M0 0 H100" pathLength="10"/><line x2="100" pathLength="0"/>
        <path d="M0 0 H100" pathLength="-1"/><path d="M0 0 H100"/></g>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 4u);
    ASSERT_EQ(s[0]->stroke->geometry.dashes.size(), 2u);
    EXPECT_NEAR(s[0]->stroke->geometry.dashes[0], 10, 1e-6);
    EXPECT_NEAR(s[0]->stroke->geometry.dash_offset, 5, 1e-6);
    EXPECT_TRUE(s[1]->stroke->geometry.dashes.empty()) << "0: the first dash forever";
    EXPECT_EQ(s[2]->stroke->geometry.dashes, s[3]->stroke->geometry.dashes) << "negative: ignored";
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("pathLength: '-1'"), std::string::npos)
        << r.warnings[0].text();
}

TEST(PathLength, TextPathStartOffsetIsInItsUnits) {
    // Found on WPT's pathLength-positive and -zero: startOffset 1 of a
    // pathLength of 2 is half the path, as 50% is; of a pathLength of 0, an
    // infinite offset: no glyph on the path.
    const auto glyph_boxes = [](const std::string& path_length, const char* offset) {
        const SvgResult r =
            read(R"svg(<defs><path id="p" d="M 50 50 h 200")svg" + path_length +
                 R"svg(/></defs><text font-size="20"><textPath href="#p" startOffset=")svg" +
                 offset + R"svg(">Fox</textPath></text>)svg");
        EXPECT_TRUE(r.scene) << r.error;
        std::vector<Rect> boxes;
        for (const Shape* s : shapes(*r.scene))
            if (!s->path.empty()) boxes.push_back(device_bounds(*s));
        return boxes;
    };
    const std::vector<Rect> half = glyph_boxes("", "50%"),
                            scaled = glyph_boxes(R"( pathLength="2")", "1");
    ASSERT_FALSE(half.empty());
    ASSERT_EQ(half.size(), scaled.size());
    for (std::size_t i = 0; i < half.size(); ++i) {
        EXPECT_NEAR(half[i].x0, scaled[i].x0, 1e-9) << i;
        EXPECT_NEAR(half[i].y0, scaled[i].y0, 1e-9) << i;
    }
    EXPECT_TRUE(glyph_boxes(R"( pathLength="0")", "1").empty());
    EXPECT_EQ(glyph_boxes(R"( pathLength="0")", "0").size(), glyph_boxes("", "0").size());
}

TEST(DProperty, CssOverridesTheAttribute) {
    // SVG 2, 9.3.1; found on WPT's path/property/priority, where CSS's d was
    // ignored.
    const SvgResult r = read(R"svg(<style>#a { d: path('M 20 10 h 70') }</style>
        <path id="a" d="M 10 20 h 70" stroke="blue"/>
        <path d="M 10 90 h 70" style="d: path(&quot;M 20 80 h 70&quot;)" stroke="blue"/>
        <path d="M 10 50 h 70" style="d: path('M 20 80 h 70 Q')" stroke="blue"/>
        <path d="M 10 60 h 70" style="d: none" stroke="blue"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 3u) << "none draws nothing";
    expect_box(*s[0], {20, 10, 90, 10}, "the style sheet's");
    expect_box(*s[1], {20, 80, 90, 80}, "the style attribute's");
    expect_box(*s[2], {10, 50, 80, 50}, "invalid path data in CSS: the attribute's");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("property d: 'path('M 20 80 h 70 Q')'"), std::string::npos)
        << r.warnings[0].text();
}

TEST(Painting, PaintOrderAndShapeRendering) {
    const SvgResult r = read(R"svg(<marker id="m"><rect width="1" height="1"/></marker>
        <rect width="5" height="5" stroke="red" paint-order="stroke"/>
        <rect width="5" height="5" stroke="red" paint-order="normal" shape-rendering="crispEdges"/>
        <path d="M0 0 H5 V5" stroke="red" marker-mid="url(#m)" paint-order="fill markers"/>
        <path d="M0 0 H5 V5" stroke="red" marker-mid="url(#m)" paint-order="markers"/>
        <rect width="5" height="5" paint-order="fill fill"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 8u);
    EXPECT_TRUE(s[0]->stroke_first);
    EXPECT_FALSE(s[1]->stroke_first);
    EXPECT_TRUE(s[0]->antialias);
    EXPECT_FALSE(s[1]->antialias);
    // fill, markers, stroke: the path split around its marker.
    EXPECT_TRUE(s[2]->fill && !s[2]->stroke);
    EXPECT_EQ(s[3]->path.segment_count(), 4u); // the marker's rect
    EXPECT_TRUE(!s[4]->fill && s[4]->stroke);
    // markers first: under the whole shape.
    EXPECT_EQ(s[5]->path.segment_count(), 4u);
    EXPECT_TRUE(s[6]->fill && s[6]->stroke);
    // "fill fill" is invalid: normal, with a warning.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("property paint-order"), std::string::npos);
}

// librsvg 2.54 ignores vector-effect, so this is tested against the spec.
TEST(Painting, NonScalingStrokeIsDrawnInHostSpace) {
    const SvgResult r = read(R"svg(<linearGradient id="g"><stop stop-color="red"/></linearGradient>
        <g transform="scale(4 2)"><rect x="3" y="5" width="20" height="40" fill="url(#g)"
        stroke="black" stroke-width="2" vector-effect="non-scaling-stroke"/></g>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const Shape& s = *shapes(*r.scene).at(0);
    EXPECT_EQ((s.transform * Point{7, 9}), (Point{7, 9}));
    EXPECT_EQ((s.transform * Point{0, 0}), (Point{0, 0}));
    expect_box(s, {12, 10, 92, 90}, "the path mapped into host space");
    EXPECT_EQ(s.stroke->geometry.width, 2); // 2 px, not 8 by 4
    // The gradient's objectBoundingBox map is kept: the unit square lands on
    // the same device box.
    ASSERT_TRUE(s.fill->gradient);
    EXPECT_FALSE(s.fill->gradient->object_bounding_box);
    EXPECT_EQ((s.fill->gradient->transform * Point{1, 1}), (Point{92, 90}));
}

TEST(TransformOrigin, TheTransformIsAppliedAboutIt) {
    // rotate(90) about (15, 15): the 10 x 10 square at 10, 10 stays put.
    const SvgResult r = read(R"svg(
        <rect x="10" y="10" width="10" height="10" transform="rotate(90)" transform-origin="15 15"/>
        <rect width="10" height="10" transform="scale(2)" style="transform-origin: center"/>
        <rect width="10" height="10" transform="scale(2)" transform-origin="right bottom"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    expect_box(*s[0], {10, 10, 20, 20}, "rotated about its centre");
    expect_box(*s[1], {-100, -100, -80, -80}, "scaled about the viewport's centre");
    expect_box(*s[2], {-200, -200, -180, -180}, "about the viewport's corner");
}

TEST(TransformProperty, CssOverridesTheAttributeAndAnInvalidValueIsIgnored) {
    // SVG 2, 8.5: the attribute is the presentation attribute of the CSS
    // transform property; found on WPT's clip-path-css-transform-001, whose
    // style sheet transform was ignored.
    const SvgResult r = read(R"svg(<style>#a { transform: translate(20px, 0) }
          .b { transform: rotate(90) }</style>
        <rect id="a" width="10" height="10" transform="translate(5 5)"/>
        <rect width="10" height="10" transform="translate(5 5)" style="transform: none"/>
        <rect class="b" width="10" height="10" transform="translate(5,5)"/>
        <rect width="10" height="10" style="transform: scale(2) translateY(1em)"/>
        <rect width="10" height="10" transform="translate(5px, 1em) rotate(0.25turn)"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 5u);
    expect_box(*s[0], {20, 0, 30, 10}, "the style sheet's, not the attribute's");
    expect_box(*s[1], {0, 0, 10, 10}, "none");
    expect_box(*s[2], {5, 5, 15, 15}, "CSS's rotate needs a unit: the attribute stays");
    expect_box(*s[3], {0, 32, 20, 52}, "em of the font size, scaled");
    expect_box(*s[4], {-5, 16, 5, 26}, "units in the attribute, as browsers take them");
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("transform: rotate(): '90' is not an angle"),
              std::string::npos)
        << r.warnings[0].text();
}

TEST(TransformBox, FillBoxIsTheElementsOwnBox) {
    // rotate(180) about the centre of each one's own box leaves it in place;
    // translate(50%) moves by half its width.
    const SvgResult r = read(R"svg(<style>.c { transform-box: fill-box; transform-origin: center }
        </style>
        <rect class="c" x="20" y="20" width="60" height="40" transform="rotate(180)"/>
        <g class="c" style="transform: rotate(180deg)">
          <rect x="100" y="10" width="20" height="10"/><rect x="140" y="30" width="20" height="20"/></g>
        <rect class="c" x="10" y="100" width="40" height="10" style="transform: translate(50%)"/>
        <rect x="10" y="150" width="40" height="10" style="transform: translate(50%)"/>
        <rect class="c" x="10" y="170" width="20" height="10" stroke="black" stroke-width="4"
          style="transform-box: stroke-box; transform-origin: 0 0; transform: scale(2)"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty());
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 6u);
    expect_box(*s[0], {20, 20, 80, 60}, "a rect turned about its centre");
    // The group's box is its content's, 100..160 x 10..50, its centre (130, 30).
    expect_box(*s[1], {140, 40, 160, 50}, "mirrored through the group's centre");
    expect_box(*s[2], {100, 10, 120, 30}, "the other, mirrored too");
    expect_box(*s[3], {30, 100, 70, 110}, "half its own width");
    expect_box(*s[4], {110, 150, 150, 160}, "view-box: half the viewport's width");
    // The stroke box's corner (8, 168) stays; the rect doubles from there.
    expect_box(*s[5], {12, 172, 52, 192}, "about the stroke box's corner");
}

TEST(TransformBox, AMeasuredShapesProblemIsToldOnce) {
    // Measuring the fill box reads the geometry a second time, quietly.
    const SvgResult r = read(R"svg(<rect width="10" height="10" x="1zz"
        style="transform-box: fill-box; transform: scale(2)"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("attribute x: '1zz'"), std::string::npos)
        << r.warnings[0].text();
}

TEST(TransformBox, NestedFillBoxGroupsAreMeasuredOnceEach) {
    // Each group measures what it draws by walking it once; without the
    // measured boxes kept, 40 nested groups would walk the leaf 2^40 times.
    std::string body;
    for (int i = 0; i < 40; ++i)
        body += R"svg(<g style="transform-box: fill-box; transform-origin: center;
            transform: rotate(180deg)">)svg";
    body += R"(<rect x="10" y="20" width="30" height="10"/>)";
    for (int i = 0; i < 40; ++i) body += "</g>";
    const SvgResult r = read(body);
    ASSERT_TRUE(r.scene) << r.error;
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 1u);
    expect_box(*s[0], {10, 20, 40, 30}, "turned 40 times about its own centre");
}

TEST(ContextPaint, MarkersTakeTheirShapesPaintsAndUsesTheirOwn) {
    // SVG 2, 13.3: in a marker, the shape it is on; under a use, the use.
    const SvgResult r = read(R"svg(<defs>
          <marker id="m" markerWidth="4" markerHeight="4" markerUnits="userSpaceOnUse">
            <rect width="4" height="4" fill="context-stroke" stroke="context-fill"/></marker>
          <rect id="r" width="5" height="5" fill="context-fill" stroke="context-stroke"/></defs>
        <path d="M10 10 H50" fill="blue" stroke="red" marker-end="url(#m)"/>
        <use href="#r" fill="lime" stroke="yellow"/>
        <rect width="5" height="5" fill="context-fill" stroke="context-stroke"/>)svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty());
    const auto s = shapes(*r.scene);
    ASSERT_EQ(s.size(), 4u);
    EXPECT_FALSE(s[3]->fill || s[3]->stroke) << "no context element: none";
    ASSERT_TRUE(s[1]->fill && s[1]->stroke);
    EXPECT_EQ(s[1]->fill->color, (Rgba{1, 0, 0, 1})) << "the marker's fill: the path's stroke";
    EXPECT_EQ(s[1]->stroke->color, (Rgba{0, 0, 1, 1}));
    ASSERT_TRUE(s[2]->fill && s[2]->stroke);
    EXPECT_EQ(s[2]->fill->color, (Rgba{0, 1, 0, 1})) << "the use's fill";
    EXPECT_EQ(s[2]->stroke->color, (Rgba{1, 1, 0, 1}));
}

} // namespace
} // namespace casteljau
