// CSS values as browsers parse them: colors (CSS Color 4) and lengths (CSS
// Values and Units 3), alone and through the reader's cascade.
#include "casteljau/svg/color.h"
#include "casteljau/svg/reader.h"
#include "casteljau/svg/style.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

void expect_color(const char* text, Rgba want) {
    const auto c = parse_color(text);
    ASSERT_TRUE(c) << text;
    EXPECT_NEAR(c->r, want.r, 1e-6f) << text;
    EXPECT_NEAR(c->g, want.g, 1e-6f) << text;
    EXPECT_NEAR(c->b, want.b, 1e-6f) << text;
    EXPECT_NEAR(c->a, want.a, 1e-6f) << text;
}

TEST(Color, NamesAndHexForms) {
    expect_color("green", {0, 128 / 255.0f, 0, 1});
    expect_color("LightGoldenrodYellow", {250 / 255.0f, 250 / 255.0f, 210 / 255.0f, 1});
    expect_color("yellowgreen", {154 / 255.0f, 205 / 255.0f, 50 / 255.0f, 1});
    expect_color("TRANSPARENT", {0, 0, 0, 0});
    expect_color("#f80", {1, 136 / 255.0f, 0, 1});
    expect_color("#f808", {1, 136 / 255.0f, 0, 136 / 255.0f});
    expect_color("#FF8000", {1, 128 / 255.0f, 0, 1});
    expect_color("#11223344", {17 / 255.0f, 34 / 255.0f, 51 / 255.0f, 68 / 255.0f});
    // SVG 1.1's ICC color after an sRGB one: the sRGB one.
    expect_color("#CD853F icc-color(acmecmyk, 0.11, 0.48, 0.83, 0.00)",
                 {205 / 255.0f, 133 / 255.0f, 63 / 255.0f, 1});
}

TEST(Color, RgbAndHslInTheLegacyAndModernForms) {
    expect_color(" rgb(255, 0, 128) ", {1, 0, 128 / 255.0f, 1});
    expect_color("rgb(100%, 50%, 300%)", {1, 0.5f, 1, 1});
    expect_color("rgb(300, -5, 0)", {1, 0, 0, 1}); // clamped
    expect_color("rgba(0, 0, 255, 0.25)", {0, 0, 1, 0.25f});
    expect_color("rgb(0, 0, 255, 25%)", {0, 0, 1, 0.25f});
    expect_color("RGB(255 0 0)", {1, 0, 0, 1});
    expect_color("rgb(255 0 0 / 50%)", {1, 0, 0, 0.5f});
    expect_color("rgba(255 50% 0/0.5)", {1, 0.5f, 0, 0.5f}); // modern: mixed, no space at /
    expect_color("rgb(none 255 0)", {0, 1, 0, 1});
    expect_color("hsl(0, 100%, 50%)", {1, 0, 0, 1});
    expect_color("hsl(120, 100%, 25%)", {0, 0.5f, 0, 1});
    expect_color("hsla(240, 100%, 50%, 0.5)", {0, 0, 1, 0.5f});
    expect_color("hsl(240deg 100% 50% / 0.5)", {0, 0, 1, 0.5f});
    expect_color("hsl(0.5turn 100% 50%)", {0, 1, 1, 1});
    expect_color("hsl(-120 100 50)", {0, 0, 1, 1}); // modern: numbers for percentages
    expect_color("hsl(400grad 0% 100%)", {1, 1, 1, 1});
    // "#2a2fb05.5": longer than six digits overflowed the digit buffer
    // (fuzz_svg_read, tests/fuzz/regressions/svg_read).
    for (const char* bad : {"",
                            "#12",
                            "#ggg",
                            "#12345",
                            "rgb(1,2)",
                            "rgb(1,2,3",
                            "rgb(1,2 3)",
                            "rgb(1 2 3 4)",
                            "rgb(10%, 20, 30)",
                            "rgb(1,2,3,)",
                            "rgb(none, 0, 0)",
                            "rgb(1 2 / 3 4)",
                            "rgb(1 2 3 /)",
                            "hsl(120, 100, 50%)",
                            "hsl(10%, 1%, 1%)",
                            "notacolor",
                            "ButtonFace",
                            "currentColor",
                            "#2a2fb05.5",
                            "#1234567",
                            "#12345678901234567890",
                            "rgb(1px, 2, 3)"})
        EXPECT_FALSE(parse_color(bad)) << bad;
}

TEST(Color, HwbAndTheLabFamily) {
    // CSS Color 4's own examples and the sRGB primaries' known coordinates.
    const auto near8 = [](const char* text, double r, double g, double b, float a = 1) {
        const auto c = parse_color(text);
        ASSERT_TRUE(c) << text;
        EXPECT_NEAR(c->r * 255, r, 0.6) << text;
        EXPECT_NEAR(c->g * 255, g, 0.6) << text;
        EXPECT_NEAR(c->b * 255, b, 0.6) << text;
        EXPECT_NEAR(c->a, a, 1e-6) << text;
    };
    near8("hwb(120 20% 30%)", 51, 178.5, 51);
    near8("hwb(0 60% 60% / 50%)", 127.5, 127.5, 127.5, 0.5); // past 100%: a gray of the ratio
    near8("lch(52.2345% 72.2 56.2)", 198, 93, 6);            // 9.4's example
    near8("LAB(100 0 0)", 255, 255, 255);
    near8("lab(0% none none)", 0, 0, 0);
    near8("oklab(0.627955 0.224863 0.125846)", 255, 0, 0);             // sRGB red
    near8("oklch(51.975% 0.176858 142.495 / 0.25)", 0, 128, 0, 0.25f); // CSS green
    near8("oklch(45.2% 0.3132 264.05)", 0, 0, 255);
    near8("oklch(100% 0.4 0)", 255, 32.2, 244.2); // out of gamut: R (3.64 linear) clipped
    for (const char* bad : {"lab(50, 40, 59)", "oklch(50% 0.1 1%)", "hwb(120, 20%, 30%)",
                            "lab(50% 40)", "oklab(1 2 3 4)", "lch(50deg 1 1)"})
        EXPECT_FALSE(parse_color(bad)) << bad;
}

TEST(Length, EveryUnitAgainstWhatItIsRelativeTo) {
    LengthContext ctx;
    ctx.font_size = 20;
    ctx.root_font_size = 10;
    ctx.viewport_w = 200;
    ctx.viewport_h = 50;
    const std::pair<const char*, double> cases[] = {
        {"7", 7},       {"7px", 7},     {"1in", 96}, {"2.54cm", 96},   {"25.4mm", 96},
        {"101.6Q", 96}, {"72pt", 96},   {"6pc", 96}, {"2em", 40},      {"2ex", 20},
        {"2ch", 20},    {"2rem", 20},   {"50%", 40}, {"10vw", 20},     {"10vh", 5},
        {"10vmin", 5},  {"10vmax", 20}, {"1PX", 1},  {"+.5e1Em", 100}, {" 3 ", 3}};
    for (const auto& [text, want] : cases) {
        const auto v = parse_length(text, 80, ctx);
        ASSERT_TRUE(v) << text;
        EXPECT_NEAR(*v, want, 1e-9) << text;
    }
    for (const char* bad : {"", "px", "3furlongs", "1e999", "nan", "inf", "1 px", "1e308in", "--1"})
        EXPECT_FALSE(parse_length(bad, 80, ctx)) << bad;
}

const Shape& shape_at(const Scene& s, std::size_t i) {
    return std::get<Shape>(s.root.children.at(i).item);
}

TEST(Length, CalcMinMaxAndClamp) {
    // CSS Values 4, 10 (svg/css_math.h): each leaf resolved by the length
    // rules (em of 16 px, % of 200).
    LengthContext ctx;
    ctx.font_size = 16;
    const auto at = [&](const char* text) { return parse_length(text, 200, ctx); };
    EXPECT_EQ(at("calc(10px + 2em)"), 42.0);
    EXPECT_EQ(at(" calc(50% - 10px) "), 90.0);
    EXPECT_EQ(at("calc(2 * 3px)"), 6.0);
    EXPECT_EQ(at("calc(3px * 2 / 4)"), 1.5);
    EXPECT_EQ(at("calc((1px + 2px) * -3)"), -9.0);
    EXPECT_EQ(at("CALC(1PX + calc(1px))"), 2.0);
    EXPECT_EQ(at("min(10px, 2em, 30%)"), 10.0);
    EXPECT_EQ(at("max(1px, 5%)"), 10.0);
    EXPECT_EQ(at("clamp(1px, 50px, 20px)"), 20.0);
    EXPECT_EQ(at("calc(1 + 2)"), 3.0) << "a number: user units, as in an SVG length";
    std::string deep = "1px";
    for (int i = 0; i < 40; ++i) deep = "calc(" + deep + ")";
    for (const std::string& bad :
         {std::string("calc(10px + 2)"), std::string("calc(1px * 2px)"),
          std::string("calc(1px / 0)"), std::string("calc(1px / 2px)"),
          std::string("calc(10px -5px)"), std::string("calc(10px+5px)"), std::string("calc(1px"),
          std::string("calc()"), std::string("min()"), std::string("clamp(1px, 2px)"),
          std::string("calc(1px) x"), std::string("calc(1qq)"), std::string("calc(1e308px * 10)"),
          deep})
        EXPECT_FALSE(at(bad.c_str())) << bad;
}

TEST(Length, EmAndPercentagesThroughTheCascade) {
    // font-size inherits as a computed length; em in an element's own
    // attributes uses its own font-size, even when set after them (in its
    // style attribute); % of font-size is of the parent's.
    const SvgResult r = parse_svg(R"svg(<svg width="200" height="100" font-size="10">
        <g font-size="20"><rect width="2em" height="1em" stroke="red" stroke-width="0.1em"/></g>
        <rect width="2em" height="1em" style="font-size: 150%"/>
        <rect width="1em" height="1em" font-size="larger"/>
        <rect width="2rem" height="10vh" font-size="xx-large"/>
        <circle r="10%"/></svg>)svg",
                                  "u.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty());
    const Rect a = shape_at(*r.scene, 0).path.bounds();
    EXPECT_NEAR(a.width(), 40, 1e-12);
    EXPECT_NEAR(a.height(), 20, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 0).stroke->geometry.width, 2, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 1).path.bounds().width(), 30, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 2).path.bounds().width(), 12, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 3).path.bounds().width(), 20, 1e-12); // the root's 10
    EXPECT_NEAR(shape_at(*r.scene, 3).path.bounds().height(), 10, 1e-12);
    // r in %: of the normalised diagonal sqrt((200^2 + 100^2) / 2).
    EXPECT_NEAR(shape_at(*r.scene, 4).path.bounds().width(), 2 * 0.1 * std::sqrt(25000.0), 1e-9);
}

TEST(Color, CurrentColorAndFallbacksThroughTheCascade) {
    const SvgResult r = parse_svg(R"svg(<svg width="10" height="10" color="rgb(0 0 255)">
        <g color="red"><rect width="1" height="1" fill="CurrentColor"/></g>
        <rect width="1" height="1" fill="currentColor" color="inherit"/>
        <rect width="1" height="1" fill="hsl(120 100% 50% / 0.5)"/>
        <rect width="1" height="1" fill="url(#missing) #0f0"/></svg>)svg",
                                  "c.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(shape_at(*r.scene, 0).fill->color, (Rgba{1, 0, 0, 1}));
    EXPECT_EQ(shape_at(*r.scene, 1).fill->color, (Rgba{0, 0, 1, 1}));
    EXPECT_EQ(shape_at(*r.scene, 2).fill->color, (Rgba{0, 1, 0, 0.5f}));
    EXPECT_EQ(shape_at(*r.scene, 3).fill->color, (Rgba{0, 1, 0, 1}));
}

TEST(StyleSheet, CascadeOrderInTheReader) {
    // Presentation attribute < sheet < style attribute < sheet !important <
    // style attribute !important; a sheet's font-size is used by em lengths.
    const std::string svg = R"svg(<svg width="100" height="100">
        <style>
          rect { fill: red } .a { fill: lime } .b { fill: blue !important }
          .em { font-size: 20px }
          [broken { fill: black }
        </style>
        <style type="text/x-other">rect { fill: black }</style>
        <rect width="1" height="1" fill="black"/>
        <rect width="1" height="1" class="a" style="fill: navy"/>
        <rect width="1" height="1" class="b" style="fill: navy"/>
        <rect width="1" height="1" class="b" style="fill: teal !important"/>
        <rect width="2em" height="1" class="em"/></svg>)svg";
    const SvgResult r = parse_svg(svg, "c.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_EQ(shape_at(*r.scene, 0).fill->color, (Rgba{1, 0, 0, 1})); // sheet > attribute
    EXPECT_EQ(shape_at(*r.scene, 1).fill->color, (Rgba{0, 0, 128 / 255.0f, 1})); // style > sheet
    EXPECT_EQ(shape_at(*r.scene, 2).fill->color, (Rgba{0, 0, 1, 1})); // !important > style
    EXPECT_EQ(shape_at(*r.scene, 3).fill->color, (Rgba{0, 128 / 255.0f, 128 / 255.0f, 1}));
    EXPECT_NEAR(shape_at(*r.scene, 4).path.bounds().width(), 40, 1e-12);
    // The broken rule: one warning, on the document's line of the rule.
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].line, 5) << r.warnings[0].text();
    SvgOptions strict;
    strict.strict = true;
    EXPECT_FALSE(parse_svg(svg, "c.svg", strict).scene);
    // An at-rule this reader skips is worth a warning, not an error.
    const SvgResult media = parse_svg(
        "<svg width='9' height='9'><style>@media (hover) { rect { fill: red } }</style></svg>",
        "m.svg", strict);
    ASSERT_TRUE(media.scene) << media.error;
    EXPECT_EQ(media.warnings.size(), 1u);
}

} // namespace
} // namespace casteljau
