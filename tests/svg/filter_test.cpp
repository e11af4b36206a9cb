// Filters read from SVG and drawn: regions and units, the filter property's
// functions, errors as the spec has them, where librsvg 2.54 is wrong, and
// hostile values bounded. (Bands bit-identical with filters:
// clip_mask_test.cpp, EffectFormats.)
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "image_files.h"
#include "pixels.h"

#include <gtest/gtest.h>
#include <string>

namespace casteljau {
namespace {

SvgResult parse(const std::string& body, int size) {
    const std::string s = std::to_string(size);
    return parse_svg(R"svg(<svg xmlns="http://www.w3.org/2000/svg" width=")svg" + s +
                         "\" height=\"" + s + "\">" + body + "</svg>",
                     "t.svg");
}

Canvas render(const std::string& body, int size = 100,
              std::vector<SvgDiagnostic>* warnings = nullptr) {
    const SvgResult doc = parse(body, size);
    EXPECT_TRUE(doc.scene) << doc.error;
    if (warnings) *warnings = doc.warnings;
    Canvas c(size, size);
    if (doc.scene) Renderer().render(*doc.scene, Affine::identity(), c, RenderOptions{});
    return c;
}

const Premul& at(const Canvas& c, int x, int y) { return c.row(y)[x]; }

TEST(Filter, AFloodFillsTheDefaultRegion) {
    // objectBoundingBox -10%, -10%, 120%, 120% of a 50 x 50 box at 20, 20:
    // 15 .. 75 on both axes.
    const Canvas c =
        render(R"svg(<filter id="f"><feFlood flood-color="#0000ff" flood-opacity="0.5"/></filter>
        <rect x="20" y="20" width="50" height="50" filter="url(#f)"/>)svg");
    EXPECT_NEAR(at(c, 16, 16).b, 0.5f, 1e-6);
    EXPECT_NEAR(at(c, 74, 74).a, 0.5f, 1e-6);
    EXPECT_EQ(at(c, 14, 40).a, 0.0f);
    EXPECT_EQ(at(c, 76, 40).a, 0.0f);
}

TEST(Filter, UserSpaceRegionsAndPrimitiveSubregions) {
    const Canvas c = render(
        R"svg(<filter id="f" filterUnits="userSpaceOnUse" x="10" y="10" width="80" height="80">
          <feFlood flood-color="red" x="30" width="20"/></filter>
        <g filter="url(#f)"/>)svg");
    EXPECT_EQ(at(c, 40, 50).r, 1.0f) << "an empty group: a user-space filter still draws";
    EXPECT_EQ(at(c, 29, 50).a, 0.0f);
    EXPECT_EQ(at(c, 50, 50).a, 0.0f);
    EXPECT_EQ(at(c, 40, 5).a, 0.0f) << "y and height from the region";
}

TEST(Filter, OffsetMovesTheElement) {
    const Canvas c = render(R"svg(<filter id="f"><feOffset dx="10" dy="5"/></filter>
        <rect x="20" y="20" width="40" height="40" fill="#000" filter="url(#f)"/>)svg");
    EXPECT_EQ(at(c, 25, 22).a, 0.0f);
    EXPECT_EQ(at(c, 35, 30).a, 1.0f);
    EXPECT_EQ(at(c, 63, 62).a, 1.0f) << "within the region: 60 + 10% of 40";
}

TEST(Filter, AReferenceToNoFilterIsNotDrawn) {
    std::vector<SvgDiagnostic> w;
    const Canvas c = render(R"svg(<rect width="50" height="50" filter="url(#none)"/>
        <linearGradient id="g"/><rect x="50" width="50" height="50" filter="url(#g)"/>)svg",
                            100, &w);
    EXPECT_EQ(at(c, 25, 25).a, 0.0f);
    EXPECT_EQ(at(c, 75, 25).a, 0.0f);
    EXPECT_EQ(w.size(), 2u);
}

TEST(Filter, AnEmptyFilterOrBoxIsNotDrawn) {
    std::vector<SvgDiagnostic> w;
    const Canvas c = render(R"svg(<filter id="e"/><filter id="o"><feOffset/></filter>
        <rect width="50" height="50" filter="url(#e)"/>
        <line x1="0" y1="80" x2="100" y2="80" stroke="#000" stroke-width="4" filter="url(#o)"/>)svg",
                            100, &w);
    EXPECT_EQ(at(c, 25, 25).a, 0.0f) << "no primitives";
    EXPECT_EQ(at(c, 50, 80).a, 0.0f) << "objectBoundingBox on a box with no height";
    // A primitive subregion of no area disables the element, even where a
    // later primitive would draw without it.
    const Canvas z =
        render(R"svg(<filter id="z"><feFlood width="0"/><feOffset in="SourceGraphic"/></filter>
        <rect width="50" height="50" filter="url(#z)"/>)svg");
    EXPECT_EQ(at(z, 25, 25).a, 0.0f);
}

TEST(Filter, AnInvalidFilterValueIsIgnored) {
    std::vector<SvgDiagnostic> w;
    const Canvas c = render(R"svg(<rect width="50" height="50" filter="blur(-2px)"/>)svg", 100, &w);
    EXPECT_EQ(at(c, 25, 25).a, 1.0f);
    EXPECT_EQ(w.size(), 1u);
}

TEST(FilterFunctions, ColorFunctionsOnRed) {
    const auto pixel = [](const char* f) {
        return at(
            render(std::string(R"svg(<rect width="100" height="100" fill="#ff0000" filter=")svg") +
                   f + "\"/>"),
            50, 50);
    };
    EXPECT_NEAR(pixel("opacity(0.5)").a, 0.5f, 1e-6);
    EXPECT_NEAR(pixel("invert(1)").g, 1.0f, 1e-6);
    EXPECT_NEAR(pixel("invert(1)").r, 0.0f, 1e-6);
    EXPECT_NEAR(pixel("grayscale(100%)").g, 0.2126f, 1e-5) << "in sRGB, as CSS filters are";
    EXPECT_NEAR(pixel("brightness(0.5)").r, 0.5f, 1e-6);
    EXPECT_NEAR(pixel("sepia(1)").g, 0.349f, 1e-5);
    EXPECT_NEAR(pixel("hue-rotate(0deg) saturate(1)").r, 1.0f, 1e-5);
    EXPECT_NEAR(pixel("contrast(2)").r, 1.0f, 1e-6);
}

TEST(FilterFunctions, DropShadowAndBlurReachOutside) {
    const Canvas c = render(R"svg(<rect x="20" y="20" width="30" height="30" fill="#fff"
        filter="drop-shadow(20px 20px 0 #0000ff)"/>)svg");
    EXPECT_EQ(at(c, 30, 30).r, 1.0f) << "the element";
    EXPECT_EQ(at(c, 65, 65).b, 1.0f) << "its shadow, outside the element's box";
    EXPECT_EQ(at(c, 65, 65).r, 0.0f);
    const Canvas b =
        render(R"svg(<rect x="40" y="40" width="20" height="20" filter="blur(4px)"/>)svg");
    EXPECT_GT(at(b, 37, 50).a, 0.05f) << "spread beyond the rectangle";
    EXPECT_LT(at(b, 50, 50).a, 1.0f);
    double sum = 0;
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) sum += at(b, x, y).a;
    EXPECT_NEAR(sum, 400, 2) << "a blur keeps the total alpha";
}

TEST(Filter, FeImageDrawsAnElement) {
    const Canvas c =
        render(R"svg(<defs><rect id="r" x="60" y="60" width="20" height="20" fill="#00ff00"/></defs>
        <filter id="f" filterUnits="userSpaceOnUse" x="0" y="0" width="100" height="100">
          <feImage href="#r"/></filter>
        <rect width="10" height="10" filter="url(#f)"/>)svg");
    EXPECT_EQ(at(c, 70, 70).g, 1.0f);
    EXPECT_EQ(at(c, 5, 5).a, 0.0f) << "the source is replaced";
}

TEST(Filter, LinearRgbIsTheDefaultSpace) {
    // Half-transparent white merged over black: 0.5 in linear light, which
    // is 0.735 in sRGB; in sRGB it stays 0.5.
    const auto gray = [](const char* space) {
        return at(render(std::string(R"svg(<filter id="f" color-interpolation-filters=")svg") +
                         space +
                         R"svg("><feFlood flood-color="#000" result="b"/>
                           <feFlood flood-color="#fff" flood-opacity="0.5"/>
                           <feMerge><feMergeNode in="b"/><feMergeNode/></feMerge></filter>
                         <rect width="100" height="100" filter="url(#f)"/>)svg"),
                  50, 50)
            .r;
    };
    EXPECT_NEAR(gray("linearRGB"), 0.7354f, 2e-3);
    EXPECT_NEAR(gray("sRGB"), 0.5f, 1e-4);
}

TEST(Filter, LightingColorIsConvertedToTheFiltersSpace) {
    // A flat surface lit straight from above gives kd * lighting-color; in
    // linearRGB the color goes to linear light and back, so #808080 comes
    // out as #808080 (librsvg 2.54 lights with the sRGB values in linear
    // light instead, and gets #bcbcbc).
    const Canvas c = render(R"svg(<filter id="f" x="0" y="0" width="1" height="1">
          <feFlood flood-color="#000"/>
          <feDiffuseLighting lighting-color="#808080"><feDistantLight elevation="90"/></feDiffuseLighting>
        </filter><rect width="100" height="100" filter="url(#f)"/>)svg");
    EXPECT_NEAR(at(c, 50, 50).r, 128 / 255.0f, 2e-4);
    EXPECT_EQ(at(c, 50, 50).a, 1.0f);
}

TEST(Filter, SmallDeviationsBlurByTheGaussianItself) {
    // stdDeviation 1 spreads an edge as the Gaussian of deviation 1 does:
    // 0.31 and 0.69 of the way at the pixels either side (librsvg 2.54
    // blurs by about half that: 0.13 and 0.87).
    const Canvas c = render(R"svg(<filter id="b" color-interpolation-filters="sRGB">
        <feGaussianBlur stdDeviation="1"/></filter>
        <rect x="20" y="10" width="40" height="80" filter="url(#b)"/>)svg");
    EXPECT_NEAR(at(c, 19, 50).a, 0.3085f, 0.01);
    EXPECT_NEAR(at(c, 20, 50).a, 0.6915f, 0.01);
}

TEST(Filter, FillPaintAndStrokePaintAreThePaintsOverTheRegion) {
    const Canvas c = render(
        R"svg(<filter id="f" filterUnits="userSpaceOnUse" x="0" y="0" width="100" height="100">
          <feOffset in="StrokePaint" x="50" width="50" result="s"/>
          <feMerge><feMergeNode in="FillPaint"/><feMergeNode in="s"/></feMerge></filter>
        <rect x="40" y="40" width="20" height="20" fill="#00ff00" stroke="#0000ff" filter="url(#f)"/>)svg");
    EXPECT_EQ(at(c, 5, 5).g, 1.0f) << "the fill's paint, all over the region";
    EXPECT_EQ(at(c, 75, 5).b, 1.0f) << "the stroke's, over its subregion";
    EXPECT_EQ(at(c, 75, 95).b, 1.0f);
}

TEST(Filter, FeDropShadowIsItsEquivalentGraph) {
    // Filter Effects 1, 15.13: blur of the alpha, offset, flood, in, merged
    // under the source. (librsvg 2.54 does not draw feDropShadow.)
    const Canvas shadow = render(R"svg(<filter id="f"><feDropShadow dx="4" dy="6" stdDeviation="3"
          flood-color="#203060" flood-opacity="0.7"/></filter>
        <circle cx="45" cy="45" r="25" fill="#e0a030" filter="url(#f)"/>)svg");
    const Canvas graph = render(R"svg(<filter id="f">
          <feGaussianBlur in="SourceAlpha" stdDeviation="3"/><feOffset dx="4" dy="6" result="o"/>
          <feFlood flood-color="#203060" flood-opacity="0.7"/><feComposite in2="o" operator="in"/>
          <feMerge><feMergeNode/><feMergeNode in="SourceGraphic"/></feMerge></filter>
        <circle cx="45" cy="45" r="25" fill="#e0a030" filter="url(#f)"/>)svg");
    EXPECT_LT(testing::max_difference(shadow, graph), 2e-4f);
    EXPECT_GT(at(shadow, 71, 56).a, 0.3f) << "the shadow shows beyond the circle";
}

TEST(Filter, IgnoredInClipPathsDrawnInMasks) {
    // A clip path is its children's geometry: their filters do not count;
    // a mask's content is drawn, filters and all.
    const Canvas c = render(R"svg(<filter id="away"><feOffset dx="100"/></filter>
        <clipPath id="c"><rect width="50" height="100" filter="url(#away)"/></clipPath>
        <mask id="m" maskUnits="userSpaceOnUse" x="0" y="0" width="100" height="100">
          <rect x="50" width="50" height="100" fill="#fff" filter="url(#away)"/></mask>
        <rect width="100" height="50" fill="#000" clip-path="url(#c)"/>
        <rect y="50" width="100" height="50" fill="#000" mask="url(#m)"/>)svg");
    EXPECT_EQ(at(c, 25, 25).a, 1.0f) << "clipped to the unmoved rectangle";
    EXPECT_EQ(at(c, 75, 75).a, 0.0f) << "the mask's rectangle moved out of the mask";
}

TEST(Filter, OnAnImage) {
    // The image's pixels go through the filter: red becomes green.
    const std::string inner = "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
                              "<rect width='10' height='10' fill='#f00'/></svg>";
    const Canvas c = render(
        "<filter id='f' color-interpolation-filters='sRGB'><feColorMatrix type='matrix' "
        "values='0 0 0 0 0  1 0 0 0 0  0 0 0 0 0  0 0 0 1 0'/></filter>"
        "<image x='10' y='10' width='50' height='50' filter='url(#f)' href='data:image/svg+xml," +
        testing::percent_encoded(inner) + "'/>");
    EXPECT_EQ(at(c, 30, 30).g, 1.0f);
    EXPECT_EQ(at(c, 30, 30).r, 0.0f);
    EXPECT_EQ(at(c, 5, 5).a, 0.0f);
}

TEST(Filter, FeImageOfAFileFillsItsSubregion) {
    // Without x, y, width, height, the subregion is the filter region, and
    // the image is fitted into it (preserveAspectRatio none: stretched).
    const std::string inner = "<svg xmlns='http://www.w3.org/2000/svg' width='10' height='10'>"
                              "<rect width='10' height='10' fill='#00f'/></svg>";
    const Canvas c = render("<filter id='f' filterUnits='userSpaceOnUse' x='20' y='20' "
                            "width='60' height='30'><feImage preserveAspectRatio='none' "
                            "href='data:image/svg+xml," +
                            testing::percent_encoded(inner) +
                            "'/></filter><rect width='5' height='5' filter='url(#f)'/>");
    EXPECT_EQ(at(c, 21, 21).b, 1.0f);
    EXPECT_EQ(at(c, 78, 48).b, 1.0f);
    EXPECT_EQ(at(c, 50, 55).a, 0.0f);
    EXPECT_EQ(at(c, 2, 2).a, 0.0f) << "the source is not drawn";
}

TEST(Filter, RotatedSubregionsAreParallelograms) {
    // Under a rotation the subregion is the rotated square, not its box: a
    // red flood over the subregion stays under a green square one unit larger.
    const Canvas c = render(
        R"svg(<filter id="f" filterUnits="userSpaceOnUse" x="0" y="0" width="200" height="200">
          <feFlood flood-color="red" x="70" y="70" width="60" height="60"/></filter>
        <g transform="rotate(45 100 100)">
          <rect x="70" y="70" width="60" height="60" filter="url(#f)"/>
          <rect x="69" y="69" width="62" height="62" fill="#00ff00"/></g>)svg",
        200);
    for (int y = 0; y < 200; ++y)
        for (int x = 0; x < 200; ++x) {
            const Premul p = at(c, x, y);
            ASSERT_LT(p.r, 0.01f) << "red at " << x << "," << y;
        }
    EXPECT_EQ(at(c, 100, 100).g, 1.0f);
}

TEST(Filter, AHugeRegionIsCutToTheFrameGrownByTheReach) {
    // A region of 2e9 units: only the frame and what the offset pulls in
    // are drawn, and the rectangle moved in from outside the frame shows.
    const Canvas c = render(
        R"svg(<filter id="f" filterUnits="userSpaceOnUse" x="-1e9" y="-1e9" width="2e9" height="2e9">
          <feOffset dx="10"/></filter>
        <rect x="-20" y="40" width="25" height="20" filter="url(#f)"/>)svg");
    EXPECT_EQ(at(c, 2, 50).a, 1.0f) << "from x = -8 to 15";
    EXPECT_EQ(at(c, 14, 50).a, 1.0f);
    EXPECT_EQ(at(c, 15, 50).a, 0.0f);
    // Hostile values are bounded (their time: tests/bad_input): a kernel
    // over the limit is a transparent primitive, an offset of 1e300 moves
    // everything out.
    const Canvas k = render(R"svg(<filter id="f"><feConvolveMatrix order="1000" kernelMatrix="1"/>
        </filter><rect width="100" height="100" filter="url(#f)"/>
        <filter id="o"><feOffset dx="1e300"/></filter>
        <rect width="100" height="100" fill="#f00" filter="url(#o)"/>)svg");
    EXPECT_EQ(at(k, 50, 50).a, 0.0f);
}

TEST(Filter, ParametersOfInfiniteFloatGiveValidPixels) {
    // 1e300 is a finite number to the reader and infinite in float: times a
    // transparent pixel's 0 it is NaN, which must never reach a pixel (the
    // fuzzer's nan_from_an_infinite_color_matrix).
    const Canvas c = render(R"svg(<filter id="f">
          <feColorMatrix values="1e300 0 0 0 0  0 1 0 0 0  0 0 1 0 0  0 0 0 1e300 0"/>
          <feComponentTransfer><feFuncG type="gamma" exponent="1e300" amplitude="1e300"/></feComponentTransfer>
          <feComposite in2="SourceGraphic" operator="arithmetic" k1="1e300" k2="-1e300" k4="1e300"/>
        </filter><circle cx="50" cy="50" r="30" fill="#808080" filter="url(#f)"/>)svg");
    for (int y = 0; y < 100; ++y)
        for (int x = 0; x < 100; ++x) {
            const Premul p = at(c, x, y);
            ASSERT_TRUE(p.a >= 0 && p.a <= 1 && p.r >= 0 && p.r <= p.a && p.g >= 0 && p.g <= p.a &&
                        p.b >= 0 && p.b <= p.a)
                << x << "," << y;
        }
}

} // namespace
} // namespace casteljau
