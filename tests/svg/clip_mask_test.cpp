// Clip paths, masks, patterns, blend modes and viewport clipping, drawn:
// what the specs say where librsvg (the agreement files' reference) does
// otherwise or does not draw it (a clip-path on a clipPath or on its
// children, the overflow of a symbol), exactness against direct fills, and
// bands bit-identical to a whole frame with every kind of layer.
#include "casteljau/render/bands.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "pixels.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>

namespace casteljau {
namespace {

Canvas render(const std::string& body, int size = 100,
              std::vector<SvgDiagnostic>* warnings = nullptr) {
    const std::string s = std::to_string(size);
    const SvgResult doc = parse_svg(
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" xmlns:xlink="http://www.w3.org/1999/xlink" width=")svg" +
            s + "\" height=\"" + s + "\">" + body + "</svg>",
        "t.svg");
    EXPECT_TRUE(doc.scene) << doc.error;
    if (warnings) *warnings = doc.warnings;
    Canvas c(size, size);
    if (doc.scene) Renderer().render(*doc.scene, Affine::identity(), c, RenderOptions{});
    return c;
}

using testing::max_difference;

TEST(ClipPath, CoverageIsTheClipShapesExactAreaCoverage) {
    // A rectangle over the canvas clipped by a circle gives, pixel for
    // pixel, the circle filled: the same rasterizer's coverage, not a stencil.
    const Canvas clipped =
        render(R"svg(<clipPath id="c"><circle cx="47.3" cy="51.1" r="31.7"/></clipPath>
        <rect width="100" height="100" fill="#3366cc" clip-path="url(#c)"/>)svg");
    const Canvas filled = render(R"svg(<circle cx="47.3" cy="51.1" r="31.7" fill="#3366cc"/>)svg");
    EXPECT_LT(max_difference(clipped, filled), 1e-6f);
    EXPECT_GT(clipped.row(51)[47].a, 0.99f);
    EXPECT_EQ(clipped.row(2)[2].a, 0.0f);
}

TEST(ClipPath, AClipPathOnTheClipPathIntersects) {
    // CSS Masking 1, 6.1: a clip-path on the clipPath clips the clip path.
    // (librsvg 2.54 ignores it.)
    const Canvas c = render(R"svg(<clipPath id="half"><rect width="50" height="100"/></clipPath>
        <clipPath id="disc" clip-path="url(#half)"><circle cx="50" cy="50" r="40"/></clipPath>
        <rect width="100" height="100" fill="#000" clip-path="url(#disc)"/>)svg");
    EXPECT_GT(c.row(50)[30].a, 0.99f) << "in both";
    EXPECT_EQ(c.row(50)[70].a, 0.0f) << "in the disc, outside the half";
    EXPECT_EQ(c.row(5)[30].a, 0.0f) << "in the half, outside the disc";
}

TEST(ClipPath, AClipPathOnAChildClipsThatChild) {
    const Canvas c = render(R"svg(<clipPath id="small"><circle cx="30" cy="50" r="15"/></clipPath>
        <clipPath id="two"><rect x="10" y="30" width="40" height="40" clip-path="url(#small)"/>
          <rect x="60" y="30" width="30" height="40"/></clipPath>
        <rect width="100" height="100" fill="#000" clip-path="url(#two)"/>)svg");
    EXPECT_GT(c.row(50)[30].a, 0.99f);
    EXPECT_EQ(c.row(33)[12].a, 0.0f) << "in the child rect, outside its own clip";
    EXPECT_GT(c.row(35)[75].a, 0.99f) << "the other child, unclipped";
}

TEST(ClipPath, ClipRuleAndInvalidChildrenAndUnits) {
    const Canvas c = render(R"svg(<clipPath id="ring"><path clip-rule="evenodd"
          d="M10 10 h80 v80 h-80 z M30 30 h40 v40 h-40 z"/><g><rect width="100" height="100"/></g></clipPath>
        <clipPath id="obb" clipPathUnits="objectBoundingBox"><rect width="0.5" height="1"/></clipPath>
        <rect width="100" height="100" fill="#000" clip-path="url(#ring)"/>
        <rect x="0" y="0" width="100" height="4" fill="#f00" clip-path="url(#obb)"/>)svg");
    EXPECT_EQ(c.row(50)[50].a, 0.0f) << "the hole (evenodd); the <g> child is ignored";
    EXPECT_GT(c.row(20)[20].a, 0.99f);
    EXPECT_GT(c.row(2)[20].r, 0.99f) << "left half of its own box";
    EXPECT_EQ(c.row(2)[80].a, 0.0f);
}

TEST(ClipPath, ClipsTheElementAsAWholeNotEachPaint) {
    // The clip applies to the element's fill and stroke drawn together: at
    // the clip's edge, inside the stroke, no fill shows through (clipping
    // each paint on its own, as librsvg does, lets it bleed through there).
    const Canvas c =
        render(R"svg(<clipPath id="c"><rect x="10.5" y="0" width="80" height="100"/></clipPath>
        <rect x="10" y="20" width="60" height="60" fill="#00ff00" stroke="#000" stroke-width="8"
          clip-path="url(#c)"/>)svg");
    const Premul p = c.row(50)[10]; // half inside the clip, on the stroke
    EXPECT_NEAR(p.a, 0.5f, 1e-5f);
    EXPECT_NEAR(p.g, 0.0f, 1e-6f) << "the fill under the stroke shows through";
}

TEST(ClipPath, AMissingReferenceIsIgnoredAndACycleDrawsNothing) {
    std::vector<SvgDiagnostic> w;
    const Canvas missing =
        render(R"svg(<rect width="100" height="100" clip-path="url(#nope)"/>)svg", 100, &w);
    EXPECT_GT(missing.row(50)[50].a, 0.99f);
    EXPECT_EQ(w.size(), 1u);
    const Canvas cycle = render(
        R"svg(<clipPath id="a" clip-path="url(#b)"><rect width="100" height="100"/></clipPath>
        <clipPath id="b" clip-path="url(#a)"><rect width="100" height="100"/></clipPath>
        <rect width="100" height="100" clip-path="url(#a)"/>)svg",
        100, &w);
    EXPECT_EQ(cycle.row(50)[50].a, 0.0f);
    EXPECT_FALSE(w.empty());
}

TEST(ClipPath, ABasicShapeClipsAsTheSameOutlineInAClipPath) {
    // Found on WPT's clip-path-shape-circle-001 and -inset-001: basic shapes
    // were ignored. Each against a clipPath of the outline it stands for, on
    // a 60 x 40 rectangle at (10, 20) (its box's centre (40, 40)).
    const struct {
        const char *shape, *outline;
    } cases[] = {
        {"circle()", R"svg(<circle cx="40" cy="40" r="20"/>)svg"},
        {"ellipse(farthest-side closest-side at 25% 50%)",
         R"svg(<ellipse cx="25" cy="40" rx="45" ry="20"/>)svg"},
        {"inset(5px 10% round 4px / 2px)",
         R"svg(<rect x="16" y="25" width="48" height="30" rx="4" ry="2"/>)svg"},
        {"polygon(evenodd, 0 0, 100% 0, 50% 100%, 0 50%, 100% 50%)",
         R"svg(<polygon points="10 20 70 20 40 60 10 40 70 40" clip-rule="evenodd"/>)svg"},
        {"path('M 0 0 H 30 V 20 Z')", R"svg(<path d="M10 20 H40 V40 Z"/>)svg"},
        {"view-box inset(10px)", R"svg(<rect x="10" y="10" width="80" height="80"/>)svg"},
    };
    for (const auto& [shape, outline] : cases) {
        const std::string rect =
            R"svg(<rect x="10" y="20" width="60" height="40" fill="#3366cc" )svg";
        const Canvas by_shape = render(rect + "clip-path=\"" + shape + "\"/>");
        const Canvas by_clip = render("<clipPath id=\"c\">" + std::string(outline) + "</clipPath>" +
                                      rect + "clip-path=\"url(#c)\"/>");
        EXPECT_LE(max_difference(by_shape, by_clip), 1.0f / 255) << shape;
        float most = 0; // and not by drawing nothing in both
        for (int y = 0; y < 100; ++y)
            for (int x = 0; x < 100; ++x) most = std::max(most, by_shape.row(y)[x].a);
        EXPECT_GT(most, 0.99f) << shape;
    }
}

TEST(ClipPath, ABasicShapesBoxIsTheStrokeBoxUnlessItSaysOtherwise) {
    // inset(0) of the stroke box (border-box, the initial box) clips nothing
    // of a square's stroke; of the fill box, its outer half.
    const std::string square =
        R"svg(<rect x="30" y="30" width="40" height="40" fill="none" stroke="black" stroke-width="10" )svg";
    const Canvas whole = render(square + "/>");
    EXPECT_EQ(max_difference(render(square + R"svg(clip-path="inset(0)"/>)svg"), whole), 0.0f);
    const Canvas inner = render(square + R"svg(clip-path="fill-box"/>)svg");
    EXPECT_EQ(inner.row(50)[27].a, 0.0f) << "outside the fill box";
    EXPECT_GT(inner.row(50)[32].a, 0.99f) << "inside it";
    std::vector<SvgDiagnostic> warnings;
    render(square + R"svg(clip-path="circle(50)"/>)svg", 100, &warnings);
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].text().find("a basic shape"), std::string::npos) << warnings[0].text();
}

TEST(ClipPath, TheBoundingBoxLeavesMarkersOut) {
    // Found on WPT's clip-path-on-marker-001: an objectBoundingBox clip of
    // the element's own box (SVG 2, 8.10: markers do not count) clips the
    // marker that reaches out of it; the box had taken the marker in.
    const Canvas c = render(R"svg(<clipPath id="c" clipPathUnits="objectBoundingBox">
        <rect width="1" height="1"/></clipPath>
        <marker id="m" markerWidth="40" markerHeight="40" refX="20" refY="20"
          markerUnits="userSpaceOnUse"><rect width="40" height="40" fill="blue"/></marker>
        <path d="M30 30 H90 V90 H30 Z" fill="green" marker-start="url(#m)"
          clip-path="url(#c)"/>)svg");
    EXPECT_EQ(c.row(15)[15].a, 0.0f) << "the marker outside the box";
    EXPECT_GT(c.row(40)[40].b, 0.99f) << "the marker inside it";
    EXPECT_GT(c.row(80)[80].g, 0.4f) << "the path";
}

TEST(Mask, LuminanceAndAlpha) {
    // A mask of gray g scales by its luminance, 0.2125 r + 0.7154 g + 0.0721 b
    // of the sRGB-encoded values; mask-type: alpha by its alpha.
    const Canvas c =
        render(R"svg(<mask id="red"><rect width="100" height="100" fill="#ff0000"/></mask>
        <mask id="alpha" style="mask-type:alpha"><rect width="100" height="100" fill="#ff0000" fill-opacity="0.5"/></mask>
        <mask id="linear" color-interpolation="linearRGB"><rect width="100" height="100" fill="#808080"/></mask>
        <rect width="100" height="30" fill="#fff" mask="url(#red)"/>
        <rect y="35" width="100" height="30" fill="#fff" mask="url(#alpha)"/>
        <rect y="70" width="100" height="30" fill="#fff" mask="url(#linear)"/>)svg");
    EXPECT_NEAR(c.row(15)[50].a, 0.2125f, 1e-5f);
    EXPECT_NEAR(c.row(50)[50].a, 0.5f, 1e-6f);
    // 128/255 decoded to linear light: 0.2158605.
    EXPECT_NEAR(c.row(85)[50].a, 0.2158605f, 1e-4f);
}

TEST(Mask, DefaultRegionIsTenPercentAroundTheBox) {
    // maskUnits objectBoundingBox: -10%, -10%, 120%, 120% of the box; the
    // content beyond the region is cut.
    const Canvas c = render(R"svg(<mask id="m"><rect width="100" height="100" fill="#fff"/></mask>
        <g mask="url(#m)"><rect x="30" y="30" width="40" height="40" fill="#000"/>
        <rect x="20" y="48" width="60" height="4" fill="#000"/></g>)svg");
    // The group's box is 20..80 x 30..70: its region is 14..86 x 26..74.
    EXPECT_GT(c.row(50)[21].a, 0.99f);
    EXPECT_GT(c.row(50)[79].a, 0.99f);
    const Canvas cut = render(R"svg(<mask id="m"><rect width="100" height="100" fill="#fff"/></mask>
        <rect x="40" y="40" width="20" height="20" fill="#000" mask="url(#m)"/>
        <rect x="0" y="49" width="100" height="2" fill="#000" mask="url(#m)"/>)svg");
    EXPECT_GT(cut.row(50)[5].a, 0.99f) << "the line's own region spans the canvas";
}

TEST(Overflow, ASymbolIsClippedToItsViewport) {
    // The UA style sheet gives symbol overflow: hidden (SVG 2, appendix D);
    // librsvg 2.54 does not clip it.
    const Canvas c =
        render(R"svg(<symbol id="s" viewBox="0 0 10 10"><circle cx="5" cy="5" r="8"/></symbol>
        <use href="#s" x="25" y="25" width="50" height="50"/>
        <symbol id="v" viewBox="0 0 10 10" overflow="visible"><circle cx="5" cy="5" r="8"/></symbol>)svg");
    EXPECT_GT(c.row(50)[26].a, 0.99f);
    EXPECT_EQ(c.row(50)[20].a, 0.0f) << "the circle beyond the viewport is clipped";
    const Canvas v = render(
        R"svg(<symbol id="v" viewBox="0 0 10 10" overflow="visible"><circle cx="5" cy="5" r="8"/></symbol>
        <use href="#v" x="25" y="25" width="50" height="50"/>)svg");
    EXPECT_GT(v.row(50)[20].a, 0.99f);
}

// overflow is not inherited, but `inherit` takes the parent's computed
// value: visible from a group that says nothing, hidden from an svg that
// says nothing (the UA style sheet's), what the parent says otherwise
// (resvg's painting/overflow/inherit-on-marker; before, always hidden).
TEST(Overflow, InheritTakesTheParentsComputedValue) {
    const auto marked = [](const std::string& around) {
        return render(R"svg(<svg )svg" + around + R"svg(><marker id="m" overflow="inherit"
              markerUnits="userSpaceOnUse"><circle r="10"/></marker>
            <path d="M20 50 H80" stroke="#00f" marker-start="url(#m)"/></svg>)svg");
    };
    EXPECT_GT(marked(R"(overflow="visible")").row(50)[12].a, 0.99f);
    EXPECT_EQ(marked("").row(50)[12].a, 0.0f) << "an svg hides by default";
    const Canvas g = render(R"svg(<g><marker id="m" overflow="inherit" markerUnits="userSpaceOnUse">
          <circle r="10"/></marker></g><path d="M20 50 H80" stroke="#00f" marker-start="url(#m)"/>)svg");
    EXPECT_GT(g.row(50)[12].a, 0.99f) << "a group's overflow is visible";
}

TEST(Overflow, TheClipPropertyGivesTheViewportsClipRectangle) {
    // clip: rect(top, right, bottom, left), offsets from the viewport's
    // corner, auto for its edge; it replaces the viewport's bounds as the
    // clip where overflow hides (SVG 1.1, 14.3.2); invalid, it is ignored.
    const Canvas c = render(R"svg(<svg x="20" y="20" width="60" height="60"
          clip="rect(10, auto, 50px, 5)"><rect x="-20" y="-20" width="100" height="100"/></svg>)svg");
    EXPECT_GT(c.row(31)[26].a, 0.99f) << "inside (25..80 x 30..70)";
    EXPECT_EQ(c.row(28)[40].a, 0.0f) << "above its top";
    EXPECT_EQ(c.row(50)[23].a, 0.0f) << "left of its left";
    EXPECT_EQ(c.row(72)[40].a, 0.0f) << "below its bottom";
    EXPECT_GT(c.row(50)[79].a, 0.99f) << "auto: the viewport's right edge";
    EXPECT_EQ(c.row(50)[81].a, 0.0f);
    std::vector<SvgDiagnostic> w;
    const Canvas bad = render(R"svg(<svg x="20" y="20" width="60" height="60" clip="rect(1 2 3)">
          <rect x="-20" y="-20" width="100" height="100"/></svg>)svg",
                              100, &w);
    EXPECT_EQ(w.size(), 1u);
    EXPECT_GT(bad.row(21)[21].a, 0.99f) << "the viewport's bounds";
    EXPECT_EQ(bad.row(19)[21].a, 0.0f);
}

// resvg's a-stroke-013: a horizontal line has no box for a pattern's
// objectBoundingBox units, so it takes the fallback color, or none; a
// pattern in user space units needs no box. Before: none either way.
TEST(Pattern, ObjectBoundingBoxUnitsOnALineTakeTheFallback) {
    const Canvas c = render(R"svg(<pattern id="p" width="0.5" height="0.5">
          <rect width="50" height="50" fill="#f00"/></pattern>
        <pattern id="u" patternUnits="userSpaceOnUse" width="10" height="10">
          <rect width="10" height="10" fill="#00f"/></pattern>
        <line x1="0" y1="10" x2="100" y2="10" stroke="url(#p) #00ff00" stroke-width="4"/>
        <line x1="0" y1="30" x2="100" y2="30" stroke="url(#p)" stroke-width="4"/>
        <line x1="0" y1="50" x2="100" y2="50" stroke="url(#u) #00ff00" stroke-width="4"/>)svg");
    EXPECT_EQ(c.row(10)[50].g, 1.0f);
    EXPECT_EQ(c.row(10)[50].r, 0.0f);
    EXPECT_EQ(c.row(30)[50].a, 0.0f);
    EXPECT_EQ(c.row(50)[50].b, 1.0f) << "the user-space pattern";
}

// A gradient without stops paints as none, its fallback color unused: the
// reference is to a paint server (SVG 1.1, 13.2.4; resvg's a-fill-025 and
// a-fill-034). A reference to nothing takes the fallback. Before: the
// fallback either way.
TEST(Gradient, ZeroStopsPaintNoneAndNotTheFallback) {
    std::vector<SvgDiagnostic> w;
    const Canvas c = render(R"svg(<linearGradient id="none"/>
        <rect width="50" height="100" fill="url(#none) #00ff00" color="#00ff00"/>
        <rect x="50" width="50" height="50" fill="url(#none) currentColor" color="#00ff00"/>
        <rect x="50" y="50" width="50" height="50" fill="url(#missing) #0000ff"/>)svg",
                            100, &w);
    EXPECT_EQ(c.row(50)[25].a, 0.0f);
    EXPECT_EQ(c.row(25)[75].a, 0.0f);
    EXPECT_EQ(c.row(75)[75].b, 1.0f) << "a reference to nothing takes the fallback";
    ASSERT_EQ(w.size(), 2u) << "one warning a gradient";
    EXPECT_NE(w[0].message.find("without stops: none is painted"), std::string::npos)
        << w[0].text();
}

TEST(Pattern, ATileFilledWhollyPaintsAsItsColor) {
    // A tile its content covers wholly is its color everywhere: no seams,
    // whatever the tile's alignment to pixels.
    const Canvas p = render(
        R"svg(<pattern id="p" patternUnits="userSpaceOnUse" x="0.3" y="0.7" width="7.3" height="5.1">
          <rect x="-1" y="-1" width="10" height="10" fill="#3366cc"/></pattern>
        <circle cx="50" cy="50" r="40" fill="url(#p)"/>)svg");
    const Canvas f = render(R"svg(<circle cx="50" cy="50" r="40" fill="#3366cc"/>)svg");
    EXPECT_LT(max_difference(p, f), 1.0f / 255);
}

TEST(Pattern, TilesRepeatFromTheirOrigin) {
    // 10 px tiles from (5, 5), each with its top-left 5 x 5 quarter painted.
    const Canvas c = render(
        R"svg(<pattern id="p" patternUnits="userSpaceOnUse" x="5" y="5" width="10" height="10">
          <rect width="5" height="5" fill="#000"/></pattern>
        <rect width="100" height="100" fill="url(#p)"/>)svg");
    for (int ty = 0; ty < 9; ++ty)
        for (int tx = 0; tx < 9; ++tx) {
            const int x = 5 + 10 * tx, y = 5 + 10 * ty;
            EXPECT_GT(c.row(y + 2)[x + 2].a, 0.99f) << x << "," << y;
            EXPECT_LT(c.row(y + 7)[x + 7].a, 0.01f) << x << "," << y;
        }
}

TEST(Pattern, ARotatedPatternMatchesItsTilesDrawnOneByOne) {
    // The tile is drawn at the device resolution and resampled under the
    // rotation: against the same squares drawn as shapes, only the edges
    // differ, by the resampling's blur (at most one pixel wide).
    const Canvas p =
        render(R"svg(<pattern id="p" patternUnits="userSpaceOnUse" width="20" height="20"
          patternTransform="rotate(30 50 50)"><rect width="10" height="10" fill="#000"/></pattern>
        <rect width="100" height="100" fill="url(#p)"/>)svg");
    std::string squares = R"svg(<g transform="rotate(30 50 50)">)svg";
    for (int i = -6; i < 8; ++i)
        for (int j = -6; j < 8; ++j)
            squares += "<rect x='" + std::to_string(20 * i) + "' y='" + std::to_string(20 * j) +
                       "' width='10' height='10'/>";
    const Canvas d = render(squares + "</g>");
    double sum = 0;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) sum += std::fabs(p.row(y)[x].a - d.row(y)[x].a);
    EXPECT_LT(sum / 1e4, 0.02) << "mean alpha difference";
    EXPECT_LT(max_difference(p, d), 0.5f);
}

TEST(Pattern, AViewBoxIsAlignedInTheTile) {
    // viewBox 0 0 10 10 in a 24 x 16 tile, xMidYMid meet: scaled by 1.6 and
    // centred, (24 - 16) / 2 = 4 from the tile's left. (librsvg 2.54 puts
    // it 6.4 from the left: the offset scaled twice.)
    const Canvas c =
        render(R"svg(<pattern id="p" patternUnits="userSpaceOnUse" width="24" height="16"
          viewBox="0 0 10 10"><rect width="10" height="10" fill="#000"/></pattern>
        <rect width="100" height="100" fill="url(#p)"/>)svg");
    EXPECT_EQ(c.row(8)[3].a, 0.0f);
    EXPECT_GT(c.row(8)[4].a, 0.99f);
    EXPECT_GT(c.row(8)[19].a, 0.99f);
    EXPECT_EQ(c.row(8)[20].a, 0.0f);
    EXPECT_GT(c.row(8)[28].a, 0.99f) << "the next tile";
}

TEST(Pattern, AnHrefToNoPatternIsAProblemAndTheChainEndsThere) {
    // As a gradient's chain (svg/detail/href.h): the pattern keeps its own.
    std::vector<SvgDiagnostic> w;
    const Canvas c = render(
        R"svg(<pattern id="p" href="#nope" patternUnits="userSpaceOnUse" width="10" height="10">
          <rect width="10" height="10" fill="#000"/></pattern>
        <rect width="100" height="100" fill="url(#p)"/>)svg",
        100, &w);
    ASSERT_EQ(w.size(), 1u);
    EXPECT_NE(w[0].message.find("href '#nope' names no pattern"), std::string::npos)
        << w[0].message;
    EXPECT_GT(c.row(50)[50].a, 0.99f);
}

TEST(Pattern, ATinyTileIsItsMeanColor) {
    // Tiles of 1e-6 px: the tile is drawn into one pixel, whose exact-area
    // coverage is the tile's mean (here a quarter covered).
    const Canvas c =
        render(R"svg(<pattern id="p" patternUnits="userSpaceOnUse" width="1e-6" height="1e-6">
          <rect width="5e-7" height="5e-7" fill="#000"/></pattern>
        <rect width="100" height="100" fill="url(#p)"/>)svg");
    EXPECT_NEAR(c.row(50)[50].a, 0.25f, 1e-3f);
}

TEST(Pattern, ATile1e36WideAnd1e30HighPaintsAsItsColor) {
    // Regression (fuzz input tests/fuzz/pending/svg_render/
    // pattern-tile-7.9e34-px-long.svg): the tile's area is finite, but its
    // long side in device pixels was converted to int before the clamp to
    // kMaxTilePixels, undefined behaviour that the sanitizer pass (which
    // aborts on it) catches. Clamped, the tile is 2^20 x 1 pixels, wholly
    // covered, so it paints its color.
    const Canvas c =
        render(R"svg(<pattern id="p" patternUnits="userSpaceOnUse" width="1e36" height="1e-30">
          <rect width="1e36" height="1e-30" fill="#000"/></pattern>
        <rect width="100" height="100" fill="url(#p)"/>)svg");
    EXPECT_NEAR(c.row(50)[50].a, 1.0f, 1e-3f);
    EXPECT_NEAR(c.row(99)[0].a, 1.0f, 1e-3f);
}

TEST(BlendMode, IsolationKeepsTheBackdropOut) {
    // difference of blue over red inside an isolated group ignores the green
    // under the group; without isolation it blends with it where the red
    // does not cover.
    const char* body = R"svg(<rect width="100" height="100" fill="#00ff00"/>
        <g %s><rect width="50" height="100" fill="#ff0000"/>
        <rect width="100" height="100" fill="#0000ff" style="mix-blend-mode:difference"/></g>)svg";
    char iso[512], plain[512];
    std::snprintf(iso, sizeof iso, body, "style=\"isolation:isolate\"");
    std::snprintf(plain, sizeof plain, body, "");
    const Canvas i = render(iso), p = render(plain);
    // Over red: |red - blue| = magenta, either way.
    EXPECT_NEAR(i.row(50)[25].r, 1, 1e-6);
    EXPECT_NEAR(i.row(50)[25].b, 1, 1e-6);
    EXPECT_NEAR(p.row(50)[25].r, 1, 1e-6);
    // Right half: isolated, blue over nothing is blue; else |green - blue| = cyan.
    EXPECT_NEAR(i.row(50)[75].g, 0, 1e-6);
    EXPECT_NEAR(i.row(50)[75].b, 1, 1e-6);
    EXPECT_NEAR(p.row(50)[75].g, 1, 1e-6);
    EXPECT_NEAR(p.row(50)[75].b, 1, 1e-6);
}

// mix-blend-mode and isolation are properties without presentation
// attributes (SVG 2, 6.6): as attributes they do nothing, as browsers and
// librsvg read them (resvg's a-isolation-002; before, both applied).
TEST(BlendMode, MixBlendModeAndIsolationAreNoAttributes) {
    const Canvas c = render(R"svg(<rect width="100" height="100" fill="#00ff00"/>
        <rect width="50" height="50" fill="#ff00ff" mix-blend-mode="multiply"/>
        <g isolation="isolate"><rect y="50" width="50" height="50" fill="#0000ff"
          style="mix-blend-mode:difference"/></g>)svg");
    EXPECT_NEAR(c.row(25)[25].g, 0, 1e-6) << "magenta over green, not multiplied";
    EXPECT_NEAR(c.row(75)[25].g, 1, 1e-6) << "difference with the green: not isolated";
}

TEST(BlendMode, PlusLighterAddsAndFeBlendRefusesIt) {
    // mix-blend-mode: plus-lighter (Compositing 2) sums the premultiplied
    // colors, clamped: red plus half-transparent green is (1, 0.5, 0) at alpha 1.
    // feBlend's mode takes only <blend-mode>s: plus-lighter there is normal.
    const Canvas c = render(R"svg(<rect width="100" height="100" fill="#ff0000"/>
        <rect width="50" height="100" fill="#00ff00" fill-opacity="0.5"
              style="mix-blend-mode:plus-lighter"/>)svg");
    EXPECT_NEAR(c.row(50)[25].r, 1, 1e-6);
    EXPECT_NEAR(c.row(50)[25].g, 0.5, 1e-6);
    EXPECT_NEAR(c.row(50)[25].a, 1, 1e-6);
    EXPECT_NEAR(c.row(50)[75].g, 0, 1e-6);
    const Canvas f = render(R"svg(<filter id="f"><feFlood flood-color="#00ff00" result="g"/>
        <feBlend in="g" in2="SourceGraphic" mode="plus-lighter"/></filter>
        <rect width="100" height="100" fill="#ff0000" filter="url(#f)"/>)svg");
    EXPECT_NEAR(f.row(50)[50].r, 0, 1e-6); // green over red: normal
    EXPECT_NEAR(f.row(50)[50].g, 1, 1e-6);
}

TEST(LayerBudget, OverItAClippedGroupIsNotDrawnAndAnOpaqueOneIsDrawnStraight) {
    // Past the layer budget, what a clip would hide never shows; a group
    // with only opacity is drawn without it.
    const SvgResult doc =
        parse_svg(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="40" height="40">
        <clipPath id="c"><rect width="10" height="10"/></clipPath>
        <rect width="40" height="40" fill="#f00" clip-path="url(#c)"/>
        <g opacity="0.5"><rect y="20" width="40" height="20" fill="#00f"/></g></svg>)svg",
                  "t.svg");
    ASSERT_TRUE(doc.scene) << doc.error;
    Canvas c(40, 40);
    Renderer r;
    r.set_layer_budget(1000); // fewer bytes than any layer here
    r.render(*doc.scene, Affine::identity(), c, RenderOptions{});
    EXPECT_EQ(c.row(5)[5].a, 0.0f) << "the clipped rectangle: not drawn at all";
    EXPECT_EQ(c.row(30)[30].b, 1.0f) << "the group: drawn straight, opaque";
    r.set_layer_budget(kMaxLayerBytes);
    c.reset(40, 40);
    r.render(*doc.scene, Affine::identity(), c, RenderOptions{});
    EXPECT_EQ(c.row(5)[5].r, 1.0f);
    EXPECT_EQ(c.row(15)[15].a, 0.0f);
    EXPECT_NEAR(c.row(30)[30].b, 0.5f, 1e-6f);
}

// Context paints (SVG 2, 13.3): context-fill and context-stroke take the
// context element's paint in its user space and with its box, whatever
// transforms lie between it and the shape painted. Under a use that is the
// use's box, all it draws (WPT's paint-context-004: one grid across two
// rectangles of different heights, moved by the use's x and y).
TEST(ContextPaint, AUsesPaintServerTakesTheUsesBoxAndSpace) {
    const Canvas used = render(R"svg(<pattern id="grid" width="0.125" height="0.125"
          patternContentUnits="objectBoundingBox"><rect width="0.0625" height="0.0625"/></pattern>
        <defs><g id="rects"><rect width="32" height="64" fill="context-fill"/>
          <rect x="32" y="6" width="32" height="58" fill="context-fill"/></g></defs>
        <use x="18" y="18" fill="url(#grid)" href="#rects"/>)svg");
    const Canvas direct = render(R"svg(<pattern id="grid" width="8" height="8" x="18" y="18"
          patternUnits="userSpaceOnUse"><rect width="4" height="4"/></pattern>
        <rect x="18" y="18" width="32" height="64" fill="url(#grid)"/>
        <rect x="50" y="24" width="32" height="58" fill="url(#grid)"/>)svg");
    EXPECT_LT(max_difference(used, direct), 2e-3f);
    EXPECT_GT(used.row(20)[20].a, 0.99f); // the grid's first cell is there
    EXPECT_EQ(used.row(20)[24].a, 0.0f);  // and the gap after it
}

// Measuring a use's box walks its content quietly; the problems it meets
// are told by the walk that draws, once each (regression: a use painted with
// a url() swallowed its content's warnings, and --strict let the file pass).
TEST(ContextPaint, MeasuringAUseLosesNoWarning) {
    const std::string body = R"svg(<linearGradient id="g"><stop/></linearGradient>
        <linearGradient id="bad" x1="zz"><stop/></linearGradient><linearGradient id="none"/>
        <defs><rect id="r" width="10" height="10" fill="url(#none) blue" stroke="url(#bad)"/></defs>
        <use href="#r" fill="url(#g)"/>)svg";
    std::vector<SvgDiagnostic> w;
    render(body, 100, &w);
    ASSERT_EQ(w.size(), 2u);
    EXPECT_NE(w[0].message.find("x1: 'zz' is invalid"), std::string::npos) << w[0].text();
    EXPECT_NE(w[1].message.find("gradient without stops"), std::string::npos) << w[1].text();
}

// A gradient in the use's box stays one gradient across shapes that
// transforms put side by side: black to white over the use's 100 px.
// Before, each shape took it in its own space over a unit square.
TEST(ContextPaint, AUsesGradientSpansWhatTheUseDraws) {
    const Canvas c = render(R"svg(<linearGradient id="g"><stop offset="0" stop-color="black"/>
          <stop offset="1" stop-color="white"/></linearGradient>
        <defs><g id="two"><rect width="50" height="10" fill="context-fill"/>
          <rect width="25" height="5" transform="translate(50 0) scale(2)" fill="context-fill"/>
        </g></defs><use href="#two" y="40" fill="url(#g)"/>)svg");
    for (int x : {5, 30, 49, 50, 75, 95})
        EXPECT_NEAR(c.row(45)[x].r, (float(x) + 0.5f) / 100, 2e-3f) << "x " << x;
}

// In a marker the context element is the marked shape: its gradient, in
// objectBoundingBox units, is the shape's over the shape's box.
TEST(ContextPaint, AMarkersGradientIsTheMarkedShapes) {
    const Canvas c = render(R"svg(<linearGradient id="g"><stop offset="0" stop-color="black"/>
          <stop offset="1" stop-color="white"/></linearGradient>
        <marker id="m" markerWidth="10" markerHeight="10" markerUnits="userSpaceOnUse" refX="5"
          refY="5"><rect width="10" height="10" fill="context-fill"/></marker>
        <polygon points="0,0 100,0 100,20 80,60 0,20" fill="url(#g)" marker-mid="url(#m)"/>)svg");
    for (int x : {76, 80, 84}) // the marker at (80, 60), below the polygon
        EXPECT_NEAR(c.row(62)[x].r, (float(x) + 0.5f) / 100, 2e-3f) << "x " << x;
}

// Layers for clips, masks, blend modes, pattern tiles and filters keep bands (and
// threads) bit-identical to one whole-frame render.
template <class C>
class EffectFormats : public ::testing::Test {};
using Formats = ::testing::Types<Canvas, Canvas8>;
TYPED_TEST_SUITE(EffectFormats, Formats);

TYPED_TEST(EffectFormats, BandsAreBitIdenticalWithEveryLayer) {
    for (const char* file : {"clip_paths.svg", "masks.svg", "patterns.svg", "blend_modes.svg",
                             "overflow_viewports.svg", "filters.svg",
                             // feImage of an element: a float layer under an 8-bit one
                             // (the shared layer count overran the float layers)
                             "filter_primitives.svg"}) {
        const SvgResult doc = read_svg_file(std::string(CASTELJAU_TESTS "/svg/agreement/") + file);
        ASSERT_TRUE(doc.scene) << doc.error;
        // Scaled so that the frame has several bands of 128 rows.
        const double k = 2.7;
        const int w = int(doc.scene->width * k), h = int(doc.scene->height * k);
        TypeParam a(w, h), b(w, h);
        Renderer().render(*doc.scene, Affine::scale(k), a, RenderOptions{});
        BandRenderer bands;
        for (int threads : {1, 3}) {
            b.fill({1, 0, 1, 1});
            bands.render(*doc.scene, Affine::scale(k), b, RenderOptions{}, {0, 0, 0, 0}, threads);
            EXPECT_EQ(testing::differing_rows(a, b), 0) << file << ", " << threads << " threads";
        }
    }
}

} // namespace
} // namespace casteljau
