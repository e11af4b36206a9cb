// The font properties (svg/text_properties.h): CSS Fonts 4's font-family
// (2.1), font-weight (2.2), font-stretch (2.3), font-style (2.4),
// font-size-adjust (2.6), the font shorthand (2.7), font-kerning,
// font-variant and font-variant-caps (6.4, 6.11), font-feature-settings
// (6.12) and font-variation-settings (7.2), as SVG 2, 11.10 lists them, with
// the CSS-wide keywords of CSS Cascade 4, 7.3 (inherit, initial, unset).
// font-size itself is svg/style.cpp's. The other text properties are
// svg/text_properties.cpp's, whose apply_text_property hands these here.
//
// Family names and feature tags are read with CSS Syntax 3's tokens
// (4.3: strings, identifiers and their escapes), so that a quoted name may
// hold commas and an unquoted one is checked as CSS checks it.
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/text_property_parsing.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/text_properties.h"
#include "casteljau/text/utf8.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <utility>

namespace casteljau {

namespace {

using svg_detail::iequals;
using svg_detail::trim;
using svg_detail::text_parsing::bad;
using svg_detail::text_parsing::css_wide;
using svg_detail::text_parsing::is_space;
using svg_detail::text_parsing::lookup;
using svg_detail::text_parsing::Setter;
using svg_detail::text_parsing::skip_spaces;
using svg_detail::text_parsing::Wide;
using svg_detail::text_parsing::words;

// The word at i (up to whitespace or one of `stops`), i moved past it.
std::string_view next_word(std::string_view v, std::size_t& i, std::string_view stops = {}) {
    skip_spaces(v, i);
    const std::size_t start = i;
    while (i < v.size() && !is_space(v[i]) && stops.find(v[i]) == stops.npos) ++i;
    return v.substr(start, i - start);
}

// --- CSS Syntax 3 tokens: strings and identifiers ---

// Whether a backslash at i starts an escape (4.3.8): not before a newline
// or the end.
bool valid_escape(std::string_view v, std::size_t i) {
    return i + 1 < v.size() && v[i] == '\\' && v[i + 1] != '\n' && v[i + 1] != '\r' &&
           v[i + 1] != '\f';
}

// The escape after the backslash at i - 1 (4.3.7): up to six hex digits
// and one whitespace after them, or the next character as itself.
void consume_escape(std::string_view v, std::size_t& i, std::string& out) {
    char32_t c = 0;
    std::size_t digits = 0;
    for (; i < v.size() && digits < 6 && std::isxdigit(static_cast<unsigned char>(v[i]));
         ++i, ++digits)
        c = c * 16 + char32_t(std::isdigit(static_cast<unsigned char>(v[i]))
                                  ? v[i] - '0'
                                  : std::tolower(static_cast<unsigned char>(v[i])) - 'a' + 10);
    if (digits == 0) {
        out += v[i++]; // a non-ASCII character's first byte: its others follow as themselves
        return;
    }
    if (i < v.size() && is_space(v[i])) ++i;
    if (c == 0 || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) c = 0xFFFD;
    append_utf8(out, c);
}

// A string token at i (4.3.5), its quotes removed; nullopt when it is not
// closed or breaks a line.
std::optional<std::string> consume_string(std::string_view v, std::size_t& i) {
    const char quote = v[i++];
    std::string out;
    while (i < v.size() && v[i] != quote) {
        if (v[i] == '\n' || v[i] == '\r' || v[i] == '\f') return std::nullopt;
        if (v[i] != '\\') {
            out += v[i++];
        } else if (++i < v.size() && (v[i] == '\n' || v[i] == '\r' || v[i] == '\f')) {
            ++i; // an escaped newline continues the string
        } else if (i < v.size()) {
            consume_escape(v, i, out);
        }
    }
    if (i == v.size()) return std::nullopt;
    ++i;
    return out;
}

bool name_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}

bool name_char(char c) {
    return name_start(c) || c == '-' || std::isdigit(static_cast<unsigned char>(c));
}

// Whether an identifier starts at i (4.3.9).
bool starts_ident(std::string_view v, std::size_t i) {
    if (i >= v.size()) return false;
    if (v[i] == '-')
        return i + 1 < v.size() &&
               (name_start(v[i + 1]) || v[i + 1] == '-' || valid_escape(v, i + 1));
    return name_start(v[i]) || valid_escape(v, i);
}

// An identifier at i (4.3.11), escapes decoded; nullopt, and i unmoved,
// when none starts there.
std::optional<std::string> consume_ident(std::string_view v, std::size_t& i) {
    if (!starts_ident(v, i)) return std::nullopt;
    std::string out;
    while (i < v.size()) {
        if (name_char(v[i])) {
            out += v[i++];
        } else if (valid_escape(v, i)) {
            ++i;
            consume_escape(v, i, out);
        } else {
            break;
        }
    }
    return out;
}

// --- Fonts ---

// One family name at i (CSS Fonts 4, 2.1): a string, or identifiers
// joined by single spaces; the generic families in lower case; nullopt for
// none or for a CSS-wide or reserved keyword standing alone.
std::optional<std::string> family_name(std::string_view v, std::size_t& i) {
    skip_spaces(v, i);
    if (i < v.size() && (v[i] == '"' || v[i] == '\'')) {
        auto name = consume_string(v, i);
        skip_spaces(v, i);
        return name;
    }
    std::string name;
    int count = 0;
    while (const std::optional<std::string> id = consume_ident(v, i)) {
        if (count++ > 0) name += ' '; // however much whitespace was between
        name += *id;
        skip_spaces(v, i);
    }
    if (count == 0) return std::nullopt;
    if (count > 1) return name;
    for (const char* reserved :
         {"inherit", "initial", "unset", "default", "revert", "revert-layer"})
        if (iequals(name, reserved)) return std::nullopt;
    for (const char* generic :
         {"serif", "sans-serif", "cursive", "fantasy", "monospace", "system-ui", "emoji", "math",
          "fangsong", "ui-serif", "ui-sans-serif", "ui-monospace", "ui-rounded"})
        if (iequals(name, generic)) return std::string(generic);
    return name;
}

// An angle (CSS Values 3, 7.1) in degrees; a unit is required.
std::optional<double> parse_angle(std::string_view v) {
    std::string_view unit;
    const auto n = parse_number(v, &unit);
    if (!n) return std::nullopt;
    const auto k = lookup<double>(
        unit, {{"deg", 1.0}, {"grad", 0.9}, {"rad", 180 / std::numbers::pi}, {"turn", 360.0}});
    if (!k) return std::nullopt;
    return *n * *k;
}

// An oblique angle: from -90 to 90 degrees (2.4).
bool oblique_angle(std::string_view v) {
    const auto a = parse_angle(v);
    return a && std::abs(*a) <= 90;
}

// font-style (2.4): normal, italic, or oblique with an optional angle (any
// angle is an oblique face: fonts are matched by style, not by slant).
std::optional<FontStyle> parse_font_style(std::string_view v) {
    std::size_t i = 0;
    const std::string_view word = next_word(v, i);
    const std::string_view angle = next_word(v, i);
    if (!trim(v.substr(i)).empty()) return std::nullopt;
    if (iequals(word, "oblique") && (angle.empty() || oblique_angle(angle)))
        return FontStyle::Oblique;
    if (!angle.empty()) return std::nullopt;
    return lookup<FontStyle>(word, {{"normal", FontStyle::Normal}, {"italic", FontStyle::Italic}});
}

// font-stretch's keywords (2.3), the fractional ones truncated.
std::optional<int> stretch_keyword(std::string_view v) {
    return lookup<int>(v, {{"ultra-condensed", 50},
                           {"extra-condensed", 62},
                           {"condensed", 75},
                           {"semi-condensed", 87},
                           {"normal", 100},
                           {"semi-expanded", 112},
                           {"expanded", 125},
                           {"extra-expanded", 150},
                           {"ultra-expanded", 200}});
}

// font-stretch: a keyword or a non-negative percentage. A percentage is
// truncated as the keywords are (62.5% is extra-condensed) and clamped to
// the 50% to 200% of font matching: no face is narrower or wider, so a
// value beyond picks the same face as the limit.
std::optional<int> parse_font_stretch(std::string_view v) {
    if (const auto k = stretch_keyword(v)) return k;
    std::string_view unit;
    const auto n = parse_number(v, &unit);
    if (!n || unit != "%" || *n < 0) return std::nullopt;
    return int(std::clamp(*n, 50.0, 200.0));
}

// font-variant-caps (6.4): whether the value asks for small capitals.
// The ones that turn capitals into small ones too (all-small-caps, ...)
// are small-caps here; titling-caps has nothing to do with small ones.
std::optional<bool> caps_value(std::string_view v) {
    return lookup<bool>(v, {{"normal", false},
                            {"small-caps", true},
                            {"all-small-caps", true},
                            {"petite-caps", true},
                            {"all-petite-caps", true},
                            {"unicase", true},
                            {"titling-caps", false}});
}

// Whether a word is a value of another font-variant subproperty
// (ligatures, position, numeric, east-asian, emoji): valid in the
// font-variant shorthand, and ignored (their features are not asked for).
bool other_variant_word(std::string_view w) {
    for (const char* k : {"common-ligatures",
                          "no-common-ligatures",
                          "discretionary-ligatures",
                          "no-discretionary-ligatures",
                          "historical-ligatures",
                          "no-historical-ligatures",
                          "contextual",
                          "no-contextual",
                          "sub",
                          "super",
                          "lining-nums",
                          "oldstyle-nums",
                          "proportional-nums",
                          "tabular-nums",
                          "diagonal-fractions",
                          "stacked-fractions",
                          "ordinal",
                          "slashed-zero",
                          "jis78",
                          "jis83",
                          "jis90",
                          "jis04",
                          "simplified",
                          "traditional",
                          "full-width",
                          "proportional-width",
                          "ruby",
                          "historical-forms",
                          "text",
                          "emoji",
                          "unicode"})
        if (iequals(w, k)) return true;
    return false;
}

// font-variant (6.11): normal, none, or values of its subproperties, each
// at most once and one of them for the caps; only the caps are kept.
std::optional<bool> parse_font_variant(std::string_view v) {
    if (iequals(v, "normal") || iequals(v, "none")) return false;
    const std::vector<std::string_view> ws = words(v);
    std::optional<bool> caps;
    for (const std::string_view w : ws) {
        if (std::count_if(ws.begin(), ws.end(), [&](auto o) { return iequals(o, w); }) > 1)
            return std::nullopt;
        const auto c = caps_value(w);
        if (c && !caps && !iequals(w, "normal"))
            caps = c;
        else if (!other_variant_word(w))
            return std::nullopt;
    }
    if (ws.empty()) return std::nullopt;
    return caps.value_or(false);
}

// A feature or axis tag (6.12, 7.2): a string of four characters from
// U+20 to U+7E, at i.
std::optional<std::array<char, 4>> parse_tag(std::string_view v, std::size_t& i) {
    skip_spaces(v, i);
    if (i == v.size() || (v[i] != '"' && v[i] != '\'')) return std::nullopt;
    const auto s = consume_string(v, i);
    if (!s || s->size() != 4) return std::nullopt;
    std::array<char, 4> tag{};
    for (std::size_t k = 0; k < 4; ++k) {
        if ((*s)[k] < 0x20 || (*s)[k] > 0x7E) return std::nullopt;
        tag[k] = (*s)[k];
    }
    return tag;
}

// A comma-separated list of a tag and a value after it: `item(tag, value)`
// for each, in order; false when malformed or when `item` says so.
template <class F>
bool tag_list(std::string_view v, F item) {
    for (std::size_t i = 0;;) {
        const auto tag = parse_tag(v, i);
        if (!tag) return false;
        const std::size_t end = std::min(v.find(',', i), v.size());
        if (!item(*tag, trim(v.substr(i, end - i)))) return false;
        if (end == v.size()) return true;
        i = end + 1;
    }
}

// font-feature-settings (6.12): normal, or tags each with on, off, or a
// non-negative integer (on when omitted; above 1, an alternate's index:
// on).
std::optional<std::vector<FontFeature>> parse_features(std::string_view v) {
    std::vector<FontFeature> out;
    if (iequals(v, "normal")) return out;
    const bool ok = tag_list(v, [&](const std::array<char, 4>& tag, std::string_view value) {
        FontFeature f;
        std::copy(tag.begin(), tag.end(), f.tag);
        if (value.empty() || iequals(value, "on"))
            f.on = true;
        else if (iequals(value, "off"))
            f.on = false;
        else if (value.find_first_not_of("+0123456789") == value.npos && parse_number(value))
            f.on = *parse_number(value) != 0;
        else
            return false;
        out.push_back(f);
        return true;
    });
    return ok ? std::optional(out) : std::nullopt;
}

// font-variation-settings (7.2): normal, or tags each with a number.
std::optional<std::vector<FontVariation>> parse_variations(std::string_view v) {
    std::vector<FontVariation> out;
    if (iequals(v, "normal")) return out;
    const bool ok = tag_list(v, [&](const std::array<char, 4>& tag, std::string_view value) {
        const auto n = parse_number(value);
        if (!n) return false;
        FontVariation f;
        std::copy(tag.begin(), tag.end(), f.tag);
        f.value = *n;
        out.push_back(f);
        return true;
    });
    return ok ? std::optional(out) : std::nullopt;
}

// font-size-adjust (2.6): none, or a non-negative number.
std::optional<std::optional<double>> parse_size_adjust(std::string_view v) {
    if (iequals(v, "none")) return std::optional<double>();
    const auto n = parse_number(v);
    if (!n || *n < 0) return std::nullopt;
    return n;
}

// The subproperties the font shorthand sets or resets (2.7): all but
// font-size, which is StyleState's.
void copy_font(const TextState& from, TextState& to) {
    to.font_family = from.font_family;
    to.font_weight = from.font_weight;
    to.font_style = from.font_style;
    to.font_stretch = from.font_stretch;
    to.small_caps = from.small_caps;
    to.kerning = from.kerning;
    to.variations = from.variations;
    to.features = from.features;
    to.font_size_adjust = from.font_size_adjust;
}

// One word of the font shorthand before the size: a style (an oblique's
// angle taken from after it), small-caps, a weight, a width keyword, or
// normal for any of them; each at most once. False when it is none: the
// size, then.
bool font_prefix_word(std::string_view w, std::string_view v, std::size_t& i, int parent_weight,
                      TextState& font, std::array<bool, 4>& given) {
    if (iequals(w, "normal")) return true;
    if (!given[0] && (iequals(w, "italic") || iequals(w, "oblique"))) {
        font.font_style = iequals(w, "italic") ? FontStyle::Italic : FontStyle::Oblique;
        std::size_t after = i;
        if (font.font_style == FontStyle::Oblique && oblique_angle(next_word(v, after))) i = after;
        return given[0] = true;
    }
    if (!given[1] && iequals(w, "small-caps")) return font.small_caps = given[1] = true;
    if (const auto weight = parse_font_weight(w, parent_weight); weight && !given[2]) {
        font.font_weight = *weight;
        return given[2] = true;
    }
    if (const auto stretch = stretch_keyword(w); stretch && !given[3]) {
        font.font_stretch = *stretch;
        return given[3] = true;
    }
    return false;
}

// The font shorthand (2.7): [style || small-caps || weight || width]? size
// [/ line-height]? family-list, into `font` (the other subproperties at
// their initial values) and `size`. line-height is checked and dropped:
// SVG text does not use it.
bool parse_font(std::string_view v, const StyleState& parent, const LengthContext& ctx,
                TextState& font, double& size) {
    std::size_t i = 0;
    std::array<bool, 4> given{};
    std::string_view w = next_word(v, i, "/");
    for (int n = 0; n < 4 && font_prefix_word(w, v, i, parent.text.font_weight, font, given); ++n)
        w = next_word(v, i, "/");
    const auto font_size = parse_font_size(w, parent.font_size, ctx);
    if (!font_size) return false;
    size = *font_size;
    skip_spaces(v, i);
    if (i < v.size() && v[i] == '/') {
        const std::string_view line_height = next_word(v, ++i);
        const auto length = parse_length(line_height, 0, ctx); // a number, a length or a %
        if (!iequals(line_height, "normal") && !(length && *length >= 0)) return false;
    }
    const auto family = parse_font_family(v.substr(i));
    if (!family) return false;
    font.font_family = *family;
    return true;
}

std::string apply_font_shorthand(std::string_view value, const StyleState& parent,
                                 StyleState& style, const LengthContext& ctx) {
    // A system font (caption, ...): valid, but there are no system fonts
    // to take it from, so nothing changes.
    for (const char* system :
         {"caption", "icon", "menu", "message-box", "small-caption", "status-bar"})
        if (iequals(value, system)) return "";
    TextState font;
    double size = 16; // medium: the initial value
    switch (css_wide(value)) {
    case Wide::Inherit:
        copy_font(parent.text, font);
        size = parent.font_size;
        break;
    case Wide::Initial:
        break;
    case Wide::None:
        if (!parse_font(value, parent, ctx, font, size))
            return bad("font", value,
                       "a font: [style variant weight stretch] size[/line-height] families");
    }
    // Assigned only now: parent and style are one object at the root.
    copy_font(font, style.text);
    style.font_size = size;
    return "";
}

} // namespace

// font-weight (2.2): a keyword, bolder or lighter by the table of 2.2 from
// the parent's weight, or a number from 1 to 1000 (rounded: the computed
// weight is kept as an integer).
std::optional<int> parse_font_weight(std::string_view v, int parent) {
    if (iequals(v, "normal")) return 400;
    if (iequals(v, "bold")) return 700;
    if (iequals(v, "bolder"))
        return parent < 350 ? 400 : parent < 550 ? 700 : std::max(parent, 900);
    if (iequals(v, "lighter"))
        return parent < 100 ? parent : parent < 550 ? 100 : parent < 750 ? 400 : 700;
    const auto n = parse_number(v);
    if (!n || *n < 1 || *n > 1000) return std::nullopt;
    return int(std::lround(*n));
}

std::optional<std::vector<std::string>> parse_font_family(std::string_view v) {
    std::vector<std::string> names;
    for (std::size_t i = 0;; ++i) {
        auto name = family_name(v, i);
        if (!name) return std::nullopt;
        if (!name->empty()) names.push_back(std::move(*name)); // "": no family to look for
        if (i == v.size()) return names;
        if (v[i] != ',') return std::nullopt;
    }
}

namespace svg_detail {

std::optional<std::string> apply_font_property(std::string_view name, std::string_view value,
                                               const StyleState& parent, StyleState& style,
                                               const LengthContext& ctx) {
    const Setter set{name, value};
    const TextState initial;
    TextState& t = style.text;
    const TextState& p = parent.text;
    if (name == "font") return apply_font_shorthand(value, parent, style, ctx);
    if (name == "font-family")
        return set(t.font_family, p.font_family, initial.font_family, parse_font_family(value),
                   "a list of font families");
    if (name == "font-weight")
        return set(t.font_weight, p.font_weight, initial.font_weight,
                   parse_font_weight(value, p.font_weight),
                   "normal, bold, bolder, lighter or a number from 1 to 1000");
    if (name == "font-style")
        return set(t.font_style, p.font_style, initial.font_style, parse_font_style(value),
                   "normal, italic or oblique [angle]");
    if (name == "font-stretch")
        return set(t.font_stretch, p.font_stretch, initial.font_stretch, parse_font_stretch(value),
                   "a font-stretch keyword or a non-negative percentage");
    if (name == "font-variant")
        return set(t.small_caps, p.small_caps, initial.small_caps, parse_font_variant(value),
                   "a font variant");
    if (name == "font-variant-caps")
        return set(t.small_caps, p.small_caps, initial.small_caps, caps_value(value),
                   "a font-variant-caps value");
    if (name == "font-kerning")
        return set(t.kerning, p.kerning, initial.kerning,
                   lookup<bool>(value, {{"auto", true}, {"normal", true}, {"none", false}}),
                   "auto, normal or none");
    if (name == "font-variation-settings")
        return set(t.variations, p.variations, initial.variations, parse_variations(value),
                   "normal or a list of \"tag\" number");
    if (name == "font-feature-settings")
        return set(t.features, p.features, initial.features, parse_features(value),
                   "normal or a list of \"tag\" [on, off or an integer]");
    if (name == "font-size-adjust")
        return set(t.font_size_adjust, p.font_size_adjust, initial.font_size_adjust,
                   parse_size_adjust(value), "none or a non-negative number");
    return std::nullopt;
}

} // namespace svg_detail

} // namespace casteljau
