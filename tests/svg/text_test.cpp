// SVG text as the reader reads it (svg/text.cpp): which characters a text
// draws, where and in what paint. SVG 2, chapter 11 (simple text, the x, y,
// dx, dy and rotate lists, 11.8.3; white space and xml:space, with CSS Text
// 3's white-space; fill and stroke, a gradient's objectBoundingBox); SVG
// 1.1, 10.5 (tspan) and 10.6 (tref); display, visibility and conditional
// processing on a tspan; the reader's limit on characters. Layout (anchors,
// spacing, baselines, textPath, decorations, vertical text, bidi) is
// text_layout_test.cpp's. Expectations are computed from the text library
// itself (text/layout.h: text_to_path, text_advance) and the fonts' metrics,
// never from pixels. The fonts are the packages the tests pin (DejaVu and
// Noto, in a database of their own: text_test_support.h).
#include "text_test_support.h"

#include <cmath>
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace casteljau::svg_text_test {
namespace {

// --- 1. Simple text ----------------------------------------------------------

TEST(Text, SimpleTextIsTheLibrarysLineOnItsBaseline) {
    const TextStyle s = style(40);
    const SvgResult r = read(text(R"(x="20" y="100" font-size="40")", "Hello"));
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_TRUE(r.warnings.empty()) << r.warnings[0].text();
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    ASSERT_TRUE(sh[0]->fill);
    EXPECT_EQ(sh[0]->fill->color, (Rgba{0, 0, 0, 1})) << "fill's initial value is black";
    const Rect b = sh[0]->path.bounds();
    const Path want = text_to_path(fonts(), "Hello", s, {20, 100});
    expect_rect(b, want.bounds(), 1e-9, "the library's line at (20, 100)");
    EXPECT_EQ(sh[0]->path.subpaths().size(), want.subpaths().size());
    // The ink starts after the first glyph's side bearing, under 0.2 em.
    EXPECT_GE(b.x0, 20.0) << str(b);
    EXPECT_LT(b.x0 - 20, 0.2 * 40) << str(b);

    // 'H' stands on the baseline, as tall as the font's cap height (Noto
    // Sans has one in its OS/2 table; DejaVu Sans's table is too old to).
    const Rect h = bounds_of(text(R"(x="20" y="100" font-size="40")", "H"));
    EXPECT_NEAR(h.y1, 100, 0.01) << str(h);
    const SfntValues noto = read_sfnt(kNotoFile);
    ASSERT_GT(noto.cap_height, 0);
    const Rect n =
        bounds_of(R"(<text font-family="Noto Sans" x="20" y="100" font-size="40">H</text>)");
    EXPECT_NEAR(n.y1, 100, 0.01) << str(n);
    EXPECT_NEAR(n.y0, 100 - noto.cap_height * 40 / noto.units_per_em, 0.01) << str(n);
    EXPECT_NEAR(metrics("Noto Sans").cap_height, noto.cap_height, 1e-9);
}

TEST(Text, TheNextChunkStartsAfterTheAdvance) {
    // A tspan without x continues where the text before it ends: its 'H'
    // starts at x + the advance of "Hello" + H's left side bearing.
    const TextStyle s = style(40);
    const SvgResult r =
        read(text(R"(x="20" y="100" font-size="40")", R"(Hello<tspan fill="blue">H</tspan>)"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 2u);
    EXPECT_EQ(sh[1]->fill->color, (Rgba{0, 0, 1, 1}));
    const double want = 20 + advance("Hello", s) + left_bearing("H", s);
    EXPECT_NEAR(sh[1]->path.bounds().x0, want, 1e-9) << "advance of Hello " << advance("Hello", s);
    // One line: the whole is the library's "HelloH".
    expect_rect(bounds(sh), ink("HelloH", s, {20, 100}), 1e-9, "HelloH");
}

TEST(Text, TheTransformIsTheShapesAndThePathStaysInUserSpace) {
    const SvgResult r = read(
        text(R"a(x="20" y="100" font-size="40" transform="translate(5 7) scale(2)")a", "Hello"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    const Affine m = sh[0]->transform;
    EXPECT_EQ(m.a, 2);
    EXPECT_EQ(m.d, 2);
    EXPECT_EQ(m.e, 5);
    EXPECT_EQ(m.f, 7);
    expect_rect(sh[0]->path.bounds(), ink("Hello", style(40), {20, 100}), 1e-9, "user space");
}

TEST(Text, FontSizeScalesTheGlyphs) {
    const Rect small = bounds_of(text(R"(x="0" y="100" font-size="20")", "Hello"));
    const Rect big = bounds_of(text(R"(x="0" y="100" font-size="40")", "Hello"));
    EXPECT_NEAR(big.width(), 2 * small.width(), 1e-9);
    EXPECT_NEAR(big.height(), 2 * small.height(), 1e-9);
}

// --- 2. x, y, dx, dy and rotate lists ----------------------------------------

TEST(TextPositions, EachValueOfXAndYPlacesItsCharacter) {
    const TextStyle s = style(20);
    const SvgResult r =
        read(text(R"(x="10 50 90" y="100 120 140" font-size="20")", each({"H", "H", "H", "H"})));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 4u);
    const Rect h = ink("H", s);
    expect_rect(sh[0]->path.bounds(), moved(h, 10, 100), 1e-9, "first at (10, 100)");
    expect_rect(sh[1]->path.bounds(), moved(h, 50, 120), 1e-9, "second at (50, 120)");
    expect_rect(sh[2]->path.bounds(), moved(h, 90, 140), 1e-9, "third at (90, 140)");
    // The lists are shorter than the text: the fourth follows the third.
    expect_rect(sh[3]->path.bounds(), moved(h, 90 + advance("H", s), 140), 1e-9, "fourth");
}

TEST(TextPositions, LengthsInEmAndPercentages) {
    // em of the element's font size; percentages of the viewport (400 x 200).
    const TextStyle s = style(20);
    expect_rect(bounds_of(text(R"(x="2em" y="50%" font-size="20")", "H")), ink("H", s, {40, 100}),
                1e-9, "2em, 50%");
    expect_rect(bounds_of(text(R"(x="10%" y="10" dx="1em" dy="1em" font-size="20")", "H")),
                ink("H", s, {60, 30}), 1e-9, "10% + 1em, 10 + 1em");
}

TEST(TextPositions, DxAndDyAreCumulative) {
    const std::string chars = each({"A", "B", "C"});
    const SvgResult plain = read(text(R"(x="10" y="100" font-size="20")", chars));
    const SvgResult shifted =
        read(text(R"(x="10" y="100" font-size="20" dx="0 5 5" dy="1 2 3")", chars));
    ASSERT_TRUE(plain.scene && shifted.scene);
    const auto p = shapes(plain), q = shapes(shifted);
    ASSERT_EQ(p.size(), 3u);
    ASSERT_EQ(q.size(), 3u);
    expect_rect(q[0]->path.bounds(), moved(p[0]->path.bounds(), 0, 1), 1e-9, "A: dy 1");
    expect_rect(q[1]->path.bounds(), moved(p[1]->path.bounds(), 5, 3), 1e-9, "B: dx 5, dy 1+2");
    expect_rect(q[2]->path.bounds(), moved(p[2]->path.bounds(), 10, 6), 1e-9, "C: 5+5, 1+2+3");
}

TEST(TextPositions, ATspansListOverridesItsParentsForItsCharactersOnly) {
    // The tspan's x has one value: its first character (the text's second)
    // goes to 50; its second keeps the text's value for index 2 (SVG 2,
    // 11.8.3 "resolve character positioning": descendants win where they
    // have a value).
    const TextStyle s = style(20);
    const SvgResult r = read(
        text(R"(x="10 100 200 300" y="100" font-size="20")",
             "<tspan>H</tspan><tspan x=\"50\">" + each({"H", "H"}) + "</tspan><tspan>H</tspan>"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 4u);
    const Rect h = ink("H", s);
    const double want[] = {10, 50, 200, 300};
    for (int i = 0; i < 4; ++i)
        expect_rect(sh[std::size_t(i)]->path.bounds(), moved(h, want[i], 100), 1e-9,
                    "character " + std::to_string(i));
}

TEST(TextPositions, AShortRotateListRepeatsItsLastValue) {
    // rotate="0 90": the second and third glyphs both turn 90 degrees about
    // their own origins on the baseline; the advance is unchanged.
    const TextStyle s = style(20);
    const SvgResult r =
        read(text(R"(x="50" y="100" font-size="20" rotate="0 90")", each({"H", "H", "H"})));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 3u);
    const Rect h = ink("H", s);
    const double adv = advance("H", s);
    expect_rect(sh[0]->path.bounds(), moved(h, 50, 100), 1e-9, "unrotated");
    // Rotating by 90 degrees (y down) maps (x, y) to (-y, x).
    const Rect turned{-h.y1, h.x0, -h.y0, h.x1};
    expect_rect(sh[1]->path.bounds(), moved(turned, 50 + adv, 100), 1e-9, "second, 90");
    expect_rect(sh[2]->path.bounds(), moved(turned, 50 + 2 * adv, 100), 1e-9, "third, repeated");
}

// KNOWN BUG (see the report): svg/text.cpp's rotate_at takes the value of
// the nearest list that still has one for the index before the last value
// of the innermost list: a tspan's short rotate list gives way to its
// parent's longer one. SVG 1.1, 10.5 (tspan's rotate) and SVG 2, 11.8.3
// ("resolve glyph rotations"; usvg's resolve_rotate_list likewise): the
// characters past the end of an element's own list take its last value.
TEST(TextPositions, ATspansShortRotateListRepeatsItsOwnLastValue) {
    const TextStyle s = style(20);
    const SvgResult r = read(text(R"(x="50" y="100" font-size="20" rotate="0 0 0 0")",
                                  R"(<tspan>H</tspan><tspan rotate="90">)" + each({"H", "H"}) +
                                      "</tspan><tspan>H</tspan>"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 4u);
    const Rect h = ink("H", s);
    const Rect turned{-h.y1, h.x0, -h.y0, h.x1};
    const double adv = advance("H", s);
    expect_rect(sh[1]->path.bounds(), moved(turned, 50 + adv, 100), 1e-9, "the tspan's 90");
    expect_rect(sh[2]->path.bounds(), moved(turned, 50 + 2 * adv, 100), 1e-9,
                "the tspan's last value, not its parent's 0");
    expect_rect(sh[3]->path.bounds(), moved(h, 50 + 3 * adv, 100), 1e-9, "the text's 0 again");
}

// --- 3. White space ----------------------------------------------------------

TEST(TextWhiteSpace, SpacesCollapseAndTrim) {
    const Rect want = bounds_of(text(R"(x="10" y="100" font-size="20")", "a b"));
    expect_rect(bounds_of(text(R"(x="10" y="100" font-size="20")", " a   b ")), want, 1e-9,
                "collapsed and trimmed");
    expect_rect(bounds_of(text(R"(x="10" y="100" font-size="20")", "\n\ta\n \t b\n")), want, 1e-9,
                "tabs and line breaks are spaces");
}

TEST(TextWhiteSpace, PreserveKeepsEverySpace) {
    const TextStyle s = style(20);
    const Rect pre =
        bounds_of(text(R"(x="10" y="100" font-size="20" xml:space="preserve")", " a   b "));
    expect_rect(pre, ink(" a   b ", s, {10, 100}), 1e-9, "every space kept");
    const Rect collapsed = bounds_of(text(R"(x="10" y="100" font-size="20")", " a   b "));
    EXPECT_GT(pre.width(), collapsed.width() + advance(" ", s)) << "two more spaces inside";
    EXPECT_NEAR(pre.x0, collapsed.x0 + advance(" ", s), 1e-9) << "the leading space is kept";
}

TEST(TextWhiteSpace, ASpaceBetweenTspansIsKeptOnce) {
    const Rect want = bounds_of(text(R"(x="10" y="100" font-size="20")", "a b"));
    expect_rect(
        bounds_of(text(R"(x="10" y="100" font-size="20")", "<tspan>a </tspan> <tspan> b</tspan>")),
        want, 1e-9, "three spaces across tspans");
    expect_rect(
        bounds_of(text(R"(x="10" y="100" font-size="20")", "<tspan>a</tspan> <tspan>b</tspan>")),
        want, 1e-9, "the space between elements");
}

// --- 4. tref and display -----------------------------------------------------

TEST(Tref, DrawsTheReferencedElementsText) {
    const Rect plain = bounds_of(text(R"(x="10" y="100" font-size="20")", "Hello"));
    const SvgResult r =
        read(R"(<defs><text id="t">Hello</text></defs>)" +
             text(R"(x="10" y="100" font-size="20")", R"(<tref xlink:href="#t" fill="blue"/>)"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    expect_rect(sh[0]->path.bounds(), plain, 1e-9, "tref");
    EXPECT_EQ(sh[0]->fill->color, (Rgba{0, 0, 1, 1})) << "styled as the tref";
}

// KNOWN BUG (see the report): svg/text.cpp's text_children reads a tref's
// target with pugixml's text(), its first text child only. SVG 1.1, 10.6:
// "all of the character data within the referenced element, including
// character data enclosed within additional markup, will be rendered".
TEST(Tref, DrawsTheTextOfTheTargetsDescendantsToo) {
    const Rect plain = bounds_of(text(R"(x="10" y="100" font-size="20")", "Hello"));
    const Rect b = bounds_of(R"(<defs><text id="t">Hel<tspan>lo</tspan></text></defs>)" +
                             text(R"(x="10" y="100" font-size="20")", R"(<tref href="#t"/>)"));
    expect_rect(b, plain, 1e-9, "Hel and lo");
}

TEST(TextDisplay, DisplayNoneRemovesCharactersAndTheirWidth) {
    const Rect plain = bounds_of(text(R"(x="10" y="100" font-size="20")", "abcd"));
    const SvgResult r =
        read(text(R"(x="10" y="100" font-size="20")", R"(ab<tspan display="none">XYZ</tspan>cd)"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    expect_rect(sh[0]->path.bounds(), plain, 1e-9, "as if XYZ were not there");
}

TEST(TextDisplay, VisibilityHiddenKeepsTheWidth) {
    const SvgResult with =
        read(text(R"(x="10" y="100" font-size="20")", R"(ab<tspan>XYZ</tspan><tspan>cd</tspan>)"));
    const SvgResult hidden =
        read(text(R"(x="10" y="100" font-size="20")",
                  R"(ab<tspan visibility="hidden">XYZ</tspan><tspan>cd</tspan>)"));
    ASSERT_TRUE(with.scene && hidden.scene);
    const auto a = shapes(with), b = shapes(hidden);
    ASSERT_EQ(a.size(), 3u);
    ASSERT_EQ(b.size(), 2u) << "XYZ not drawn";
    expect_rect(b[1]->path.bounds(), a[2]->path.bounds(), 1e-9, "cd where it was");
}

TEST(TextDisplay, AFailedConditionRemovesATspan) {
    const Rect plain = bounds_of(text(R"(x="10" y="100" font-size="20")", "abcd"));
    expect_rect(bounds_of(text(R"(x="10" y="100" font-size="20")",
                               R"(ab<tspan systemLanguage="xx">XYZ</tspan>cd)")),
                plain, 1e-9, "systemLanguage xx");
}

// --- 5. Paint ----------------------------------------------------------------

// The map from a gradient's space to user space, as the renderer makes it
// (render/renderer.cpp): for objectBoundingBox, the unit square onto the
// shape's path bounds, then gradientTransform.
Affine gradient_to_user(const Shape& s, const Gradient& g) {
    Affine m = Affine::identity();
    if (g.object_bounding_box) {
        const Rect b = s.path.bounds();
        m = Affine::translate(b.min().to_vec()) * Affine::scale(b.width(), b.height());
    }
    return m * g.transform;
}

void expect_affine(const Affine& got, const Affine& want, double tol, const std::string& what) {
    const double g[] = {got.a, got.b, got.c, got.d, got.e, got.f};
    const double w[] = {want.a, want.b, want.c, want.d, want.e, want.f};
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(g[i], w[i], tol) << what << ", coefficient " << i;
}

const char* const kGradient = R"(<defs><linearGradient id="g">
    <stop offset="0" stop-color="red"/><stop offset="1" stop-color="blue"/>
    </linearGradient></defs>)";

TEST(TextPaint, StrokeAndAnObjectBoundingBoxGradient) {
    const SvgResult r = read(
        std::string(kGradient) +
        text(R"a(x="10" y="100" font-size="40" fill="url(#g)" stroke="blue" stroke-width="2")a",
             "Hello"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    ASSERT_TRUE(sh[0]->stroke);
    EXPECT_EQ(sh[0]->stroke->color, (Rgba{0, 0, 1, 1}));
    EXPECT_EQ(sh[0]->stroke->geometry.width, 2);
    ASSERT_TRUE(sh[0]->fill && sh[0]->fill->gradient);
    const Rect box = ink("Hello", style(40), {10, 100});
    expect_affine(gradient_to_user(*sh[0], *sh[0]->fill->gradient),
                  Affine::translate(box.min().to_vec()) * Affine::scale(box.width(), box.height()),
                  1e-9, "the unit square onto the text's box");
}

// KNOWN BUG (see the report): svg/text.cpp's draw_text passes the whole
// text's box to painted(), but Reader::paint only uses it for patterns; a
// gradient keeps objectBoundingBox units and the renderer maps it onto the
// span's own path bounds, not the text element's box that text.cpp's own
// comment (and browsers) give a tspan.
TEST(TextPaint, ATspansObjectBoundingBoxGradientUsesTheTextsBox) {
    const SvgResult r =
        read(std::string(kGradient) + text(R"(x="10" y="100" font-size="40")",
                                           R"a(Hello <tspan fill="url(#g)">World</tspan>)a"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 2u);
    ASSERT_TRUE(sh[1]->fill && sh[1]->fill->gradient);
    const Rect box = bounds(sh);
    expect_affine(gradient_to_user(*sh[1], *sh[1]->fill->gradient),
                  Affine::translate(box.min().to_vec()) * Affine::scale(box.width(), box.height()),
                  1e-9, "the unit square onto the whole text's box " + str(box));
}

TEST(TextPaint, FillNoneDrawsNoFillAndOpacityMakesAGroup) {
    const SvgResult r = read(
        text(R"(x="10" y="100" font-size="40" fill="none" stroke="red" opacity="0.5")", "Hello"));
    ASSERT_TRUE(r.scene) << r.error;
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    EXPECT_FALSE(sh[0]->fill);
    ASSERT_TRUE(sh[0]->stroke);
    EXPECT_EQ(sh[0]->opacity, 1.0f) << "the group carries the opacity";
    ASSERT_EQ(r.scene->root.children.size(), 1u);
    const Group* g = std::get_if<Group>(&r.scene->root.children[0].item);
    ASSERT_TRUE(g);
    EXPECT_EQ(g->opacity, 0.5f);
}

// --- 6. Limits ---------------------------------------------------------------

TEST(TextLimits, CharactersPastTheLimitAreNotDrawn) {
    const std::size_t per = text_to_path(fonts(), "H", style(20)).subpaths().size();
    SvgOptions o;
    o.max_text_characters = 10;
    const SvgResult r = read(text(R"(x="10" y="100" font-size="20")", "HHHHHHHHHHHHHHHHHHHH"), o);
    ASSERT_TRUE(r.scene) << r.error;
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_NE(r.warnings[0].text().find("limit of 10 characters"), std::string::npos)
        << r.warnings[0].text();
    const auto sh = shapes(r);
    ASSERT_EQ(sh.size(), 1u);
    EXPECT_EQ(sh[0]->path.subpaths().size(), 10 * per);
    // The limit is the document's: a second text gets what is left.
    const SvgResult two = read(text(R"(x="10" y="100" font-size="20")", "HHHHHH") +
                                   text(R"(x="10" y="150" font-size="20")", "HHHHHHHH"),
                               o);
    ASSERT_TRUE(two.scene) << two.error;
    const auto t = shapes(two);
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t[0]->path.subpaths().size(), 6 * per);
    EXPECT_EQ(t[1]->path.subpaths().size(), 4 * per);
    EXPECT_EQ(two.warnings.size(), 1u);
}

// The language (xml:lang, lang, inherited from any ancestor) chooses the
// font's local forms: Noto Sans CJK draws 直 differently in Japanese and
// in Simplified Chinese (its locl feature).
TEST(TextLanguage, XmlLangChoosesLocalForms) {
    const std::string cjk = "/usr/share/fonts/opentype/noto";
    if (!std::filesystem::is_directory(cjk)) GTEST_SKIP() << "fonts-noto-cjk is not installed";
    static const std::unique_ptr<FontDatabase> db = [&] {
        auto d = FontDatabase::empty();
        d->add_font_dir(cjk);
        return d;
    }();
    const auto glyph_box = [&](const std::string& body) {
        SvgOptions o;
        o.fonts = db.get();
        const SvgResult r = parse_svg(
            "<svg xmlns='http://www.w3.org/2000/svg' width='200' height='200'>" + body + "</svg>",
            "lang.svg", o);
        EXPECT_TRUE(r.scene) << r.error;
        return bounds(shapes(r));
    };
    const char* text =
        R"(<text x="10" y="100" font-family="Noto Sans CJK JP" font-size="80">直</text>)";
    const Rect ja = glyph_box(std::string(R"(<g xml:lang="ja">)") + text + "</g>");
    const Rect zh = glyph_box(std::string(R"(<g lang="zh-Hans">)") + text + "</g>");
    const Rect none = glyph_box(text);
    EXPECT_GT(std::abs(ja.x0 - zh.x0) + std::abs(ja.y0 - zh.y0) + std::abs(ja.x1 - zh.x1) +
                  std::abs(ja.y1 - zh.y1),
              0.5)
        << "ja " << str(ja) << ", zh " << str(zh);
    EXPECT_NEAR(none.x1 - none.x0, ja.x1 - ja.x0, 1e-9) << "the font's own language is Japanese";
}

} // namespace
} // namespace casteljau::svg_text_test
