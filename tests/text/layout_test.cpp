// Text layout (text/layout.h) and what it stands on: shaping against
// HarfBuzz called directly, a paragraph's runs in visual order with font
// fallback, one line set as a path, and arc length along a path
// (curve/path_measure.h, which text on a path uses). Bidi and UTF-8 are
// unicode_test.cpp's, font matching font_database_test.cpp's. The fonts are
// the Debian packages the tests pin (fonts-dejavu-core, fonts-noto-core), in
// a database of their own (text_test_support.h), never whatever the machine
// happens to have.
#include "casteljau/curve/path_measure.h"
#include "casteljau/text/font_database.h"
#include "casteljau/text/layout.h"
#include "casteljau/text/shaping.h"
#include "casteljau/text/utf8.h"
#include "corpus.h"
#include "text_test_support.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <gtest/gtest.h>
#include <hb.h>
#include <memory>
#include <numbers>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace casteljau::text_test {
namespace {

TextStyle style_of(std::string family, double size) {
    TextStyle s;
    s.font = query(std::move(family));
    s.size = size;
    return s;
}

std::shared_ptr<Font> load(const std::string& file) {
    std::string error;
    auto f = Font::load(file, 0, {}, &error);
    EXPECT_TRUE(f) << error;
    return f;
}

// ---------------------------------------------------------------- shaping

// HarfBuzz's own shaping of text[begin, end) in the font file at its units
// per em, for comparison: what shape_run should return, field for field.
std::vector<ShapedGlyph> harfbuzz_shape(const std::string& file, std::u32string_view text,
                                        std::size_t begin, std::size_t end, hb_direction_t dir,
                                        const std::vector<hb_feature_t>& features = {}) {
    hb_blob_t* blob = hb_blob_create_from_file(file.c_str());
    hb_face_t* face = hb_face_create(blob, 0);
    hb_font_t* font = hb_font_create(face);
    const int upem = int(hb_face_get_upem(face));
    hb_font_set_scale(font, upem, upem);
    hb_buffer_t* buf = hb_buffer_create();
    hb_buffer_add_utf32(buf, reinterpret_cast<const std::uint32_t*>(text.data()), int(text.size()),
                        unsigned(begin), int(end - begin));
    hb_buffer_set_direction(buf, dir);
    hb_buffer_guess_segment_properties(buf);
    hb_shape(font, buf, features.data(), unsigned(features.size()));
    unsigned n = 0;
    const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
    const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
    std::vector<ShapedGlyph> out;
    for (unsigned i = 0; i < n; ++i)
        out.push_back({info[i].codepoint, info[i].cluster, double(pos[i].x_advance),
                       double(pos[i].y_advance), double(pos[i].x_offset), double(pos[i].y_offset)});
    hb_buffer_destroy(buf);
    hb_font_destroy(font);
    hb_face_destroy(face);
    hb_blob_destroy(blob);
    return out;
}

void expect_same_glyphs(const std::vector<ShapedGlyph>& got, const std::vector<ShapedGlyph>& want,
                        const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_EQ(got[i].glyph, want[i].glyph) << what << " glyph " << i;
        EXPECT_EQ(got[i].cluster, want[i].cluster) << what << " glyph " << i;
        EXPECT_EQ(got[i].x_advance, want[i].x_advance) << what << " glyph " << i;
        EXPECT_EQ(got[i].y_advance, want[i].y_advance) << what << " glyph " << i;
        EXPECT_EQ(got[i].x_offset, want[i].x_offset) << what << " glyph " << i;
        EXPECT_EQ(got[i].y_offset, want[i].y_offset) << what << " glyph " << i;
    }
}

double total_advance(const std::vector<ShapedGlyph>& glyphs) {
    double a = 0;
    for (const ShapedGlyph& g : glyphs) a += g.x_advance;
    return a;
}

// Latin with kerning and ligatures, combining marks (positioned by mark
// offsets), Arabic right to left, Devanagari with its reordering: glyph for
// glyph what HarfBuzz gives.
TEST(ShapeRun, GlyphsAndPositionsAreHarfBuzzs) {
    struct Case {
        std::string file;
        const char* utf8;
        TextDirection dir;
    };
    const std::vector<Case> cases = {
        {kDejaVuSans, "Hello, World!", TextDirection::Ltr},
        {kDejaVuSans, "AVATAR To Wa Ty", TextDirection::Ltr},
        {kDejaVuSans, "office fjord affluent", TextDirection::Ltr},
        {kDejaVuSans, "e\xCC\x81 a\xCC\x88\xCC\xA3 q\xCC\x8C", TextDirection::Ltr},
        {kDejaVuSans, kSalam, TextDirection::Rtl},
        {kNotoDevanagari, kNamaste, TextDirection::Ltr},
    };
    for (const Case& c : cases) {
        const auto font = load(c.file);
        ASSERT_TRUE(font);
        const std::u32string text = decode_utf8(c.utf8);
        const auto got = shape_run(*font, text, 0, text.size(), {c.dir, "", {}});
        const auto want =
            harfbuzz_shape(c.file, text, 0, text.size(),
                           c.dir == TextDirection::Rtl ? HB_DIRECTION_RTL : HB_DIRECTION_LTR);
        expect_same_glyphs(got, want, c.utf8);
        // Advances are font units: the pen moves by the font's advances,
        // kerning aside, not by pixels of some size.
        EXPECT_GT(total_advance(got), 0.3 * font->metrics().units_per_em) << c.utf8;
    }
}

// A range of a longer text is shaped as HarfBuzz shapes that range, its
// clusters indices into the whole text; the text around it is context:
// Arabic letters join across the range's ends.
TEST(ShapeRun, ARangeIsShapedInTheContextOfItsText) {
    const auto font = load(kDejaVuSans);
    ASSERT_TRUE(font);
    const std::u32string latin = U"xxHelloyy";
    const auto got = shape_run(*font, latin, 2, 7, {});
    auto want = harfbuzz_shape(kDejaVuSans, U"Hello", 0, 5, HB_DIRECTION_LTR);
    for (ShapedGlyph& g : want) g.cluster += 2;
    expect_same_glyphs(got, want, "Hello in xxHelloyy");

    // سمعت: meem and ain in the middle are shaped joined to their
    // neighbours, not in the forms they take alone.
    const std::u32string arabic = decode_utf8(kSamiat);
    const auto whole = shape_run(*font, arabic, 0, 4, {TextDirection::Rtl, "", {}});
    const auto middle = shape_run(*font, arabic, 1, 3, {TextDirection::Rtl, "", {}});
    const auto alone = shape_run(*font, arabic.substr(1, 2), 0, 2, {TextDirection::Rtl, "", {}});
    ASSERT_EQ(whole.size(), 4u);
    ASSERT_EQ(middle.size(), 2u);
    ASSERT_EQ(alone.size(), 2u);
    // Visual order, right to left text: the glyph of cluster 2 comes first.
    EXPECT_EQ(middle[0].cluster, 2u);
    EXPECT_EQ(middle[1].cluster, 1u);
    EXPECT_EQ(middle[0].glyph, whole[1].glyph);
    EXPECT_EQ(middle[1].glyph, whole[2].glyph);
    EXPECT_NE(middle[1].glyph, alone[1].glyph) << "meem alone starts a word, here it is medial";
    EXPECT_NE(middle[0].glyph, alone[0].glyph) << "ain alone ends a word, here it is medial";
}

// Kerning pulls A and V together; switching the kern feature off leaves
// the glyphs' own advances.
TEST(ShapeRun, KerningAndTheKernFeature) {
    const auto font = load(kDejaVuSans);
    ASSERT_TRUE(font);
    const std::u32string av = U"AV";
    const double plain =
        font->advance(font->glyph_index(U'A')) + font->advance(font->glyph_index(U'V'));
    const auto kerned = shape_run(*font, av, 0, 2, {});
    ASSERT_EQ(kerned.size(), 2u);
    EXPECT_LT(total_advance(kerned), plain - 50); // DejaVu's A-V kern is -129 units of 2048
    FontFeature kern_off{{'k', 'e', 'r', 'n'}, false};
    const auto unkerned = shape_run(*font, av, 0, 2, {TextDirection::Ltr, "", {kern_off}});
    EXPECT_EQ(total_advance(unkerned), plain);
    // The advance with kerning is HarfBuzz's, kern off too.
    EXPECT_EQ(total_advance(unkerned),
              total_advance(harfbuzz_shape(kDejaVuSans, av, 0, 2, HB_DIRECTION_LTR,
                                           {{HB_TAG('k', 'e', 'r', 'n'), 0, 0, ~0u}})));
}

// DejaVu Sans has an fi ligature: one glyph, one cluster of two characters;
// liga off gives f and i.
TEST(ShapeRun, FiLigature) {
    const auto font = load(kDejaVuSans);
    ASSERT_TRUE(font);
    const std::u32string fi = U"fi";
    const auto lig = shape_run(*font, fi, 0, 2, {});
    ASSERT_EQ(lig.size(), 1u);
    EXPECT_EQ(lig[0].cluster, 0u);
    EXPECT_NE(lig[0].glyph, font->glyph_index(U'f'));
    const auto apart =
        shape_run(*font, fi, 0, 2, {TextDirection::Ltr, "", {{{'l', 'i', 'g', 'a'}, false}}});
    ASSERT_EQ(apart.size(), 2u);
    EXPECT_EQ(apart[0].glyph, font->glyph_index(U'f'));
    EXPECT_EQ(apart[1].glyph, font->glyph_index(U'i'));

    const std::u32string text = U"fi";
    const auto laid = shape_paragraph(test_fonts(), text, {style_of("DejaVu Sans", 20)}, {0, 0},
                                      TextDirection::Ltr);
    ASSERT_EQ(laid.size(), 1u);
    EXPECT_EQ(laid[0].begin, 0u);
    EXPECT_EQ(laid[0].end, 2u);
    EXPECT_TRUE(laid[0].first);
    EXPECT_EQ(laid[0].glyph, lig[0].glyph);
}

// -------------------------------------------------------------- paragraph

// Runs of glyphs of one direction, as the glyphs come (visual order).
std::vector<std::vector<std::size_t>> direction_runs(const std::vector<LaidGlyph>& glyphs) {
    std::vector<std::vector<std::size_t>> runs;
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
        if (i == 0 || glyphs[i].rtl != glyphs[i - 1].rtl) runs.emplace_back();
        runs.back().push_back(glyphs[i].begin);
    }
    return runs;
}

std::vector<std::size_t> clusters(const std::vector<LaidGlyph>& glyphs) {
    std::vector<std::size_t> c;
    for (const LaidGlyph& g : glyphs) c.push_back(g.begin);
    return c;
}

std::vector<LaidGlyph> shape(std::u32string_view text, const TextStyle& style,
                             TextDirection dir = TextDirection::Ltr) {
    return shape_paragraph(test_fonts(), text, {style}, std::vector<std::uint32_t>(text.size(), 0),
                           dir);
}

// "abc אבג def": left to right, the Hebrew in the middle right to left
// (its clusters decreasing); in a right-to-left paragraph the Latin words
// swap places and the spaces go with the Hebrew.
TEST(ShapeParagraph, MixedDirectionsInVisualOrder) {
    const std::u32string text = decode_utf8(std::string("abc ") + kAlefBetGimel + " def");
    const TextStyle s = style_of("DejaVu Sans", 16);
    const auto ltr = shape(text, s, TextDirection::Ltr);
    EXPECT_EQ(clusters(ltr), (std::vector<std::size_t>{0, 1, 2, 3, 6, 5, 4, 7, 8, 9, 10}));
    const auto runs = direction_runs(ltr);
    ASSERT_EQ(runs.size(), 3u);
    EXPECT_FALSE(ltr.front().rtl);
    EXPECT_TRUE(ltr[4].rtl);
    for (const LaidGlyph& g : ltr) {
        EXPECT_NE(g.glyph, 0u) << g.begin;
        EXPECT_EQ(g.end, g.begin + 1);
        EXPECT_NEAR(g.scale, 16.0 / 2048, 1e-15);
    }

    const auto rtl = shape(text, s, TextDirection::Rtl);
    EXPECT_EQ(clusters(rtl), (std::vector<std::size_t>{8, 9, 10, 7, 6, 5, 4, 3, 0, 1, 2}));
    EXPECT_EQ(direction_runs(rtl).size(), 3u);
}

// Scripts the style's font lacks come from fonts that have them, and no
// glyph is the missing glyph; a character that no font has gets the style's
// own missing glyph.
TEST(ShapeParagraph, FontFallbackForOtherScripts) {
    const std::u32string text =
        decode_utf8(std::string("Hello ") + kNamaste + " " + kSawasdee + " \xF4\x8F\xBF\xBD");
    const auto glyphs = shape(text, style_of("DejaVu Sans", 16));
    ASSERT_FALSE(glyphs.empty());
    std::size_t devanagari = 0, thai = 0;
    for (const LaidGlyph& g : glyphs) {
        ASSERT_TRUE(g.font) << g.begin;
        const char32_t c = text[g.begin];
        if (c == U'\U0010FFFD') {
            EXPECT_EQ(g.glyph, 0u);
            EXPECT_EQ(g.font->family(), "DejaVu Sans");
            continue;
        }
        EXPECT_NE(g.glyph, 0u) << "U+" << std::hex << unsigned(c);
        EXPECT_NE(g.font->glyph_index(c), 0u) << "U+" << std::hex << unsigned(c);
        if (c >= 0x900 && c < 0x980) {
            ++devanagari;
            EXPECT_NE(g.font->family().find("Devanagari"), std::string::npos) << g.font->family();
        } else if (c >= 0xE00 && c < 0xE80) {
            ++thai;
            EXPECT_NE(g.font->family().find("Thai"), std::string::npos) << g.font->family();
        } else {
            EXPECT_EQ(g.font->family(), "DejaVu Sans") << "U+" << std::hex << unsigned(c);
        }
        // Each glyph is scaled for its own font's em.
        EXPECT_NEAR(g.scale, 16.0 / g.font->metrics().units_per_em, 1e-15);
    }
    EXPECT_GT(devanagari, 3u);
    EXPECT_GT(thai, 3u);
}

// Each character is set in its own style; font-size-adjust scales each font
// so that its x-height is the asked fraction of the size.
TEST(ShapeParagraph, StylesAndSizeAdjust) {
    const std::u32string text = U"abc";
    TextStyle small = style_of("Noto Sans", 10), big = style_of("Noto Sans", 30);
    const auto glyphs =
        shape_paragraph(test_fonts(), text, {small, big}, {0, 1, 1}, TextDirection::Ltr);
    ASSERT_EQ(glyphs.size(), 3u);
    EXPECT_EQ(glyphs[0].style, 0u);
    EXPECT_EQ(glyphs[1].style, 1u);
    EXPECT_NEAR(glyphs[0].scale, 10.0 / 1000, 1e-15);
    EXPECT_NEAR(glyphs[1].scale, 30.0 / 1000, 1e-15);
    const Font& f = *glyphs[1].font;
    EXPECT_NEAR(glyphs[1].advance.x, f.advance(glyphs[1].glyph) * 30.0 / 1000, 1e-9);

    TextStyle adjusted = style_of("Noto Sans", 20);
    adjusted.size_adjust = 0.5;
    const auto a = shape(text, adjusted);
    ASSERT_FALSE(a.empty());
    const FontMetrics& m = a[0].font->metrics();
    EXPECT_NEAR(a[0].scale * m.x_height, 0.5 * 20, 1e-9); // the x-height is half the size
}

// Levels given by the caller (unicode-bidi: bidi-override) replace the
// algorithm's: Latin forced right to left is drawn reversed.
TEST(ShapeParagraph, GivenLevelsOverrideTheAlgorithm) {
    const std::u32string text = U"abc def";
    const TextStyle s = style_of("DejaVu Sans", 16);
    const std::vector<std::uint32_t> one_style(text.size(), 0);
    const std::vector<std::uint8_t> rtl(text.size(), 1);
    const auto forced =
        shape_paragraph(test_fonts(), text, {s}, one_style, TextDirection::Ltr, &rtl);
    EXPECT_EQ(clusters(forced), (std::vector<std::size_t>{6, 5, 4, 3, 2, 1, 0}));
    for (const LaidGlyph& g : forced) EXPECT_TRUE(g.rtl);
    // The first word embedded left to right at level 2 inside it.
    const std::vector<std::uint8_t> nested = {2, 2, 2, 1, 1, 1, 1};
    EXPECT_EQ(
        clusters(shape_paragraph(test_fonts(), text, {s}, one_style, TextDirection::Ltr, &nested)),
        (std::vector<std::size_t>{6, 5, 4, 3, 0, 1, 2}));
    const std::vector<std::uint8_t> too_short(3, 1);
    EXPECT_TRUE(shape_paragraph(test_fonts(), text, {s}, one_style, TextDirection::Ltr, &too_short)
                    .empty());
}

// Empty text, a style per character missing, or no styles: no glyphs.
TEST(ShapeParagraph, EmptyAndMismatchedInputGiveNoGlyphs) {
    EXPECT_TRUE(shape(U"", style_of("DejaVu Sans", 16)).empty());
    EXPECT_TRUE(
        shape_paragraph(test_fonts(), U"ab", {style_of("DejaVu Sans", 16)}, {0}, TextDirection::Ltr)
            .empty());
    EXPECT_TRUE(shape_paragraph(test_fonts(), U"ab", {}, {0, 0}, TextDirection::Ltr).empty());
}

// ------------------------------------------------------------ one line

// "HEH" has flat-sided, flat-bottomed ends: its path's box is the line's
// advance less the first glyph's left side bearing and the last one's right
// side bearing, from the baseline up to the cap height, y down.
TEST(TextToPath, BoundsAreTheAdvanceLessTheSideBearings) {
    const auto font = load(kDejaVuSans);
    ASSERT_TRUE(font);
    const std::uint32_t h = font->glyph_index(U'H');
    const Rect hb = font->outline(h).bounds();
    const double k = 40.0 / 2048;
    const double lsb = hb.x0 * k, rsb = (font->advance(h) - hb.x1) * k;
    const TextStyle s = style_of("DejaVu Sans", 40);
    const Point origin{30, 100};
    const double advance = text_advance(test_fonts(), "HEH", s);
    const Rect b = text_to_path(test_fonts(), "HEH", s, origin).bounds();
    EXPECT_NEAR(b.x0, origin.x + lsb, 1e-9);
    EXPECT_NEAR(b.x1, origin.x + advance - rsb, 1e-9);
    EXPECT_NEAR(b.y1, origin.y, 1e-9);
    EXPECT_NEAR(b.y0, origin.y - hb.y1 * k, 1e-9);
    EXPECT_GT(advance, 3 * (lsb + rsb));
    // Right to left: the origin is where the line ends.
    const Rect r = text_to_path(test_fonts(), "HEH", s, origin, TextDirection::Rtl).bounds();
    EXPECT_NEAR(r.x1, origin.x - rsb, 1e-9);
    EXPECT_NEAR(r.x0, origin.x - advance + lsb, 1e-9);
}

// Moving the origin translates the path, whatever the text: a property over
// seeded random origins and a few scripts.
TEST(TextToPath, MovingTheOriginTranslatesThePath) {
    testing::Rng rng(2024);
    const TextStyle s = style_of("DejaVu Sans", 24);
    for (const std::string& utf8 : {std::string("Hamburgefonts"), std::string("AV office"),
                                    std::string("abc ") + kAlefBetGimel + " " + kNamaste}) {
        const Path at0 = text_to_path(test_fonts(), utf8, s);
        ASSERT_FALSE(at0.empty()) << utf8;
        for (int i = 0; i < 5; ++i) {
            const Vec2 o{rng.uniform(-500, 500), rng.uniform(-500, 500)};
            Path moved = at0;
            moved.transform(Affine::translate(o));
            const Path at = text_to_path(test_fonts(), utf8, s, Point{} + o);
            EXPECT_LT(control_point_distance(at, moved), 1e-9)
                << utf8 << " at " << o.x << ", " << o.y;
        }
    }
    // The comparison sees a path set elsewhere.
    Path off = text_to_path(test_fonts(), "Hamburgefonts", s);
    off.transform(Affine::translate({0.01, 0}));
    EXPECT_GT(control_point_distance(text_to_path(test_fonts(), "Hamburgefonts", s), off), 1e-3);
}

// Letter-spacing is added after each cluster (a ligature is one), and
// word-spacing after each word separator, space or no-break space.
TEST(TextAdvance, LetterAndWordSpacing) {
    TextStyle s = style_of("DejaVu Sans", 20);
    const double hello = text_advance(test_fonts(), "Hello world", s);
    const double office = text_advance(test_fonts(), "office", s); // o, ffi, c, e
    const double spaced = text_advance(test_fonts(),
                                       "a b\xC2\xA0"
                                       "c  d",
                                       s);
    s.letter_spacing = 1.5;
    EXPECT_NEAR(text_advance(test_fonts(), "Hello world", s), hello + 11 * 1.5, 1e-9);
    EXPECT_NEAR(text_advance(test_fonts(), "office", s), office + 4 * 1.5, 1e-9);
    s.letter_spacing = 0;
    s.word_spacing = 3;
    EXPECT_NEAR(text_advance(test_fonts(), "Hello world", s), hello + 3, 1e-9);
    EXPECT_NEAR(text_advance(test_fonts(),
                             "a b\xC2\xA0"
                             "c  d",
                             s),
                spaced + 4 * 3, 1e-9);
    EXPECT_NEAR(text_advance(test_fonts(), "office", s), office, 1e-9);
    EXPECT_TRUE(is_word_separator(U' '));
    EXPECT_TRUE(is_word_separator(U'\u00A0'));
    EXPECT_FALSE(is_word_separator(U'\t'));
    EXPECT_FALSE(is_word_separator(U'a'));
}

// -------------------------------------------------------------- arc length

// A circle of radius r from two SVG arcs (exact conics).
Path circle(Point c, double r) {
    Path p;
    p.move_to(c + Vec2{r, 0});
    p.arc_to({r, r}, 0, false, true, c - Vec2{r, 0});
    p.arc_to({r, r}, 0, false, true, c + Vec2{r, 0});
    p.close();
    return p;
}

TEST(PathMeasure, CircleLengthConvergesToTwoPiR) {
    for (const double r : {5.0, 10.0, 100.0, 1000.0}) {
        const PathMeasure m(circle({3, -7}, r), 0.01);
        EXPECT_NEAR(m.length(), 2 * std::numbers::pi * r, 1e-3 * 2 * std::numbers::pi * r)
            << "r = " << r;
        EXPECT_LE(m.length(), 2 * std::numbers::pi * r) << "chords are shorter than the arc";
        EXPECT_TRUE(m.closed());
    }
    // Quarter conics of weight sqrt(2)/2 make the same circle.
    Path conics;
    const double r = 50, w = std::sqrt(0.5);
    conics.move_to({r, 0});
    conics.conic_to({r, r}, {0, r}, w);
    conics.conic_to({-r, r}, {-r, 0}, w);
    conics.conic_to({-r, -r}, {0, -r}, w);
    conics.conic_to({r, -r}, {r, 0}, w);
    conics.close();
    EXPECT_NEAR(PathMeasure(conics, 0.01).length(), 2 * std::numbers::pi * r,
                1e-3 * 2 * std::numbers::pi * r);
    // The error shrinks with the tolerance: quadratically, so a tolerance
    // 100 times smaller is far closer.
    const double coarse = 2 * std::numbers::pi * 100 - PathMeasure(circle({}, 100), 1).length();
    const double fine = 2 * std::numbers::pi * 100 - PathMeasure(circle({}, 100), 0.01).length();
    EXPECT_GT(coarse, 0);
    EXPECT_LT(fine, coarse / 20);
}

TEST(PathMeasure, PointsAndTangentsAlongALine) {
    Path p;
    p.move_to({0, 0});
    p.line_to({30, 40});
    const PathMeasure m(p, 0.01);
    EXPECT_EQ(m.length(), 50);
    EXPECT_FALSE(m.closed());
    for (const double d : {0.0, 10.0, 25.0, 49.0, 50.0}) {
        const auto at = m.at(d);
        ASSERT_TRUE(at) << d;
        EXPECT_NEAR(at->point.x, 0.6 * d, 1e-12) << d;
        EXPECT_NEAR(at->point.y, 0.8 * d, 1e-12) << d;
        EXPECT_NEAR(at->tangent.x, 0.6, 1e-15) << d;
        EXPECT_NEAR(at->tangent.y, 0.8, 1e-15) << d;
    }
    EXPECT_FALSE(m.at(-1e-9));
    EXPECT_FALSE(m.at(50 + 1e-9));
    EXPECT_FALSE(m.at(NAN));
    EXPECT_FALSE(PathMeasure(Path{}, 0.01).at(0));
    EXPECT_EQ(PathMeasure(Path{}, 0.01).length(), 0);
}

// Subpaths follow one another without the jump counting; an edge of no
// length is passed over.
TEST(PathMeasure, SubpathsAndEmptyEdges) {
    Path p;
    p.move_to({0, 0});
    p.line_to({10, 0});
    p.line_to({10, 0});
    p.line_to({10, 10});
    p.move_to({100, 100});
    p.line_to({100, 110});
    const PathMeasure m(p, 0.01);
    EXPECT_EQ(m.length(), 30);
    EXPECT_FALSE(m.closed());
    const auto a = m.at(10.5);
    ASSERT_TRUE(a);
    EXPECT_NEAR(a->point.x, 10, 1e-12);
    EXPECT_NEAR(a->point.y, 0.5, 1e-12);
    EXPECT_NEAR(a->tangent.y, 1, 1e-15);
    const auto b = m.at(25);
    ASSERT_TRUE(b);
    EXPECT_NEAR(b->point.x, 100, 1e-12);
    EXPECT_NEAR(b->point.y, 105, 1e-12);
    EXPECT_NEAR(b->tangent.y, 1, 1e-15);
    const auto end = m.at(30);
    ASSERT_TRUE(end);
    EXPECT_NEAR(end->point.y, 110, 1e-12);
}

// On a circle every place lies on the circle, at the angle its distance
// says, with the tangent perpendicular to the radius: seeded random
// distances.
TEST(PathMeasure, PlacesOnACircle) {
    const double r = 40;
    const Point c{5, 5};
    const PathMeasure m(circle(c, r), 0.001);
    testing::Rng rng(11);
    for (int i = 0; i < 200; ++i) {
        const double d = rng.uniform(0, m.length());
        const auto at = m.at(d);
        ASSERT_TRUE(at) << d;
        const Vec2 radial = at->point - c;
        EXPECT_NEAR(radial.length(), r, 0.001 + 1e-9) << d;
        const double angle = std::atan2(radial.y, radial.x);
        const double expected = std::remainder(d / r, 2 * std::numbers::pi);
        EXPECT_NEAR(std::remainder(angle - expected, 2 * std::numbers::pi), 0, 2e-3) << d;
        EXPECT_NEAR(at->tangent.length(), 1, 1e-12) << d;
        EXPECT_NEAR(at->tangent.dot(radial) / r, 0, 0.02) << d;
    }
}

} // namespace
} // namespace casteljau::text_test
