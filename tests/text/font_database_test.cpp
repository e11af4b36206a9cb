// Font matching and loading (text/font_database.h): weight, style and
// stretch matched to files, families tried in order and the default family
// after them, adding files and folders, the system configuration through
// fontconfig (tests/text/fonts.conf), fallback by character, and fonts
// loaded once per face and variation. The fonts are the Debian packages the tests
// pin (fonts-dejavu-core, fonts-noto-core), in a database of their own or
// through tests/text/fonts.conf, never whatever the machine happens to have.
#include "casteljau/svg/reader.h"
#include "casteljau/text/font_database.h"
#include "text_test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <memory>
#include <optional>
#include <string>
#include <unistd.h>

namespace casteljau::text_test {
namespace {

std::string file_name(const std::optional<FontFace>& f) {
    return f ? std::filesystem::path(f->file).filename().string() : "(none)";
}

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

// A database of the system's configuration as FONTCONFIG_FILE names it, set
// to tests/text/fonts.conf while it is made (and restored after).
std::unique_ptr<FontDatabase> fonts_conf_database() {
    const char* old = std::getenv("FONTCONFIG_FILE");
    const std::string saved = old ? old : "";
    ::setenv("FONTCONFIG_FILE", CASTELJAU_TESTS "/text/fonts.conf", 1);
    auto db = std::make_unique<FontDatabase>();
    if (old)
        ::setenv("FONTCONFIG_FILE", saved.c_str(), 1);
    else
        ::unsetenv("FONTCONFIG_FILE");
    return db;
}

// The system configuration, pointed at the tests' own fontconfig file: the
// generic families resolve through its aliases, a family it classes but has
// not through its class, and an unknown family through the default family.
TEST(FontDatabase, SystemConfigurationHonoursFontconfigFile) {
    const std::unique_ptr<FontDatabase> conf = fonts_conf_database();
    FontDatabase& db = *conf;
    EXPECT_EQ(file_name(db.match(query("serif"))), "NotoSerif-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("sans-serif", 700))), "NotoSans-Bold.ttf");
    EXPECT_EQ(file_name(db.match(query("monospace"))), "NotoSansMono-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("system-ui"))), "NotoSans-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("No Such Font"))), "NotoSans-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("DejaVu Sans"))), "DejaVuSans.ttf");
    // Families the file classes but does not have: their class, as librsvg
    // draws them (a monospaced family stays monospaced), whatever the default.
    db.set_default_family("DejaVu Serif");
    EXPECT_EQ(file_name(db.match(query("Courier New"))), "NotoSansMono-Regular.ttf");
    EXPECT_EQ(file_name(db.match(query("Times New Roman", 700))), "NotoSerif-Bold.ttf");
    FontQuery list;
    list.families = {"No Such Font", "Courier New", "Times New Roman"};
    EXPECT_EQ(file_name(db.match(list)), "NotoSansMono-Regular.ttf");
    list.families = {"No Such Font", "Courier New", "DejaVu Sans"};
    EXPECT_EQ(file_name(db.match(list)), "DejaVuSans.ttf"); // a family found comes first
    EXPECT_EQ(file_name(db.match(query("No Such Font"))), "DejaVuSerif.ttf");
}

// Text without a font-family anywhere takes the initial value, the user
// agent's: Times New Roman, as browsers, librsvg and resvg have it, so
// fontconfig's serif where it is missing (tests/text/fonts.conf classes it
// so). Before: the database's default family, sans-serif.
TEST(FontDatabase, UnstyledSvgTextIsTimesNewRomanOrItsClass) {
    const std::unique_ptr<FontDatabase> conf = fonts_conf_database();
    const auto ink = [&](const char* attrs) {
        SvgOptions o;
        o.fonts = conf.get();
        const SvgResult r = parse_svg(
            std::string(R"(<svg xmlns="http://www.w3.org/2000/svg" width="300" height="60">)") +
                "<text x='5' y='40' font-size='30' " + attrs + ">Hamburg</text></svg>",
            "t.svg", o);
        EXPECT_TRUE(r.scene) << r.error;
        Rect b = Rect::empty();
        for (const Node& n : r.scene->root.children)
            if (const Shape* sh = std::get_if<Shape>(&n.item)) b = b.united(sh->path.bounds());
        return b;
    };
    const Rect plain = ink(""), serif = ink("font-family='serif'"),
               sans = ink("font-family='sans-serif'");
    EXPECT_EQ(plain.x1, serif.x1);
    EXPECT_NE(plain.x1, sans.x1);
}

// Bold and italic a family lacks are synthesized where fontconfig's rules
// for fonts say so (tests/text/fonts.conf has 90-synthetic.conf's), and
// only there: a family with the face draws it, and a configuration without
// the rules synthesizes nothing.
TEST(FontDatabase, SynthesizesWhatAFamilyLacksAsFontconfigSays) {
    const std::unique_ptr<FontDatabase> conf = fonts_conf_database();
    FontDatabase& db = *conf;
    const auto synthesis = [&](FontDatabase& d, const std::string& family, int weight,
                               FontStyle style) {
        const std::optional<FontFace> f = d.match(query(family, weight, style));
        return f ? f->synthesis : FontSynthesis{true, -1};
    };
    // Noto Sans Mono has a bold face and no italic; Noto Mono a regular face only.
    EXPECT_EQ(synthesis(db, "Noto Sans Mono", 400, FontStyle::Italic), (FontSynthesis{false, 0.2}));
    EXPECT_EQ(synthesis(db, "Noto Sans Mono", 400, FontStyle::Oblique),
              (FontSynthesis{false, 0.2}));
    EXPECT_EQ(synthesis(db, "Noto Sans Mono", 700, FontStyle::Normal), FontSynthesis{});
    EXPECT_EQ(file_name(db.match(query("Noto Sans Mono", 700))), "NotoSansMono-Bold.ttf");
    EXPECT_EQ(synthesis(db, "Noto Mono", 700, FontStyle::Normal), (FontSynthesis{true, 0}));
    EXPECT_EQ(synthesis(db, "Noto Mono", 600, FontStyle::Normal), FontSynthesis{})
        << "fontconfig's rule: bold from 700";
    EXPECT_EQ(synthesis(db, "Noto Mono", 700, FontStyle::Italic), (FontSynthesis{true, 0.2}));
    EXPECT_EQ(synthesis(db, "Noto Sans", 700, FontStyle::Italic), FontSynthesis{});
    EXPECT_EQ(synthesis(db, "Noto Sans Mono", 400, FontStyle::Normal), FontSynthesis{});
    // A character's fallback too (fontconfig's sorted fonts are prepared
    // for the query once one is chosen): Devanagari has no italic face.
    const std::optional<FontFace> nagari =
        db.fallback(query("Noto Sans Mono", 400, FontStyle::Italic), U'\u0928');
    ASSERT_TRUE(nagari);
    EXPECT_EQ(file_name(nagari), "NotoSansDevanagari-Regular.ttf");
    EXPECT_EQ(nagari->synthesis, (FontSynthesis{false, 0.2}));
    // Loaded apart from the face drawn as it is.
    const auto plain = db.font(*db.match(query("Noto Mono")));
    const auto bold = db.font(*db.match(query("Noto Mono", 700)));
    ASSERT_TRUE(plain && bold);
    EXPECT_NE(plain.get(), bold.get());
    EXPECT_TRUE(bold->synthesis().bold);
    EXPECT_FALSE(plain->synthesis().bold);
    // test_fonts() has no rules: nothing synthesized.
    EXPECT_EQ(synthesis(test_fonts(), "Noto Mono", 700, FontStyle::Italic), FontSynthesis{});
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
    EXPECT_FALSE(db.font({"/nonexistent/font.ttf", 0, nullptr, {}}));
}

} // namespace
} // namespace casteljau::text_test

namespace casteljau::text_test {
namespace {

std::shared_ptr<const std::vector<unsigned char>> bytes_of(const std::string& file) {
    std::ifstream in(file, std::ios::binary);
    return std::make_shared<const std::vector<unsigned char>>(std::istreambuf_iterator<char>(in),
                                                              std::istreambuf_iterator<char>());
}

void add(FontDatabase& layer, const std::string& family, const std::string& file, int lo, int hi,
         FontStyle style = FontStyle::Normal) {
    std::string error;
    ASSERT_TRUE(
        layer.add_font_data({family, lo, hi, style}, bytes_of(kDejaVuDir + "/" + file), error))
        << file << ": " << error;
}

// The family name the loaded font gives, or "(none)".
std::string family_of(FontDatabase& db, const std::optional<FontFace>& f) {
    if (!f) return "(none)";
    const auto font = db.font(*f);
    return font ? font->family() + (f->data ? " (memory)" : " (file)") : "(no font)";
}

// A document's fonts come first, in the order of the query's families, and
// everything else is the parent's; the parent never sees them.
TEST(FontDatabaseLayer, DocumentFamiliesComeFirstInTheQuerysOrder) {
    FontDatabase& parent = test_fonts();
    auto layer = FontDatabase::layer(parent);
    add(*layer, "Embedded", "DejaVuSerif-Bold.ttf", 400, 400);
    add(*layer, "DejaVu Sans", "DejaVuSansMono.ttf", 400, 400); // hides the installed one
    EXPECT_EQ(family_of(*layer, layer->match(query("Embedded"))), "DejaVu Serif (memory)");
    EXPECT_EQ(family_of(*layer, layer->match(query("embedded"))), "DejaVu Serif (memory)");
    EXPECT_EQ(family_of(*layer, layer->match(query("DejaVu Sans"))), "DejaVu Sans Mono (memory)");
    EXPECT_EQ(family_of(*layer, layer->match(query("DejaVu Serif"))), "DejaVu Serif (file)");
    FontQuery q;
    q.families = {"No Such Font", "Embedded"};
    EXPECT_EQ(family_of(*layer, layer->match(q)), "DejaVu Serif (memory)");
    q.families = {"Noto Sans", "Embedded"};
    EXPECT_EQ(family_of(*layer, layer->match(q)), "Noto Sans (file)");
    // A character the document's font lacks falls back to the parent's.
    q.families = {"Embedded"};
    const auto devanagari = layer->fallback(q, U'\u0928');
    ASSERT_TRUE(devanagari);
    EXPECT_FALSE(devanagari->data);
    EXPECT_EQ(family_of(*layer, layer->fallback(q, U'A')), "DejaVu Serif (memory)");
    EXPECT_NE(family_of(parent, parent.match(query("Embedded"))), "DejaVu Serif (memory)");
    EXPECT_EQ(family_of(parent, parent.match(query("DejaVu Sans"))), "DejaVu Sans (file)");
}

// CSS Fonts 4, 5.2: style first, then weight by its rules.
TEST(FontDatabaseLayer, StyleThenWeightAsCssFonts4Says) {
    auto layer = FontDatabase::layer(test_fonts());
    add(*layer, "F", "DejaVuSerif.ttf", 400, 400);
    add(*layer, "F", "DejaVuSerif-Bold.ttf", 700, 700);
    add(*layer, "F", "DejaVuSerif-Italic.ttf", 400, 400, FontStyle::Italic);
    add(*layer, "F", "DejaVuSans-ExtraLight.ttf", 200, 200);
    const auto file = [&](int weight, FontStyle style = FontStyle::Normal) {
        const auto f = layer->match(query("F", weight, style));
        return f ? f->file : std::string("(none)");
    };
    const auto name = [&](int weight, FontStyle style = FontStyle::Normal) {
        const auto f = layer->match(query("F", weight, style));
        return f ? layer->font(*f)->family() + " " + std::to_string(layer->font(*f)->glyph_count())
                 : std::string("(none)");
    };
    EXPECT_EQ(file(400), "@font-face 1 (F)");
    EXPECT_EQ(file(700), "@font-face 2 (F)");
    EXPECT_EQ(file(400, FontStyle::Italic), "@font-face 3 (F)");
    EXPECT_EQ(file(400, FontStyle::Oblique), "@font-face 3 (F)"); // oblique takes italic
    EXPECT_EQ(file(700, FontStyle::Italic), "@font-face 3 (F)");  // style before weight
    EXPECT_EQ(file(600), "@font-face 2 (F)");                     // above 500: heavier first
    EXPECT_EQ(file(900), "@font-face 2 (F)");                     // then lighter
    EXPECT_EQ(file(450), "@font-face 1 (F)"); // 400-500: up to 500, then lighter
    EXPECT_EQ(file(300), "@font-face 4 (F)"); // below 400: lighter first
    EXPECT_EQ(file(100), "@font-face 4 (F)"); // then heavier, nearest
    EXPECT_NE(name(700), name(400));
}

// A document's family lacking bold or italic gets them synthesized by the
// rule the system's fonts have (fontconfig's): bold for 700 and more from
// a face of 500 or less, a slant for italic or oblique from a normal face.
TEST(FontDatabaseLayer, SynthesizesTheBoldAndItalicADocumentFamilyLacks) {
    auto layer = FontDatabase::layer(test_fonts());
    add(*layer, "R", "DejaVuSerif.ttf", 400, 400);
    add(*layer, "B", "DejaVuSerif.ttf", 400, 400);
    add(*layer, "B", "DejaVuSerif-Bold.ttf", 700, 700);
    add(*layer, "W", "DejaVuSerif.ttf", 100, 900); // a range: every weight its own
    add(*layer, "I", "DejaVuSerif-Italic.ttf", 400, 400, FontStyle::Italic);
    const auto synthesis = [&](const std::string& family, int weight, FontStyle style) {
        const std::optional<FontFace> f = layer->match(query(family, weight, style));
        return f && f->data ? f->synthesis : FontSynthesis{true, -1};
    };
    EXPECT_EQ(synthesis("R", 400, FontStyle::Normal), FontSynthesis{});
    EXPECT_EQ(synthesis("R", 700, FontStyle::Normal), (FontSynthesis{true, 0}));
    EXPECT_EQ(synthesis("R", 600, FontStyle::Normal), FontSynthesis{});
    EXPECT_EQ(synthesis("R", 900, FontStyle::Italic), (FontSynthesis{true, 0.2}));
    EXPECT_EQ(synthesis("R", 400, FontStyle::Oblique), (FontSynthesis{false, 0.2}));
    EXPECT_EQ(synthesis("B", 700, FontStyle::Normal), FontSynthesis{});
    EXPECT_EQ(synthesis("B", 700, FontStyle::Italic), (FontSynthesis{false, 0.2}));
    EXPECT_EQ(synthesis("W", 900, FontStyle::Normal), FontSynthesis{});
    EXPECT_EQ(synthesis("I", 400, FontStyle::Italic), FontSynthesis{});
    EXPECT_EQ(synthesis("I", 400, FontStyle::Normal), FontSynthesis{}) << "never unslanted";
    const auto font = layer->font(*layer->match(query("R", 700, FontStyle::Italic)));
    ASSERT_TRUE(font);
    EXPECT_EQ(font->synthesis(), (FontSynthesis{true, 0.2}));
}

TEST(FontDatabaseLayer, OnlyALayerTakesFontsAndOnlyFontsAreTaken) {
    std::string error;
    auto db = FontDatabase::empty();
    EXPECT_FALSE(db->add_font_data({"X"}, bytes_of(kDejaVuSans), error));
    EXPECT_FALSE(error.empty());
    auto layer = FontDatabase::layer(*db);
    error.clear();
    EXPECT_FALSE(layer->add_font_data(
        {"X"}, std::make_shared<const std::vector<unsigned char>>(100, 0x41), error));
    EXPECT_NE(error.find("not a font"), std::string::npos) << error;
    EXPECT_FALSE(layer->add_font_dir(kDejaVuDir));
}

} // namespace
} // namespace casteljau::text_test
