// @media size features (svg/media_query.h) against the viewport the picture
// is drawn at, and the reader answering them for the size a front end asks
// for (SvgOptions::media_size). Types, conditions and the preference
// features: css_test.cpp.
#include "casteljau/svg/media_query.h"
#include "casteljau/svg/reader.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(MediaQuery, SizeFeaturesAnswerTheViewport) {
    MediaContext m;
    m.width = 48, m.height = 32; // landscape, 3:2
    for (const char* yes : {"(width: 48px)",
                            "(min-width: 48px)",
                            "(max-width: 3em)",
                            "(width)",
                            "(height: 32px)",
                            "(max-height: 0.5in)",
                            "(min-height: 24pt)",
                            "(aspect-ratio: 3/2)",
                            "(min-aspect-ratio: 1)",
                            "(max-aspect-ratio: 16 / 9)",
                            "(orientation: landscape)",
                            "(device-width: 48px)",
                            "(width >= 48px)",
                            "(width < 49px)",
                            "(40px < width <= 48px)",
                            "(32px = height)",
                            "(1 < aspect-ratio)",
                            "screen and (max-width: 64px)",
                            "(max-width: 16px), (min-width: 17px)",
                            "not (max-width: 47px)"})
        EXPECT_TRUE(media_matches(yes, m, nullptr)) << yes;
    for (const char* no :
         {"(width: 47px)", "(min-width: 49px)", "(max-width: 1cm)", "(orientation: portrait)",
          "(width > 48px)", "(48px < width)", "(10px < width < 20px)", "(min-aspect-ratio: 2)",
          "(height >= 33px)", "print and (width)"})
        EXPECT_FALSE(media_matches(no, m, nullptr)) << no;
    // A square is portrait (Media Queries 4, 4.4: height >= width).
    EXPECT_TRUE(media_matches("(orientation: portrait)", MediaContext{false, 16, 16}, nullptr));
    // Malformed values and sizes the context lacks are unknown: false, and named.
    std::string unknown;
    EXPECT_FALSE(media_matches("(width: wide)", m, &unknown));
    EXPECT_EQ(unknown, "(width: wide)");
    EXPECT_FALSE(media_matches("(min-width: 10px)", MediaContext{}, &unknown));
    EXPECT_EQ(unknown, "(min-width: 10px)");
    EXPECT_FALSE(media_matches("(resolution: 2dppx)", m, &unknown));
    EXPECT_EQ(unknown, "(resolution: 2dppx)");
}

const Shape* first_shape(const Group& g) {
    for (const Node& n : g.children) {
        if (const Shape* s = std::get_if<Shape>(&n.item)) return s;
        if (const Shape* s = first_shape(std::get<Group>(n.item))) return s;
    }
    return nullptr;
}

// The fill of the document's one rect, as its sheet chose it.
Rgba fill_of(const std::string& svg, SvgOptions o, std::size_t* warnings = nullptr) {
    const SvgResult r = parse_svg(svg, "m.svg", o);
    EXPECT_TRUE(r.scene) << r.error;
    if (warnings) *warnings = r.warnings.size();
    const Shape* s = r.scene ? first_shape(r.scene->root) : nullptr;
    EXPECT_TRUE(s && s->fill);
    return s && s->fill ? s->fill->color : Rgba{};
}

TEST(MediaQuery, TheReaderAnswersForTheSizeTheFrontEndAsksFor) {
    const std::string icon =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="2in" height="1in" viewBox="0 0 2 1">
        <style>rect { fill: red } @media (max-width: 64px) { rect { fill: blue } }
        @media (min-width: 65px) and (aspect-ratio: 2/1) { rect { fill: lime } }</style>
        <rect width="2" height="1"/></svg>)svg";
    SvgOptions o;
    EXPECT_EQ(fill_of(icon, o), (Rgba{0, 1, 0, 1})); // its own size: 192 x 96 px
    o.media_size.width = 64;
    EXPECT_EQ(fill_of(icon, o), (Rgba{0, 0, 1, 1}));
    o.media_size = {0, 40, 0}; // 80 x 40
    EXPECT_EQ(fill_of(icon, o), (Rgba{0, 1, 0, 1}));
    o.media_size = {0, 0, 0.25}; // 48 x 24
    EXPECT_EQ(fill_of(icon, o), (Rgba{0, 0, 1, 1}));
    // A percentage of no containing block is of 100 px (the size the
    // picture is then drawn at): 50 x 96 px.
    std::string percent = icon;
    percent.replace(percent.find("width=\"2in\""), 11, "width=\"50%\"");
    percent.replace(percent.find(" viewBox=\"0 0 2 1\""), 18, "");
    std::size_t warnings = 1;
    EXPECT_EQ(fill_of(percent, SvgOptions{}, &warnings), (Rgba{0, 0, 1, 1}));
    EXPECT_EQ(warnings, 0u);
}

// An SVG image's queries answer for its own size, not for the size asked of
// the document that draws it.
TEST(MediaQuery, AnSvgImageAnswersForItsOwnSize) {
    const std::string svg =
        R"svg(<svg xmlns="http://www.w3.org/2000/svg" width="100" height="100">)svg"
        R"svg(<image width="100" height="100" href="data:image/svg+xml,%3Csvg )svg"
        R"svg(xmlns='http://www.w3.org/2000/svg' width='100' height='100'%3E%3Cstyle%3E)svg"
        R"svg(rect { fill: red } @media (max-width: 50px) { rect { fill: blue } })svg"
        R"svg(%3C/style%3E%3Crect width='100' height='100'/%3E%3C/svg%3E"/></svg>)svg";
    SvgOptions o;
    o.media_size.width = 10;
    EXPECT_EQ(fill_of(svg, o), (Rgba{1, 0, 0, 1}));
}

} // namespace
} // namespace casteljau
