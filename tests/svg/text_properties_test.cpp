// The text properties (svg/text_properties.h) as CSS parses them: each
// value, valid and invalid (an invalid one is ignored, with what is wrong),
// the CSS-wide keywords, the font-family list and the font shorthand (CSS
// Fonts 4, 2.1 and 2.7), alone and through apply_property and the reader.
#include "casteljau/svg/reader.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/text_properties.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace casteljau {
namespace {

using Names = std::vector<std::string>;

// An element's style, its parent's and its own, and the context of its
// lengths: what apply_property sees.
struct Element {
    StyleState parent;
    StyleState style;
    ElementProps props;
    LengthContext ctx;

    /// Applies one declaration through apply_property; what is wrong, "" if
    /// nothing.
    std::string apply(std::string_view name, std::string_view value) {
        return apply_property(name, value, parent, style, props, ctx);
    }
    /// The same, expecting it applied.
    void ok(std::string_view name, std::string_view value) {
        EXPECT_EQ(apply(name, value), "") << name << ": " << value;
    }
    /// The same, expecting it refused with a message naming the property.
    void refused(std::string_view name, std::string_view value) {
        const std::string e = apply(name, value);
        EXPECT_NE(e.find(std::string(name)), std::string::npos)
            << name << ": '" << value << "' gave '" << e << "'";
    }
};

TEST(TextProperties, OnlyTextPropertiesAreTaken) {
    StyleState s;
    ElementProps p;
    EXPECT_FALSE(apply_text_property("fill", "red", s, s, p, {}));
    EXPECT_FALSE(apply_text_property("font-size", "12px", s, s, p, {}));
    EXPECT_FALSE(apply_text_property("fonts", "serif", s, s, p, {}));
    EXPECT_EQ(apply_text_property("font-weight", "bold", s, s, p, {}), "");
    EXPECT_EQ(s.text.font_weight, 700);
    const auto e = apply_text_property("font-weight", "heavy", s, s, p, {});
    ASSERT_TRUE(e);
    EXPECT_EQ(*e, "property font-weight: 'heavy' is not normal, bold, bolder, lighter or a "
                  "number from 1 to 1000");
    EXPECT_EQ(s.text.font_weight, 700);
}

TEST(FontFamily, QuotedNamesAndIdentifierSequences) {
    EXPECT_EQ(parse_font_family(R"("Noto Sans", 'DejaVu Serif', Times   New Roman, sans-serif)"),
              (Names{"Noto Sans", "DejaVu Serif", "Times New Roman", "sans-serif"}));
    EXPECT_EQ(parse_font_family("serif"), (Names{"serif"}));
    EXPECT_EQ(parse_font_family("  Arial\t,\nMONOSPACE  "), (Names{"Arial", "monospace"}));
    // A quoted name is taken as written: commas, case and spaces.
    EXPECT_EQ(parse_font_family(R"("A, B"  ,  ' Odd  Name')"), (Names{"A, B", " Odd  Name"}));
    // Escapes: a quote inside a string, a hex code point, a digit in an identifier.
    EXPECT_EQ(parse_font_family(R"("Say \"Hi\"", \31 0 Speed, Caf\e9 )"),
              (Names{"Say \"Hi\"", "10 Speed", "Caf\xC3\xA9"}));
    EXPECT_EQ(parse_font_family("Font-2 _x -y"), (Names{"Font-2 _x -y"}));
    EXPECT_EQ(parse_font_family("\xE6\x98\x8E\xE6\x9C\x9D"), (Names{"\xE6\x98\x8E\xE6\x9C\x9D"}));
    // Keywords as names in a sequence, or quoted, are names.
    EXPECT_EQ(parse_font_family("Inherit Sans, 'initial'"), (Names{"Inherit Sans", "initial"}));
    for (const char* bad :
         {"", " ", ",", "Arial,", ",Arial", "Arial,,serif", "3M", "Arial 2", "\"Unclosed",
          "'Noto' Sans", "Arial; serif", "inherit", "serif, initial", "default", "a/b", "-1x"})
        EXPECT_FALSE(parse_font_family(bad)) << bad;
}

TEST(FontFamily, ThroughApplyProperty) {
    Element e;
    e.parent.text.font_family = {"Parent"};
    e.ok("font-family", "'Noto Sans', serif");
    EXPECT_EQ(e.style.text.font_family, (Names{"Noto Sans", "serif"}));
    e.refused("font-family", "Noto Sans,");
    EXPECT_EQ(e.style.text.font_family, (Names{"Noto Sans", "serif"}));
    e.ok("font-family", "inherit");
    EXPECT_EQ(e.style.text.font_family, Names{"Parent"});
    e.ok("font-family", "INITIAL"); // the user agent's: browsers', librsvg's and resvg's
    EXPECT_EQ(e.style.text.font_family, Names{"Times New Roman"});
}

TEST(FontWeight, KeywordsNumbersAndRelativeWeights) {
    Element e;
    const std::pair<const char*, int> valid[] = {{"bold", 700},  {"normal", 400}, {"BOLD", 700},
                                                 {"100", 100},   {"1", 1},        {"1000", 1000},
                                                 {"450.4", 450}, {"+550", 550}};
    for (const auto& [text, want] : valid) {
        e.ok("font-weight", text);
        EXPECT_EQ(e.style.text.font_weight, want) << text;
    }
    e.style.text.font_weight = 300;
    for (const char* bad : {"0", "1001", "-5", "heavy", "700px", "bold 700", ""}) {
        e.refused("font-weight", bad);
        EXPECT_EQ(e.style.text.font_weight, 300) << bad;
    }
    // bolder and lighter: CSS Fonts 4, 2.2's table, from the parent's weight.
    const int table[][3] = {{50, 400, 50},   {100, 400, 100}, {349, 400, 100},  {350, 700, 100},
                            {549, 700, 100}, {550, 900, 400}, {749, 900, 400},  {750, 900, 700},
                            {899, 900, 700}, {900, 900, 700}, {1000, 1000, 700}};
    for (const auto& [parent, bolder, lighter] : table) {
        e.parent.text.font_weight = parent;
        e.ok("font-weight", "bolder");
        EXPECT_EQ(e.style.text.font_weight, bolder) << parent;
        e.ok("font-weight", "lighter");
        EXPECT_EQ(e.style.text.font_weight, lighter) << parent;
    }
    e.parent.text.font_weight = 600;
    e.ok("font-weight", "inherit");
    EXPECT_EQ(e.style.text.font_weight, 600);
    e.ok("font-weight", "initial");
    EXPECT_EQ(e.style.text.font_weight, 400);
    e.ok("font-weight", "unset"); // inherited: inherit
    EXPECT_EQ(e.style.text.font_weight, 600);
}

TEST(FontStyle, NormalItalicAndObliqueWithAnAngle) {
    Element e;
    const std::pair<const char*, FontStyle> valid[] = {
        {"italic", FontStyle::Italic},          {"normal", FontStyle::Normal},
        {"oblique", FontStyle::Oblique},        {"Italic", FontStyle::Italic},
        {"oblique 10deg", FontStyle::Oblique},  {"normal", FontStyle::Normal},
        {"oblique -90deg", FontStyle::Oblique}, {"normal", FontStyle::Normal},
        {"oblique 0.1turn", FontStyle::Oblique}};
    for (const auto& [text, want] : valid) {
        e.ok("font-style", text);
        EXPECT_EQ(e.style.text.font_style, want) << text;
    }
    e.style.text.font_style = FontStyle::Italic;
    for (const char* bad : {"slanted", "oblique 91deg", "oblique 10", "italic 10deg",
                            "oblique 10deg 5deg", "normal italic", ""}) {
        e.refused("font-style", bad);
        EXPECT_EQ(e.style.text.font_style, FontStyle::Italic) << bad;
    }
    e.ok("font-style", "initial");
    EXPECT_EQ(e.style.text.font_style, FontStyle::Normal);
}

TEST(FontStretch, KeywordsAndPercentages) {
    Element e;
    const std::pair<const char*, int> valid[] = {{"ultra-condensed", 50}, {"extra-condensed", 62},
                                                 {"condensed", 75},       {"semi-condensed", 87},
                                                 {"normal", 100},         {"semi-expanded", 112},
                                                 {"expanded", 125},       {"extra-expanded", 150},
                                                 {"ultra-expanded", 200}, {"80%", 80},
                                                 {"62.5%", 62},           {"0%", 50},
                                                 {"300%", 200},           {"Condensed", 75}};
    for (const auto& [text, want] : valid) {
        e.ok("font-stretch", text);
        EXPECT_EQ(e.style.text.font_stretch, want) << text;
    }
    e.style.text.font_stretch = 125;
    for (const char* bad : {"-10%", "80", "80 %", "wide", "condensed expanded"}) {
        e.refused("font-stretch", bad);
        EXPECT_EQ(e.style.text.font_stretch, 125) << bad;
    }
    e.parent.text.font_stretch = 75;
    e.ok("font-stretch", "inherit");
    EXPECT_EQ(e.style.text.font_stretch, 75);
}

TEST(FontVariant, SmallCapsFromEitherProperty) {
    Element e;
    for (const char* name : {"font-variant", "font-variant-caps"}) {
        const std::pair<const char*, bool> valid[] = {
            {"small-caps", true},      {"normal", false},     {"all-small-caps", true},
            {"normal", false},         {"petite-caps", true}, {"titling-caps", false},
            {"all-petite-caps", true}, {"unicase", true},     {"SMALL-CAPS", true}};
        for (const auto& [text, want] : valid) {
            e.ok(name, text);
            EXPECT_EQ(e.style.text.small_caps, want) << name << ": " << text;
        }
        for (const char* bad : {"smallcaps", "small-caps small-caps", ""}) {
            e.refused(name, bad);
            EXPECT_TRUE(e.style.text.small_caps) << name << ": " << bad;
        }
    }
    // The shorthand: none, and the other subproperties' values (ignored).
    e.ok("font-variant", "none");
    EXPECT_FALSE(e.style.text.small_caps);
    e.ok("font-variant", "oldstyle-nums small-caps no-common-ligatures");
    EXPECT_TRUE(e.style.text.small_caps);
    e.ok("font-variant", "tabular-nums");
    EXPECT_FALSE(e.style.text.small_caps);
    e.style.text.small_caps = true;
    for (const char* bad : {"small-caps all-small-caps", "normal small-caps", "none small-caps",
                            "ordinal ordinal", "fancy"}) {
        e.refused("font-variant", bad);
        EXPECT_TRUE(e.style.text.small_caps) << bad;
    }
    e.refused("font-variant-caps", "none");
    e.refused("font-variant-caps", "oldstyle-nums");
    e.parent.text.small_caps = false;
    e.ok("font-variant-caps", "inherit");
    EXPECT_FALSE(e.style.text.small_caps);
}

TEST(FontKerning, AutoNormalNone) {
    Element e;
    e.ok("font-kerning", "none");
    EXPECT_FALSE(e.style.text.kerning);
    e.refused("font-kerning", "off");
    EXPECT_FALSE(e.style.text.kerning);
    e.ok("font-kerning", "auto");
    EXPECT_TRUE(e.style.text.kerning);
    e.ok("font-kerning", "None");
    e.ok("font-kerning", "normal");
    EXPECT_TRUE(e.style.text.kerning);
}

std::string tag(const char (&t)[4]) { return std::string(t, 4); }

TEST(FontSettings, VariationsAreTagsAndNumbers) {
    Element e;
    e.ok("font-variation-settings", R"("wght" 700, 'wdth' 87.5,"slnt"-10)");
    const auto& v = e.style.text.variations;
    ASSERT_EQ(v.size(), 3u);
    EXPECT_EQ(tag(v[0].tag), "wght");
    EXPECT_EQ(v[0].value, 700);
    EXPECT_EQ(tag(v[1].tag), "wdth");
    EXPECT_EQ(v[1].value, 87.5);
    EXPECT_EQ(tag(v[2].tag), "slnt");
    EXPECT_EQ(v[2].value, -10);
    for (const char* bad :
         {R"("wght")", R"("wght" bold)", R"("wgh" 700)", R"("weight" 700)", R"(wght 700)",
          R"("wght" 700,)", R"("wght" 700 "wdth" 90)", R"("wght" 1 2)", ""}) {
        e.refused("font-variation-settings", bad);
        EXPECT_EQ(e.style.text.variations.size(), 3u) << bad;
    }
    e.ok("font-variation-settings", "normal");
    EXPECT_TRUE(e.style.text.variations.empty());
}

TEST(FontSettings, FeaturesAreTagsOnOrOff) {
    Element e;
    e.ok("font-feature-settings", R"("liga" 0, "smcp", 'dlig' on, "kern" off, "salt" 3, "ss01" 1)");
    const auto& f = e.style.text.features;
    ASSERT_EQ(f.size(), 6u);
    const std::pair<const char*, bool> want[] = {{"liga", false}, {"smcp", true}, {"dlig", true},
                                                 {"kern", false}, {"salt", true}, {"ss01", true}};
    for (std::size_t i = 0; i < 6; ++i) {
        EXPECT_EQ(tag(f[i].tag), want[i].first) << i;
        EXPECT_EQ(f[i].on, want[i].second) << i;
    }
    for (const char* bad : {R"("liga" -1)", R"("liga" 1.5)", R"("liga" yes)", R"("lig" 1)",
                            R"(liga 1)", R"("liga" 1,)", R"(, "liga")", R"("li\0a")", ""}) {
        e.refused("font-feature-settings", bad);
        EXPECT_EQ(e.style.text.features.size(), 6u) << bad;
    }
    e.parent.text.features = {FontFeature{{'k', 'e', 'r', 'n'}, false}};
    e.ok("font-feature-settings", "inherit");
    ASSERT_EQ(e.style.text.features.size(), 1u);
    EXPECT_EQ(tag(e.style.text.features[0].tag), "kern");
    e.ok("font-feature-settings", "normal");
    EXPECT_TRUE(e.style.text.features.empty());
}

TEST(FontSizeAdjust, NoneOrANonNegativeNumber) {
    Element e;
    e.ok("font-size-adjust", "0.5");
    EXPECT_EQ(e.style.text.font_size_adjust, 0.5);
    for (const char* bad : {"-0.5", "50%", "auto", ""}) {
        e.refused("font-size-adjust", bad);
        EXPECT_EQ(e.style.text.font_size_adjust, 0.5) << bad;
    }
    e.ok("font-size-adjust", "none");
    EXPECT_FALSE(e.style.text.font_size_adjust);
    e.ok("font-size-adjust", "0");
    EXPECT_EQ(e.style.text.font_size_adjust, 0.0);
}

TEST(FontShorthand, StyleWeightSizeLineHeightAndFamilies) {
    Element e;
    e.parent.font_size = 20;
    // Set first, to see the shorthand reset them.
    e.style.text.small_caps = true;
    e.style.text.font_stretch = 50;
    e.style.text.kerning = false;
    e.style.text.font_size_adjust = 0.5;
    e.style.text.features = {FontFeature{{'l', 'i', 'g', 'a'}, false}};
    e.style.text.variations = {FontVariation{{'w', 'g', 'h', 't'}, 300}};
    e.ok("font", "italic bold 12px/30px Georgia, serif");
    const TextState& t = e.style.text;
    EXPECT_EQ(t.font_style, FontStyle::Italic);
    EXPECT_EQ(t.font_weight, 700);
    EXPECT_EQ(e.style.font_size, 12);
    EXPECT_EQ(t.font_family, (Names{"Georgia", "serif"}));
    EXPECT_FALSE(t.small_caps);
    EXPECT_EQ(t.font_stretch, 100);
    EXPECT_TRUE(t.kerning);
    EXPECT_FALSE(t.font_size_adjust);
    EXPECT_TRUE(t.features.empty());
    EXPECT_TRUE(t.variations.empty());

    e.ok("font", R"(bold condensed 20px "Noto Sans")");
    EXPECT_EQ(t.font_style, FontStyle::Normal);
    EXPECT_EQ(t.font_weight, 700);
    EXPECT_EQ(t.font_stretch, 75);
    EXPECT_EQ(e.style.font_size, 20);
    EXPECT_EQ(t.font_family, Names{"Noto Sans"});

    // em against the parent's font size, as font-size's own.
    e.ok("font", R"(small-caps 1.2em "A B")");
    EXPECT_TRUE(t.small_caps);
    EXPECT_EQ(t.font_weight, 400);
    EXPECT_EQ(t.font_stretch, 100);
    EXPECT_DOUBLE_EQ(e.style.font_size, 24);
    EXPECT_EQ(t.font_family, Names{"A B"});
}

TEST(FontShorthand, EveryPrefixOrderAndForm) {
    Element e;
    e.parent.font_size = 10;
    e.parent.text.font_weight = 400;
    const TextState& t = e.style.text;
    e.ok("font", "condensed oblique 25deg 600 small-caps 150% / normal Times   New Roman");
    EXPECT_EQ(t.font_stretch, 75);
    EXPECT_EQ(t.font_style, FontStyle::Oblique);
    EXPECT_EQ(t.font_weight, 600);
    EXPECT_TRUE(t.small_caps);
    EXPECT_EQ(e.style.font_size, 15);
    EXPECT_EQ(t.font_family, Names{"Times New Roman"});
    e.ok("font", "normal normal normal normal larger/1.5 monospace");
    EXPECT_EQ(t.font_style, FontStyle::Normal);
    EXPECT_FALSE(t.small_caps);
    EXPECT_DOUBLE_EQ(e.style.font_size, 12);
    e.ok("font", "ITALIC Bolder x-large /120% 'X', Y");
    EXPECT_EQ(t.font_style, FontStyle::Italic);
    EXPECT_EQ(t.font_weight, 700);
    EXPECT_EQ(e.style.font_size, 24);
    EXPECT_EQ(t.font_family, (Names{"X", "Y"}));
    e.ok("font", "oblique 12px serif"); // 12px is not an angle: the size
    EXPECT_EQ(t.font_style, FontStyle::Oblique);
    EXPECT_EQ(e.style.font_size, 12);
}

TEST(FontShorthand, InvalidValuesChangeNothing) {
    Element e;
    e.ok("font", "italic 700 14px serif");
    const StyleState before = e.style;
    for (const char* bad : {"bold serif", "12px", "serif 12px", "italic italic 12px serif",
                            "bold bold 12px serif", "normal normal normal normal normal 12px serif",
                            "12px/ serif", "12px/-1 serif", "12px / bold serif", "-12px serif",
                            "12px serif,", "12px 'Unclosed", "oblique 100deg 12px serif",
                            "bold 12px serif 3", "inherit 12px serif", "12px inherit", ""}) {
        e.refused("font", bad);
        EXPECT_EQ(e.style.font_size, before.font_size) << bad;
        EXPECT_EQ(e.style.text.font_weight, 700) << bad;
        EXPECT_EQ(e.style.text.font_style, FontStyle::Italic) << bad;
        EXPECT_EQ(e.style.text.font_family, Names{"serif"}) << bad;
    }
}

TEST(FontShorthand, SystemFontsAndCssWideKeywords) {
    Element e;
    e.ok("font", "bold 14px serif");
    // A system font is valid; there is none to take, so nothing changes.
    for (const char* system :
         {"caption", "icon", "menu", "message-box", "small-caption", "status-bar", "Menu"}) {
        e.ok("font", system);
        EXPECT_EQ(e.style.text.font_weight, 700) << system;
        EXPECT_EQ(e.style.font_size, 14) << system;
    }
    e.parent.font_size = 30;
    e.parent.text.font_family = {"Parent"};
    e.parent.text.font_style = FontStyle::Oblique;
    e.parent.text.kerning = false;
    e.ok("font", "inherit");
    EXPECT_EQ(e.style.font_size, 30);
    EXPECT_EQ(e.style.text.font_family, Names{"Parent"});
    EXPECT_EQ(e.style.text.font_style, FontStyle::Oblique);
    EXPECT_EQ(e.style.text.font_weight, 400);
    EXPECT_FALSE(e.style.text.kerning);
    e.ok("font", "initial");
    EXPECT_EQ(e.style.font_size, 16);
    EXPECT_EQ(e.style.text.font_family, Names{"Times New Roman"});
    EXPECT_EQ(e.style.text.font_style, FontStyle::Normal);
    EXPECT_TRUE(e.style.text.kerning);
}

TEST(TextSpacing, NormalOrALengthInPx) {
    Element e;
    e.ctx.font_size = 20;
    for (const char* name : {"letter-spacing", "word-spacing"}) {
        const auto value = [&] {
            return std::string(name) == "letter-spacing" ? e.style.text.letter_spacing
                                                         : e.style.text.word_spacing;
        };
        const std::pair<const char*, double> valid[] = {
            {"2px", 2}, {"0.1em", 2},  {"10%", 2},    {"-1pt", -96.0 / 72},
            {"3", 3},   {"normal", 0}, {"Normal", 0}, {"1in", 96}};
        for (const auto& [text, want] : valid) {
            e.ok(name, text);
            EXPECT_DOUBLE_EQ(value(), want) << name << ": " << text;
        }
        for (const char* bad : {"wide", "2 px", "2furlongs", ""}) {
            e.refused(name, bad);
            EXPECT_EQ(value(), 96) << name << ": " << bad;
        }
    }
    e.parent.text.letter_spacing = 5;
    e.ok("letter-spacing", "inherit");
    EXPECT_EQ(e.style.text.letter_spacing, 5);
    e.ok("word-spacing", "initial");
    EXPECT_EQ(e.style.text.word_spacing, 0);
}

TEST(TextAlignment, AnchorAndDominantBaseline) {
    Element e;
    const std::pair<const char*, TextAnchor> anchors[] = {{"middle", TextAnchor::Middle},
                                                          {"end", TextAnchor::End},
                                                          {"start", TextAnchor::Start},
                                                          {"END", TextAnchor::End}};
    for (const auto& [text, want] : anchors) {
        e.ok("text-anchor", text);
        EXPECT_EQ(e.style.text.anchor, want) << text;
    }
    e.refused("text-anchor", "center");
    EXPECT_EQ(e.style.text.anchor, TextAnchor::End);
    e.parent.text.anchor = TextAnchor::Middle;
    e.ok("text-anchor", "inherit");
    EXPECT_EQ(e.style.text.anchor, TextAnchor::Middle);

    const std::pair<const char*, Baseline> baselines[] = {
        {"alphabetic", Baseline::Alphabetic},
        {"ideographic", Baseline::Ideographic},
        {"middle", Baseline::Middle},
        {"central", Baseline::Central},
        {"mathematical", Baseline::Mathematical},
        {"hanging", Baseline::Hanging},
        {"text-before-edge", Baseline::TextBeforeEdge},
        {"text-after-edge", Baseline::TextAfterEdge},
        {"text-top", Baseline::TextBeforeEdge},
        {"text-bottom", Baseline::TextAfterEdge},
        {"use-script", Baseline::Auto},
        {"hanging", Baseline::Hanging},
        {"no-change", Baseline::Auto},
        {"hanging", Baseline::Hanging},
        {"reset-size", Baseline::Auto},
        {"Central", Baseline::Central},
        {"auto", Baseline::Auto}};
    for (const auto& [text, want] : baselines) {
        e.ok("dominant-baseline", text);
        EXPECT_EQ(e.style.text.dominant_baseline, want) << text;
    }
    for (const char* bad : {"baseline", "before-edge", "top", "center", ""}) {
        e.refused("dominant-baseline", bad);
        EXPECT_EQ(e.style.text.dominant_baseline, Baseline::Auto) << bad;
    }
    e.parent.text.dominant_baseline = Baseline::Hanging;
    e.ok("dominant-baseline", "inherit");
    EXPECT_EQ(e.style.text.dominant_baseline, Baseline::Hanging);
}

TEST(TextAlignment, AlignmentBaselineIsNotInherited) {
    Element e;
    const std::pair<const char*, Baseline> valid[] = {
        {"baseline", Baseline::Auto},
        {"before-edge", Baseline::TextBeforeEdge},
        {"auto", Baseline::Auto},
        {"text-before-edge", Baseline::TextBeforeEdge},
        {"after-edge", Baseline::TextAfterEdge},
        {"text-after-edge", Baseline::TextAfterEdge},
        {"alphabetic", Baseline::Alphabetic},
        {"ideographic", Baseline::Ideographic},
        {"middle", Baseline::Middle},
        {"central", Baseline::Central},
        {"mathematical", Baseline::Mathematical},
        {"hanging", Baseline::Hanging},
        {"top", Baseline::TextBeforeEdge},
        {"bottom", Baseline::TextAfterEdge},
        {"center", Baseline::Central}};
    for (const auto& [text, want] : valid) {
        e.ok("alignment-baseline", text);
        EXPECT_EQ(e.props.text.alignment_baseline, want) << text;
    }
    e.refused("alignment-baseline", "text-top");
    EXPECT_EQ(e.props.text.alignment_baseline, Baseline::Central);
    e.ok("alignment-baseline", "inherit"); // the parent's is not at hand: the initial value
    EXPECT_EQ(e.props.text.alignment_baseline, Baseline::Auto);
}

TEST(TextAlignment, BaselineShift) {
    Element e;
    e.ctx.font_size = 20;
    using K = BaselineShift::Kind;
    const std::tuple<const char*, K, double> valid[] = {
        {"sub", K::Sub, 0},     {"super", K::Super, 0},     {"baseline", K::Baseline, 0},
        {"5px", K::Length, 5},  {"-0.5em", K::Length, -10}, {"50%", K::Length, 10},
        {"SUPER", K::Super, 0}, {"3", K::Length, 3}};
    for (const auto& [text, kind, px] : valid) {
        e.ok("baseline-shift", text);
        EXPECT_EQ(e.props.text.baseline_shift.kind, kind) << text;
        EXPECT_DOUBLE_EQ(e.props.text.baseline_shift.px, px) << text;
    }
    for (const char* bad : {"up", "sub super", "5 px", ""}) {
        e.refused("baseline-shift", bad);
        EXPECT_EQ(e.props.text.baseline_shift.px, 3) << bad;
    }
    e.ok("baseline-shift", "initial");
    EXPECT_EQ(e.props.text.baseline_shift.kind, K::Baseline);
}

TEST(TextDirection, WritingModeDirectionBidiAndOrientation) {
    Element e;
    const std::pair<const char*, WritingMode> modes[] = {
        {"vertical-rl", WritingMode::VerticalRl}, {"horizontal-tb", WritingMode::HorizontalTb},
        {"tb-rl", WritingMode::VerticalRl},       {"lr-tb", WritingMode::HorizontalTb},
        {"tb", WritingMode::VerticalRl},          {"lr", WritingMode::HorizontalTb},
        {"vertical-lr", WritingMode::VerticalLr}, {"rl-tb", WritingMode::HorizontalTb},
        {"vertical-lr", WritingMode::VerticalLr}, {"rl", WritingMode::HorizontalTb}};
    for (const auto& [text, want] : modes) {
        e.ok("writing-mode", text);
        EXPECT_EQ(e.style.text.writing_mode, want) << text;
    }
    e.refused("writing-mode", "sideways");
    EXPECT_EQ(e.style.text.writing_mode, WritingMode::HorizontalTb);
    e.parent.text.writing_mode = WritingMode::VerticalLr;
    e.ok("writing-mode", "inherit");
    EXPECT_EQ(e.style.text.writing_mode, WritingMode::VerticalLr);

    e.ok("direction", "rtl");
    EXPECT_TRUE(e.style.text.rtl);
    e.refused("direction", "rtl ltr");
    EXPECT_TRUE(e.style.text.rtl);
    e.ok("direction", "LTR");
    EXPECT_FALSE(e.style.text.rtl);

    const std::pair<const char*, UnicodeBidi> bidi[] = {
        {"embed", UnicodeBidi::Embed},
        {"isolate", UnicodeBidi::Isolate},
        {"bidi-override", UnicodeBidi::BidiOverride},
        {"isolate-override", UnicodeBidi::IsolateOverride},
        {"plaintext", UnicodeBidi::Plaintext},
        {"normal", UnicodeBidi::Normal}};
    for (const auto& [text, want] : bidi) {
        e.ok("unicode-bidi", text);
        EXPECT_EQ(e.props.text.unicode_bidi, want) << text;
    }
    e.ok("unicode-bidi", "embed");
    e.refused("unicode-bidi", "override");
    EXPECT_EQ(e.props.text.unicode_bidi, UnicodeBidi::Embed);

    const std::pair<const char*, int> orientations[] = {
        {"90", 90}, {"0", 0}, {"90deg", 90}, {"auto", -1}, {"0deg", 0}};
    for (const auto& [text, want] : orientations) {
        e.ok("glyph-orientation-vertical", text);
        EXPECT_EQ(e.style.text.glyph_orientation_vertical, want) << text;
    }
    for (const char* bad : {"180", "45deg", "270", "90 deg", ""}) {
        e.refused("glyph-orientation-vertical", bad);
        EXPECT_EQ(e.style.text.glyph_orientation_vertical, 0) << bad;
    }
    e.ok("glyph-orientation-vertical", "initial");
    EXPECT_EQ(e.style.text.glyph_orientation_vertical, -1);
}

TEST(TextDecoration, LinesAndTheShorthandsOtherParts) {
    Element e;
    const TextDecorationLines& d = e.props.text.decoration;
    e.ok("text-decoration", "underline");
    EXPECT_TRUE(d.underline);
    EXPECT_FALSE(d.overline || d.line_through);
    e.ok("text-decoration-line", "overline LINE-THROUGH blink");
    EXPECT_TRUE(d.overline && d.line_through);
    EXPECT_FALSE(d.underline);
    e.ok("text-decoration", "none");
    EXPECT_FALSE(d.any());
    // The shorthand's style, color and thickness are valid and dropped.
    e.ok("text-decoration", "underline wavy rgb(255, 0, 0) 2px");
    EXPECT_TRUE(d.underline);
    e.ok("text-decoration", "red line-through dotted from-font");
    EXPECT_TRUE(d.line_through);
    EXPECT_FALSE(d.underline);
    e.ok("text-decoration", "none currentColor");
    EXPECT_FALSE(d.any());
    e.ok("text-decoration", "overline underline");
    for (const char* bad : {"underline underline", "none underline", "none none", "squiggly",
                            "underline solid dotted", "underline red blue", ""}) {
        e.refused("text-decoration", bad);
        EXPECT_TRUE(d.overline && d.underline) << bad;
    }
    for (const char* bad : {"underline red", "underline solid", "red"}) {
        e.refused("text-decoration-line", bad);
        EXPECT_TRUE(d.overline && d.underline) << bad;
    }
    e.ok("text-decoration", "inherit"); // not inherited: the initial value
    EXPECT_FALSE(d.any());
}

TEST(TextSpaces, WhiteSpaceAndTextRendering) {
    Element e;
    const std::pair<const char*, bool> valid[] = {
        {"pre", true},          {"normal", false},   {"pre-wrap", true}, {"nowrap", false},
        {"break-spaces", true}, {"pre-line", false}, {"PRE", true}};
    for (const auto& [text, want] : valid) {
        e.ok("white-space", text);
        EXPECT_EQ(e.style.text.preserve_spaces, want) << text;
    }
    e.refused("white-space", "preserve");
    EXPECT_TRUE(e.style.text.preserve_spaces);
    e.parent.text.preserve_spaces = false;
    e.ok("white-space", "inherit");
    EXPECT_FALSE(e.style.text.preserve_spaces);
    for (const char* v :
         {"auto", "optimizeSpeed", "optimizeLegibility", "geometricPrecision", "inherit"})
        e.ok("text-rendering", v);
    e.refused("text-rendering", "crispEdges");
}

// Through the reader: the font shorthand is applied before the element's
// lengths (it sets font-size), and an invalid text property is one warning.
const Shape& shape_at(const Scene& s, std::size_t i) {
    return std::get<Shape>(s.root.children.at(i).item);
}

TEST(TextProperties, ThroughTheReader) {
    const SvgResult r = parse_svg(R"svg(<svg width="200" height="100" font-size="10">
        <rect width="2em" height="1em" style="font: bold 2em/3 serif"/>
        <g style="font: italic 150% 'A', B"><rect width="1em" height="1em"/></g>
        <rect width="1em" height="1em" font-weight="heavy" style="font: bold"/>
        <rect width="1em" height="1em" font="20px serif"/>
        </svg>)svg",
                                  "t.svg");
    ASSERT_TRUE(r.scene) << r.error;
    EXPECT_NEAR(shape_at(*r.scene, 0).path.bounds().width(), 40, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 0).path.bounds().height(), 20, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 1).path.bounds().width(), 15, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 2).path.bounds().width(), 10, 1e-12);
    EXPECT_NEAR(shape_at(*r.scene, 3).path.bounds().width(), 10, 1e-12)
        << "font is no presentation attribute (SVG 2, 6.6): ignored";
    // One warning each, in the order the attributes are written.
    ASSERT_EQ(r.warnings.size(), 2u);
    EXPECT_NE(r.warnings[0].text().find("property font-weight: 'heavy'"), std::string::npos)
        << r.warnings[0].text();
    EXPECT_NE(r.warnings[1].text().find("style: property font: 'bold'"), std::string::npos)
        << r.warnings[1].text();
}

} // namespace
} // namespace casteljau
