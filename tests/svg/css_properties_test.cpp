// Style sheets as the SVG reader applies them (svg/css.h, svg/style.h):
// the cascade of gradient stops' properties, and SVG 2's geometry
// properties set from sheets and style attributes.
#include "casteljau/svg/reader.h"

#include <gtest/gtest.h>
#include <sstream>

namespace casteljau {
namespace {

// The stops of each drawn shape's fill gradient, in document order (a shape
// without one: no stops).
std::vector<std::vector<GradientStop>> fill_stops(const SvgResult& r) {
    std::vector<std::vector<GradientStop>> out;
    if (!r.scene) return out;
    for (const Node& n : r.scene->root.children) {
        const Shape* s = std::get_if<Shape>(&n.item);
        out.emplace_back();
        if (s && s->fill && s->fill->gradient) out.back() = s->fill->gradient->stops;
    }
    return out;
}

// A document of `body` and one 10 x 10 rect filled with each gradient named.
std::string with_rects(const std::string& body, std::initializer_list<const char*> ids) {
    std::string svg = "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>\n";
    svg += body;
    for (const char* id : ids) {
        svg += "<rect width='10' height='10' fill='url(#";
        svg += id;
        svg += ")'/>\n";
    }
    svg += "</svg>";
    return svg;
}

std::string warnings_text(const SvgResult& r) {
    std::string s;
    for (const SvgDiagnostic& w : r.warnings) s += w.text() + "\n";
    return s;
}

constexpr Rgba kBlack{0, 0, 0, 1}, kRed{1, 0, 0, 1}, kLime{0, 1, 0, 1}, kBlue{0, 0, 1, 1};

TEST(CssStops, TypeClassAndIdSelectorsSetStopColorAndOpacity) {
    const SvgResult r = parse_svg(with_rects(R"svg(<style>
          stop { stop-opacity: 0.5 }
          .a { stop-color: red }
          #b { stop-color: #00f; stop-opacity: 25% }
        </style>
        <linearGradient id="g">
          <stop class="a" offset="0"/>
          <stop id="b" offset="0.5"/>
          <stop offset="1" stop-color="lime" stop-opacity="1"/>
        </linearGradient>)svg",
                                             {"g"}),
                                  "s.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(warnings_text(r), "");
    const auto stops = fill_stops(r);
    ASSERT_EQ(stops.size(), 1u);
    ASSERT_EQ(stops[0].size(), 3u);
    EXPECT_EQ(stops[0][0].color, (Rgba{1, 0, 0, 0.5f}));  // class; type's opacity
    EXPECT_EQ(stops[0][1].color, (Rgba{0, 0, 1, 0.25f})); // id over type, a percentage
    EXPECT_EQ(stops[0][2].color, (Rgba{0, 1, 0, 0.5f}));  // the sheet over the attribute
    EXPECT_EQ(stops[0][1].offset, 0.5f);
}

TEST(CssStops, ImportantSheetDeclarationsBeatTheStyleAttribute) {
    const SvgResult r = parse_svg(with_rects(R"svg(<style>
          .x { stop-color: red !important }
          .y { stop-color: red }
        </style>
        <linearGradient id="g">
          <stop class="x" style="stop-color: blue"/>
          <stop class="y" style="stop-color: blue"/>
          <stop class="x" style="stop-color: lime !important"/>
          <stop class="y" stop-color="lime"/>
          <stop stop-color="red" style="stop-color: blue; stop-opacity: 50%"/>
        </linearGradient>)svg",
                                             {"g"}),
                                  "i.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(warnings_text(r), "");
    const auto stops = fill_stops(r);
    ASSERT_EQ(stops.size(), 1u);
    ASSERT_EQ(stops[0].size(), 5u);
    EXPECT_EQ(stops[0][0].color, kRed);  // sheet !important over the style attribute
    EXPECT_EQ(stops[0][1].color, kBlue); // the style attribute over the sheet
    EXPECT_EQ(stops[0][2].color, kLime); // style attribute !important over sheet !important
    EXPECT_EQ(stops[0][3].color, kRed);  // the sheet over the presentation attribute
    EXPECT_EQ(stops[0][4].color, (Rgba{0, 0, 1, 0.5f}));
}

TEST(CssStops, CurrentColorIsTheStopsComputedColor) {
    const SvgResult r = parse_svg(with_rects(R"svg(<style>
          #g2 { color: blue }
          .c { stop-color: CurrentColor }
          g { color: lime }
        </style>
        <linearGradient id="g1" color="red">
          <stop offset="0" stop-color="currentColor" stop-opacity="0.5"/>
          <stop offset="1" class="c" style="color: lime"/>
        </linearGradient>
        <linearGradient id="g2"><stop class="c"/></linearGradient>
        <g><linearGradient id="g3"><stop class="c"/></linearGradient></g>
        <linearGradient id="g4"><stop class="c"/></linearGradient>)svg",
                                             {"g1", "g2", "g3", "g4"}),
                                  "c.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(warnings_text(r), "");
    const auto stops = fill_stops(r);
    ASSERT_EQ(stops.size(), 4u);
    ASSERT_EQ(stops[0].size(), 2u);
    EXPECT_EQ(stops[0][0].color, (Rgba{1, 0, 0, 0.5f})); // color from the gradient's attribute
    EXPECT_EQ(stops[0][1].color, kLime);                 // the stop's own color
    ASSERT_EQ(stops[1].size(), 1u);
    EXPECT_EQ(stops[1][0].color, kBlue); // color from the sheet, on the gradient
    ASSERT_EQ(stops[2].size(), 1u);
    EXPECT_EQ(stops[2][0].color, kLime); // from a group around the gradient
    ASSERT_EQ(stops[3].size(), 1u);
    EXPECT_EQ(stops[3][0].color, kBlack); // the initial color
}

TEST(CssStops, InheritTakesTheGradientElementsValue) {
    const SvgResult r = parse_svg(with_rects(R"svg(<style>
          #h { stop-color: blue; stop-opacity: 0.5 }
          .up { stop-color: inherit; stop-opacity: inherit }
        </style>
        <linearGradient id="h">
          <stop stop-color="inherit" stop-opacity="inherit"/>
          <stop style="stop-color: inherit"/>
          <stop/>
        </linearGradient>
        <linearGradient id="k" stop-color="red"><stop class="up"/></linearGradient>
        <linearGradient id="m"><stop class="up"/></linearGradient>
        <g stop-color="lime"><linearGradient id="n" stop-color="inherit"><stop class="up"/>
        </linearGradient></g>
        <linearGradient id="p" stop-color="currentColor" color="red"><stop class="up" color="blue"/>
        </linearGradient>)svg",
                                             {"h", "k", "m", "n", "p"}),
                                  "h.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(warnings_text(r), "");
    const auto stops = fill_stops(r);
    ASSERT_EQ(stops.size(), 5u);
    ASSERT_EQ(stops[0].size(), 3u);
    EXPECT_EQ(stops[0][0].color, (Rgba{0, 0, 1, 0.5f})); // the gradient's, from the sheet
    EXPECT_EQ(stops[0][1].color, kBlue);
    EXPECT_EQ(stops[0][2].color, kBlack); // not inherited unless told: initial
    ASSERT_EQ(stops[1].size(), 1u);
    EXPECT_EQ(stops[1][0].color, kRed); // the gradient's attribute
    ASSERT_EQ(stops[2].size(), 1u);
    EXPECT_EQ(stops[2][0].color, kBlack); // the gradient declares none: initial
    ASSERT_EQ(stops[3].size(), 1u);
    EXPECT_EQ(stops[3][0].color, kLime); // inherited twice
    ASSERT_EQ(stops[4].size(), 1u);
    EXPECT_EQ(stops[4][0].color, kBlue); // currentColor inherited: the stop's color
}

TEST(CssStops, AnInvalidDeclarationIsAProblemAndDropped) {
    // As CSS drops an invalid declaration: the one before it in the cascade
    // applies (the attribute here), or the initial value when none does.
    const std::string svg = with_rects(R"svg(<style>
          .bad { stop-color: nonsense; stop-opacity: lots }
          #q { stop-color: 12px }
        </style>
        <linearGradient id="g"><stop class="bad" stop-color="red" stop-opacity="0.5"/>
        </linearGradient>
        <linearGradient id="q"><stop stop-color="inherit" stop-opacity=""/></linearGradient>)svg",
                                       {"g", "q"});
    const SvgResult r = parse_svg(svg, "b.svg");
    ASSERT_TRUE(r.scene) << r.error;
    const std::string w = warnings_text(r);
    EXPECT_NE(w.find("b.svg:6: <stop>: stop-color: 'nonsense' is not a color; ignored"),
              std::string::npos)
        << w;
    EXPECT_NE(w.find("b.svg:6: <stop>: stop-opacity: 'lots' is not a number; ignored"),
              std::string::npos)
        << w;
    // Told about the element that declared it.
    EXPECT_NE(w.find("b.svg:8: <linearGradient>: stop-color: '12px' is not a color; black is used"),
              std::string::npos)
        << w;
    EXPECT_NE(w.find("b.svg:8: <stop>: stop-opacity: '' is not a number; 1 is used"),
              std::string::npos)
        << w;
    const auto stops = fill_stops(r);
    ASSERT_EQ(stops.size(), 2u);
    ASSERT_EQ(stops[0].size(), 1u);
    EXPECT_EQ(stops[0][0].color, (Rgba{1, 0, 0, 0.5f})) << "the attributes, under the sheet";
    ASSERT_EQ(stops[1].size(), 1u);
    EXPECT_EQ(stops[1][0].color, kBlack);
    SvgOptions strict;
    strict.strict = true;
    const SvgResult refused = parse_svg(svg, "b.svg", strict);
    EXPECT_FALSE(refused.scene);
    EXPECT_NE(refused.error.find("b.svg:6: <stop>: stop-color: 'nonsense' is not a color"),
              std::string::npos)
        << refused.error;
}

// The control box of each shape the document draws, in document order.
std::vector<Rect> shape_boxes(const SvgResult& r) {
    std::vector<Rect> boxes;
    const std::function<void(const Group&)> visit = [&](const Group& g) {
        for (const Node& n : g.children) {
            if (const Shape* s = std::get_if<Shape>(&n.item))
                boxes.push_back(mapped_box(s->path.control_bounds(), s->transform));
            else
                visit(std::get<Group>(n.item));
        }
    };
    visit(r.scene->root);
    return boxes;
}

TEST(CssGeometry, StyleSheetsAndStyleAttributesSetShapeGeometry) {
    // SVG 2's geometry properties are CSS properties of rect, circle, ellipse
    // and image: the cascade sets them, as other properties; not an svg's or
    // a use's size. An invalid declaration is a problem and drops out.
    const SvgResult r = parse_svg(R"svg(<svg xmlns="http://www.w3.org/2000/svg"
        xmlns:xlink="http://www.w3.org/1999/xlink" width="200" height="200">
          <style>
            rect { x: 20; height: 160px }
            #c { cx: 100px }
            .e { rx: 30px }
            .bad { width: wide }
          </style>
          <rect y="20" width="160"/>
          <rect x="5" y="5" width="10" height="10" style="HEIGHT : 50px; y: 1px"/>
          <circle id="c" cy="100" r="80"/>
          <ellipse class="e" cx="50" cy="50" ry="10"/>
          <rect class="bad" width="30" style="height: 12px"/>
          <svg viewBox="0 0 100 100" style="width: 50px; height: 50px">
            <circle cx="50" cy="50" r="50"/></svg>
        </svg>)svg",
                                  "g.svg");
    ASSERT_TRUE(r.scene) << r.error;
    const std::vector<Rect> b = shape_boxes(r);
    ASSERT_EQ(b.size(), 6u);
    const auto expect_box = [](const Rect& got, const Rect& want, const char* why) {
        EXPECT_NEAR(got.x0, want.x0, 1e-9) << why;
        EXPECT_NEAR(got.y0, want.y0, 1e-9) << why;
        EXPECT_NEAR(got.x1, want.x1, 1e-9) << why;
        EXPECT_NEAR(got.y1, want.y1, 1e-9) << why;
    };
    expect_box(b[0], {20, 20, 180, 180}, "type selector, a unitless x");
    expect_box(b[1], {20, 1, 30, 51}, "the style attribute over the sheet's height");
    expect_box(b[2], {20, 20, 180, 180}, "id selector: cx");
    expect_box(b[3], {20, 40, 80, 60}, "class selector: rx");
    expect_box(b[4], {20, 0, 50, 12}, "an invalid width: the attribute's");
    expect_box(b[5], {0, 0, 200, 200}, "the nested svg's CSS size ignored: 100%");
    EXPECT_EQ(warnings_text(r),
              "g.svg:13: <rect>: style sheet: property width: 'wide' is not a length; ignored\n");
}

} // namespace
} // namespace casteljau
