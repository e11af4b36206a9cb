// Font matching and loading (text/font_database.h): weight, style and
// stretch matched to files, families tried in order and the default family
// after them, adding files and folders, the system configuration through
// fontconfig (tests/text/fonts.conf), fallback by character, and fonts
// loaded once per face and variation. The fonts are the Debian packages the tests
// pin (fonts-dejavu-core, fonts-noto-core), in a database of their own or
// through tests/text/fonts.conf, never whatever the machine happens to have.
#include "casteljau/text/font_database.h"
#include "text_test_support.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
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

// The system configuration, pointed at the tests' own fontconfig file: the
// generic families resolve through its aliases, a family it classes but has
// not through its class, and an unknown family through the default family.
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

} // namespace
} // namespace casteljau::text_test
