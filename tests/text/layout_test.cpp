// Text layout (text/layout.h) and what it stands on: shaping against
// HarfBuzz called directly, the bidi levels and their visual order, UTF-8
// decoding, font matching and fallback, one line set as a path, and arc
// length along a path (curve/path_measure.h, which text on a path uses).
// The fonts are the Debian packages the tests pin (fonts-dejavu-core,
// fonts-noto-core), in a database of their own or through
// tests/text/fonts.conf, never whatever the machine happens to have.
#include "casteljau/curve/path_measure.h"
#include "casteljau/text/bidi.h"
#include "casteljau/text/font_database.h"
#include "casteljau/text/layout.h"
#include "casteljau/text/shaping.h"
#include "casteljau/text/utf8.h"
#include "corpus.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <hb.h>
#include <numbers>
#include <string>
#include <unistd.h>
#include <vector>

namespace casteljau {
namespace {

const std::string kDejaVuDir = "/usr/share/fonts/truetype/dejavu";
const std::string kNotoDir = "/usr/share/fonts/truetype/noto";
const std::string kDejaVuSans = kDejaVuDir + "/DejaVuSans.ttf";
const std::string kNotoDevanagari = kNotoDir + "/NotoSansDevanagari-Regular.ttf";

// UTF-8 spelled out, for readability of the cases below.
const char* const kAlefBetGimel = "\xD7\x90\xD7\x91\xD7\x92";   // אבג
const char* const kSalam = "\xD8\xB3\xD9\x84\xD8\xA7\xD9\x85";  // سلام
const char* const kSamiat = "\xD8\xB3\xD9\x85\xD8\xB9\xD8\xAA"; // سمعت
const char* const kNamaste = "\xE0\xA4\xA8\xE0\xA4\xAE\xE0\xA4\xB8\xE0\xA5\x8D\xE0\xA4\xA4"
                             "\xE0\xA5\x87"; // नमस्ते
const char* const kSawasdee = "\xE0\xB8\xAA\xE0\xB8\xA7\xE0\xB8\xB1\xE0\xB8\xAA\xE0\xB8\x94"
                              "\xE0\xB8\xB5"; // สวัสดี

// DejaVu and Noto, and nothing else: made once (fontconfig scans the
// folders) and shared by the tests that do not change it.
FontDatabase& test_fonts() {
    static const std::unique_ptr<FontDatabase> db = [] {
        auto d = FontDatabase::empty();
        EXPECT_TRUE(d->add_font_dir(kDejaVuDir));
        EXPECT_TRUE(d->add_font_dir(kNotoDir));
        return d;
    }();
    return *db;
}

FontQuery query(std::string family, int weight = 400, FontStyle style = FontStyle::Normal) {
    FontQuery q;
    q.families = {std::move(family)};
    q.weight = weight;
    q.style = style;
    return q;
}

TextStyle style_of(std::string family, double size) {
    TextStyle s;
    s.font = query(std::move(family));
    s.size = size;
    return s;
}

std::string file_name(const std::optional<FontFace>& f) {
    return f ? std::filesystem::path(f->file).filename().string() : "(none)";
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

// The control points of a segment, in order.
std::vector<Point> control_points(const Segment& s) {
    return std::visit(
        [](const auto& c) -> std::vector<Point> {
            if constexpr (requires { c.points(); })
                return {c.points().begin(), c.points().end()};
            else
                return {c.p0, c.p1, c.p2};
        },
        s);
}

// The largest distance between corresponding control points of two paths
// of the same structure; infinity when the structure differs.
double control_point_distance(const Path& a, const Path& b) {
    if (a.subpaths().size() != b.subpaths().size()) return INFINITY;
    double d = 0;
    for (std::size_t i = 0; i < a.subpaths().size(); ++i) {
        const Subpath &p = a.subpaths()[i], &q = b.subpaths()[i];
        if (p.segments.size() != q.segments.size() || p.closed != q.closed) return INFINITY;
        d = std::max(d, distance(p.start, q.start));
        for (std::size_t k = 0; k < p.segments.size(); ++k) {
            if (p.segments[k].index() != q.segments[k].index()) return INFINITY;
            const std::vector<Point> u = control_points(p.segments[k]),
                                     v = control_points(q.segments[k]);
            for (std::size_t j = 0; j < u.size(); ++j) d = std::max(d, distance(u[j], v[j]));
        }
    }
    return d;
}

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

// ------------------------------------------------------------------- bidi

std::vector<std::uint8_t> levels_of(const std::string& utf8, bool rtl) {
    return bidi_levels(decode_utf8(utf8), rtl);
}

using Levels = std::vector<std::uint8_t>;

struct LevelRun {
    std::size_t begin, end;
    int level;
    bool operator==(const LevelRun&) const = default;
};
std::ostream& operator<<(std::ostream& os, const LevelRun& r) {
    return os << "[" << r.begin << ", " << r.end << ") at " << r.level;
}
std::vector<LevelRun> runs_of(const Levels& levels) {
    std::vector<LevelRun> out;
    for (const BidiRun& r : visual_runs(levels)) out.push_back({r.begin, r.end, r.level});
    return out;
}

TEST(Bidi, LevelsOfSmallParagraphs) {
    EXPECT_EQ(levels_of("abc", false), (Levels{0, 0, 0}));
    EXPECT_EQ(runs_of(levels_of("abc", false)), (std::vector<LevelRun>{{0, 3, 0}}));
    // Left to right in a right-to-left paragraph rises to level 2.
    EXPECT_EQ(levels_of("abc", true), (Levels{2, 2, 2}));
    const std::string mixed = std::string("abc ") + kAlefBetGimel;
    EXPECT_EQ(levels_of(mixed, false), (Levels{0, 0, 0, 0, 1, 1, 1}));
    EXPECT_EQ(runs_of(levels_of(mixed, false)), (std::vector<LevelRun>{{0, 4, 0}, {4, 7, 1}}));
    // Base right to left: the space between the two takes the paragraph's
    // direction, and the Latin word is drawn to the right of the Hebrew.
    EXPECT_EQ(levels_of(mixed, true), (Levels{2, 2, 2, 1, 1, 1, 1}));
    EXPECT_EQ(runs_of(levels_of(mixed, true)), (std::vector<LevelRun>{{3, 7, 1}, {0, 3, 2}}));
    // European digits after Hebrew in a left-to-right paragraph: level 2,
    // drawn left to right, left of the Hebrew.
    const std::string digits = std::string(kAlefBetGimel) + " 123";
    EXPECT_EQ(levels_of(digits, false), (Levels{1, 1, 1, 1, 2, 2, 2}));
    EXPECT_EQ(runs_of(levels_of(digits, false)), (std::vector<LevelRun>{{4, 7, 2}, {0, 4, 1}}));
    EXPECT_TRUE(bidi_levels(U"", true).empty());
    EXPECT_TRUE(visual_runs({}).empty());
}

// L2 on levels set by hand (an override, say): from the highest level down
// to the lowest odd one, every sequence at that level or above reverses.
TEST(Bidi, VisualRunsReverseFromTheHighestLevel) {
    EXPECT_EQ(runs_of({0, 1, 1, 2, 2, 1, 0}),
              (std::vector<LevelRun>{{0, 1, 0}, {5, 6, 1}, {3, 5, 2}, {1, 3, 1}, {6, 7, 0}}));
    // 3: c alone; 2: b c -> c b; 1: a c b -> b c a.
    EXPECT_EQ(runs_of({1, 2, 3}), (std::vector<LevelRun>{{1, 2, 2}, {2, 3, 3}, {0, 1, 1}}));
    // Even levels alone reverse in pairs: the order stays.
    EXPECT_EQ(runs_of({0, 2, 4, 2}),
              (std::vector<LevelRun>{{0, 1, 0}, {1, 2, 2}, {2, 3, 4}, {3, 4, 2}}));
    // Against a brute-force L2 on characters, over seeded random levels.
    testing::Rng rng(7);
    for (int t = 0; t < 500; ++t) {
        Levels levels(std::size_t(rng.integer(1, 12)));
        for (auto& l : levels) l = std::uint8_t(rng.integer(0, 4));
        std::vector<std::size_t> order(levels.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        const int highest = *std::max_element(levels.begin(), levels.end());
        const int lowest = *std::min_element(levels.begin(), levels.end());
        for (int level = highest; level >= (lowest | 1); --level)
            for (std::size_t i = 0; i < order.size();) {
                if (levels[order[i]] < level) {
                    ++i;
                    continue;
                }
                std::size_t j = i;
                while (j < order.size() && levels[order[j]] >= level) ++j;
                std::reverse(order.begin() + std::ptrdiff_t(i), order.begin() + std::ptrdiff_t(j));
                i = j;
            }
        // The runs, each read in its own direction, give that order.
        std::vector<std::size_t> from_runs;
        for (const BidiRun& r : visual_runs(levels))
            for (std::size_t k = 0; k < r.end - r.begin; ++k)
                from_runs.push_back(r.rtl() ? r.end - 1 - k : r.begin + k);
        EXPECT_EQ(from_runs, order) << "case " << t;
    }
}

// ------------------------------------------------------------------ UTF-8

std::u32string fffd(int n) { return std::u32string(std::size_t(n), U'\uFFFD'); }

TEST(Utf8, WellFormedSequences) {
    EXPECT_EQ(decode_utf8(""), U"");
    EXPECT_EQ(decode_utf8("Az~\x7F"), U"Az~\x7F");
    EXPECT_EQ(decode_utf8(std::string("a\0b", 3)), std::u32string(U"a\0b", 3));
    EXPECT_EQ(decode_utf8("\xC2\x80\xC3\xA9\xDF\xBF"), U"\u0080\u00E9\u07FF");
    EXPECT_EQ(decode_utf8("\xE0\xA0\x80\xE2\x82\xAC\xED\x9F\xBF\xEE\x80\x80\xEF\xBF\xBF"),
              U"\u0800\u20AC\uD7FF\uE000\uFFFF");
    EXPECT_EQ(decode_utf8("\xF0\x90\x80\x80\xF0\x9F\x98\x80\xF4\x8F\xBF\xBF"),
              U"\U00010000\U0001F600\U0010FFFF");
}

// Each maximal subpart of an ill-formed sequence is one U+FFFD (Unicode 15,
// 3.9, "U+FFFD substitution of maximal subparts").
TEST(Utf8, IllFormedSequencesBecomeOneReplacementPerMaximalSubpart) {
    // Overlong forms: C0 and C1 never start a sequence; E0 80..9F and
    // F0 80..8F are not the start of one.
    EXPECT_EQ(decode_utf8("\xC0\x80"), fffd(2));
    EXPECT_EQ(decode_utf8("\xC1\xBF"), fffd(2));
    EXPECT_EQ(decode_utf8("\xE0\x9F\xBF"), fffd(3));
    EXPECT_EQ(decode_utf8("\xF0\x8F\xBF\xBF"), fffd(4));
    // Surrogates, ED A0..BF.
    EXPECT_EQ(decode_utf8("\xED\xA0\x80"), fffd(3));
    EXPECT_EQ(decode_utf8("\xED\xBF\xBF"), fffd(3));
    // Past U+10FFFF: F4 90.., and F5..FF never start one.
    EXPECT_EQ(decode_utf8("\xF4\x90\x80\x80"), fffd(4));
    EXPECT_EQ(decode_utf8("\xF5\x80\x80\x80"), fffd(4));
    EXPECT_EQ(decode_utf8("\xFF\xFE"), fffd(2));
    // Lone continuation bytes.
    EXPECT_EQ(decode_utf8("\x80\xBF"), fffd(2));
    // Truncated: a well-begun sequence cut short is one subpart.
    EXPECT_EQ(decode_utf8("\xE2\x82"), fffd(1));
    EXPECT_EQ(decode_utf8("\xE2\x82"
                          "A"),
              U"\uFFFDA");
    EXPECT_EQ(decode_utf8("\xF0\x9F\x98"), fffd(1));
    EXPECT_EQ(decode_utf8("\xF0\x9F\x98\xE2\x82\xAC"), U"\uFFFD\u20AC");
    EXPECT_EQ(decode_utf8("\xC3"), fffd(1));
    // The standard's examples (table 3-8 and the text before it).
    EXPECT_EQ(decode_utf8("\xF1\x80\x80\xE1\x80\xC2\x41"), U"\uFFFD\uFFFD\uFFFDA");
    EXPECT_EQ(decode_utf8("\x61\xF1\x80\x80\xE1\x80\xC2\x62\x80\x63\x80\xBF\x64"),
              U"a\uFFFD\uFFFD\uFFFDb\uFFFDc\uFFFD\uFFFDd");
}

std::string encode_utf8(char32_t c) {
    std::string s;
    if (c < 0x80) {
        s += char(c);
    } else if (c < 0x800) {
        s += char(0xC0 | (c >> 6));
        s += char(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        s += char(0xE0 | (c >> 12));
        s += char(0x80 | ((c >> 6) & 0x3F));
        s += char(0x80 | (c & 0x3F));
    } else {
        s += char(0xF0 | (c >> 18));
        s += char(0x80 | ((c >> 12) & 0x3F));
        s += char(0x80 | ((c >> 6) & 0x3F));
        s += char(0x80 | (c & 0x3F));
    }
    return s;
}

// Every scalar value survives a round trip, and random bytes decode to
// scalar values only, never more of them than there are bytes, with the
// well-formed stretches intact.
TEST(Utf8, RoundTripsAndRandomBytes) {
    testing::Rng rng(36);
    for (int t = 0; t < 200; ++t) {
        std::u32string text;
        std::string utf8;
        for (int i = 0; i < 20; ++i) {
            const int width = rng.integer(0, 3);
            const char32_t limit[] = {0x80, 0x800, 0x10000, 0x110000};
            char32_t c = char32_t(
                rng.integer(width == 0 ? 0 : int(limit[width - 1]), int(limit[width]) - 1));
            if (c >= 0xD800 && c < 0xE000) c = 0xFFFD;
            text += c;
            utf8 += encode_utf8(c);
        }
        EXPECT_EQ(decode_utf8(utf8), text) << t;
    }
    for (int t = 0; t < 500; ++t) {
        std::string bytes;
        for (int i = rng.integer(0, 30); i > 0; --i) bytes += char(rng.integer(0, 255));
        const std::u32string out = decode_utf8(bytes);
        EXPECT_LE(out.size(), bytes.size());
        for (const char32_t c : out) {
            EXPECT_LE(c, 0x10FFFFu);
            EXPECT_FALSE(c >= 0xD800 && c < 0xE000);
        }
        // A valid character after the garbage comes through whole.
        EXPECT_EQ(decode_utf8(bytes + "\xE2\x82\xAC").back(), U'\u20AC') << t;
    }
}

// ---------------------------------------------------------- font database

TEST(FontDatabase, MatchesWeightAndStyleToFiles) {
    FontDatabase& db = test_fonts();
    EXPECT_EQ(file_name(db.match(query("DejaVu Serif"))), "DejaVuSerif.ttf");
    EXPECT_EQ(file_name(db.match(query("DejaVu Serif", 700))), "DejaVuSerif-Bold.ttf");
    EXPECT_EQ(file_name(db.match(query("DejaVu Serif", 400, FontStyle::Italic))),
              "DejaVuSerif-Italic.ttf");
    EXPECT_EQ(file_name(db.match(query("DejaVu Serif", 700, FontStyle::Italic))),
              "DejaVuSerif-BoldItalic.ttf");
    // DejaVu Sans has no italic: its oblique is the closest.
    EXPECT_EQ(file_name(db.match(query("DejaVu Sans", 400, FontStyle::Italic))),
              "DejaVuSans-Oblique.ttf");
    EXPECT_EQ(file_name(db.match(query("DejaVu Sans", 400, FontStyle::Oblique))),
              "DejaVuSans-Oblique.ttf");
    // The closest weight: 600 and 900 are bold, 300 and 100 regular or lighter.
    EXPECT_EQ(file_name(db.match(query("DejaVu Sans", 900))), "DejaVuSans-Bold.ttf");
    EXPECT_NE(file_name(db.match(query("DejaVu Sans", 300))), "DejaVuSans-Bold.ttf");
    // Condensed when asked for a narrower stretch.
    FontQuery narrow = query("DejaVu Sans");
    narrow.stretch = 87;
    EXPECT_EQ(file_name(db.match(narrow)), "DejaVuSansCondensed.ttf");
    // Family names are matched without regard to case.
    EXPECT_EQ(file_name(db.match(query("dejavu serif"))), "DejaVuSerif.ttf");
}

// Families are tried in order: the first one the database has wins; when
// none is there, the default family.
TEST(FontDatabase, UnknownFamiliesFallBackToTheDefaultFamily) {
    auto db = FontDatabase::empty();
    ASSERT_TRUE(db->add_font_dir(kDejaVuDir));
    FontQuery q;
    q.families = {"No Such Font", "DejaVu Serif", "DejaVu Sans"};
    EXPECT_EQ(file_name(db->match(q)), "DejaVuSerif.ttf");
    EXPECT_EQ(db->default_family(), "sans-serif");
    db->set_default_family("DejaVu Sans Mono");
    EXPECT_EQ(db->default_family(), "DejaVu Sans Mono");
    EXPECT_EQ(file_name(db->match(query("No Such Font"))), "DejaVuSansMono.ttf");
    EXPECT_EQ(file_name(db->match(query("No Such Font", 700))), "DejaVuSansMono-Bold.ttf");
    EXPECT_EQ(file_name(db->match(FontQuery{})), "DejaVuSansMono.ttf");
    db->set_default_family("DejaVu Serif");
    EXPECT_EQ(file_name(db->match(query("No Such Font"))), "DejaVuSerif.ttf");
    // A database without fonts matches nothing.
    EXPECT_FALSE(FontDatabase::empty()->match(query("DejaVu Sans")));
}

// Adding fonts says whether it did: a font file is taken, a file that is
// not a font is not.
TEST(FontDatabase, AddingAFileThatIsNotAFontFails) {
    auto db = FontDatabase::empty();
    const std::filesystem::path garbage = std::filesystem::temp_directory_path() /
                                          ("casteljau_not_a_font_" + std::to_string(::getpid()));
    {
        std::ofstream out(garbage, std::ios::binary);
        for (int i = 0; i < 4096; ++i) out.put(char((i * 7919 + 13) % 251));
    }
    EXPECT_FALSE(db->add_font_file(garbage.string()));
    std::filesystem::remove(garbage);
    EXPECT_FALSE(db->add_font_file("/nonexistent/font.ttf"));
    EXPECT_FALSE(db->match(query("DejaVu Sans")));
    EXPECT_TRUE(db->add_font_file(kDejaVuSans));
    EXPECT_EQ(file_name(db->match(query("DejaVu Sans"))), "DejaVuSans.ttf");
}

// font_database.h: add_font_dir is "false when it is not a readable folder".
TEST(FontDatabase, AddingAFolderThatDoesNotExistFails) {
    auto db = FontDatabase::empty();
    EXPECT_FALSE(db->add_font_dir("/nonexistent/fonts"));
    EXPECT_FALSE(db->add_font_dir(kDejaVuSans)); // a file, not a folder
    EXPECT_TRUE(db->add_font_dir(kDejaVuDir));
}

// The system configuration, pointed at the tests' own fontconfig file: the
// generic families resolve through its aliases, and an unknown family
// through the default family, serif.
TEST(FontDatabase, SystemConfigurationHonoursFontconfigFile) {
    const char* old = std::getenv("FONTCONFIG_FILE");
    const std::string saved = old ? old : "";
    ::setenv("FONTCONFIG_FILE", CASTELJAU_TESTS "/text/fonts.conf", 1);
    FontDatabase db;
    if (old)
        ::setenv("FONTCONFIG_FILE", saved.c_str(), 1);
    else
        ::unsetenv("FONTCONFIG_FILE");
    EXPECT_EQ(file_name(db.match(query("serif"))), "NotoSerif-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("sans-serif", 700))), "NotoSans-Bold.ttf");
    EXPECT_EQ(file_name(db.match(query("monospace"))), "NotoSansMono-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("system-ui"))), "NotoSans-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("No Such Font"))), "NotoSans-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("DejaVu Sans"))), "DejaVuSans.ttf");
}

// A character's fallback is a font that has it; none when no font has it.
TEST(FontDatabase, FallbackFindsAFontWithTheCharacter) {
    FontDatabase& db = test_fonts();
    for (const char32_t c : {U'\u05D0', U'\u0928', U'\u0E2A', U'\u0633', U'A'}) {
        const auto face = db.fallback(query("DejaVu Serif"), c);
        ASSERT_TRUE(face) << "U+" << std::hex << unsigned(c);
        const auto font = db.font(*face);
        ASSERT_TRUE(font) << face->file;
        EXPECT_NE(font->glyph_index(c), 0u) << "U+" << std::hex << unsigned(c) << " " << face->file;
    }
    // Latin from the family itself.
    EXPECT_EQ(file_name(db.fallback(query("DejaVu Serif"), U'A')), "DejaVuSerif.ttf");
    EXPECT_FALSE(db.fallback(query("DejaVu Serif"), U'\U0010FFFD'));
}

// A face and variation is loaded once and shared; another variation is
// another font.
TEST(FontDatabase, FontsAreSharedPerFaceAndVariation) {
    FontDatabase& db = test_fonts();
    const auto face = db.match(query("DejaVu Sans"));
    ASSERT_TRUE(face);
    const auto a = db.font(*face), b = db.font(*face);
    ASSERT_TRUE(a);
    EXPECT_EQ(a.get(), b.get());
    const FontVariation bold{{'w', 'g', 'h', 't'}, 700};
    const auto c = db.font(*face, {bold}), d = db.font(*face, {bold});
    ASSERT_TRUE(c);
    EXPECT_EQ(c.get(), d.get());
    EXPECT_NE(a.get(), c.get());
    // A file that is not a font gives null, and matching does not offer it.
    EXPECT_FALSE(db.font({"/nonexistent/font.ttf", 0}));
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
} // namespace casteljau
