// The text properties (svg/text_properties.h): SVG 2, 11.10; CSS Fonts 4
// (font-family 2.1, font-weight 2.2, font-stretch 2.3, font-style 2.4,
// font-size-adjust 2.6, the font shorthand 2.7, font-kerning, font-variant
// and font-variant-caps, font-feature-settings, font-variation-settings);
// CSS Text 3 (white-space, letter-spacing, word-spacing); CSS Text
// Decoration 3 (text-decoration and text-decoration-line, 2); CSS Inline 3
// (dominant-baseline, alignment-baseline, baseline-shift); CSS Writing
// Modes 3 (direction, unicode-bidi, writing-mode with SVG 1.1's values);
// SVG 1.1, 10.7.3 (glyph-orientation-vertical); the CSS-wide keywords of
// CSS Cascade 4, 7.3 (inherit, initial, unset).
//
// Family names and feature tags are read with CSS Syntax 3's tokens
// (4.3: strings, identifiers and their escapes), so that a quoted name may
// hold commas and an unquoted one is checked as CSS checks it.
#include "casteljau/svg/text_properties.h"

#include "casteljau/svg/color.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/style.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <utility>

namespace casteljau {

namespace {

using svg_detail::iequals;
using svg_detail::trim;

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)); }

void skip_spaces(std::string_view v, std::size_t& i) {
    while (i < v.size() && is_space(v[i])) ++i;
}

// The word at i (up to whitespace or one of `stops`), i moved past it.
std::string_view next_word(std::string_view v, std::size_t& i, std::string_view stops = {}) {
    skip_spaces(v, i);
    const std::size_t start = i;
    while (i < v.size() && !is_space(v[i]) && stops.find(v[i]) == stops.npos) ++i;
    return v.substr(start, i - start);
}

// The whitespace-separated words of a value, a parenthesised group kept
// whole (a color as "rgb(1, 2, 3)").
std::vector<std::string_view> words(std::string_view v) {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; skip_spaces(v, i), i < v.size();) {
        const std::size_t start = i;
        for (int depth = 0; i < v.size() && (depth > 0 || !is_space(v[i])); ++i)
            depth += v[i] == '(' ? 1 : v[i] == ')' ? -1 : 0;
        out.push_back(v.substr(start, i - start));
    }
    return out;
}

std::string bad(std::string_view name, std::string_view value, const char* expected) {
    return "property " + std::string(name) + ": '" + std::string(value) + "' is not " + expected;
}

// The enumerator a keyword names, if it is one of `words`; CSS keywords
// are ASCII case-insensitive.
template <class E>
std::optional<E> lookup(std::string_view value,
                        std::initializer_list<std::pair<std::string_view, E>> words) {
    for (const auto& [word, e] : words)
        if (iequals(value, word)) return e;
    return std::nullopt;
}

// The CSS-wide keywords: unset is inherit for an inherited property and
// initial for the others, which is what inherit means here for those (see
// Setter), so it is taken as inherit.
enum class Wide { None, Inherit, Initial };

Wide css_wide(std::string_view value) {
    if (iequals(value, "inherit") || iequals(value, "unset")) return Wide::Inherit;
    return iequals(value, "initial") ? Wide::Initial : Wide::None;
}

// Applies one value the way apply_property does: a CSS-wide keyword takes
// `inherited` or `initial`, a value that parses is taken, anything else is
// an error. For a property that is not inherited, `inherited` is its
// initial value: the parent's is not at hand in TextProps.
struct Setter {
    std::string_view name, value;

    template <class T, class Parsed>
    std::string operator()(T& target, const T& inherited, const T& initial, const Parsed& parsed,
                           const char* expected) const {
        switch (css_wide(value)) {
        case Wide::Inherit:
            return target = inherited, "";
        case Wide::Initial:
            return target = initial, "";
        case Wide::None:
            break;
        }
        if (!parsed) return bad(name, value, expected);
        target = *parsed;
        return "";
    }
};

// --- CSS Syntax 3 tokens: strings and identifiers ---

void append_utf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += char(c);
    } else if (c < 0x800) {
        out += char(0xC0 | (c >> 6));
        out += char(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += char(0xE0 | (c >> 12));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
    } else {
        out += char(0xF0 | (c >> 18));
        out += char(0x80 | ((c >> 12) & 0x3F));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
    }
}

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

// --- Spacing, alignment, direction ---

// letter-spacing, word-spacing (CSS Text 3): normal (0) or a length, em
// and % of the element's font size.
std::optional<double> parse_spacing(std::string_view v, const LengthContext& ctx) {
    if (iequals(v, "normal")) return 0.0;
    return parse_length(v, ctx.font_size, ctx);
}

// baseline-shift (SVG 1.1, 10.9.2; CSS Inline 3): baseline, sub, super,
// or a length, % of the font size (SVG's line-height); positive is up.
std::optional<BaselineShift> parse_baseline_shift(std::string_view v, const LengthContext& ctx) {
    using K = BaselineShift::Kind;
    if (const auto k =
            lookup<K>(v, {{"baseline", K::Baseline}, {"sub", K::Sub}, {"super", K::Super}}))
        return BaselineShift{*k, 0};
    if (const auto px = parse_length(v, ctx.font_size, ctx)) return BaselineShift{K::Length, *px};
    return std::nullopt;
}

// dominant-baseline (CSS Inline 3, with SVG 1.1's use-script, no-change
// and reset-size as auto: their tables come from fonts, not kept here).
std::optional<Baseline> parse_dominant_baseline(std::string_view v) {
    return lookup<Baseline>(v, {{"auto", Baseline::Auto},
                                {"use-script", Baseline::Auto},
                                {"no-change", Baseline::Auto},
                                {"reset-size", Baseline::Auto},
                                {"alphabetic", Baseline::Alphabetic},
                                {"ideographic", Baseline::Ideographic},
                                {"middle", Baseline::Middle},
                                {"central", Baseline::Central},
                                {"mathematical", Baseline::Mathematical},
                                {"hanging", Baseline::Hanging},
                                {"text-before-edge", Baseline::TextBeforeEdge},
                                {"text-top", Baseline::TextBeforeEdge},
                                {"text-after-edge", Baseline::TextAfterEdge},
                                {"text-bottom", Baseline::TextAfterEdge}});
}

// alignment-baseline (SVG 1.1, 10.9.2; CSS Inline 3): SVG 1.1's
// before-edge and after-edge are the text edges (there is no line box);
// CSS's top, center and bottom likewise.
std::optional<Baseline> parse_alignment_baseline(std::string_view v) {
    return lookup<Baseline>(v, {{"auto", Baseline::Auto},
                                {"baseline", Baseline::Auto},
                                {"before-edge", Baseline::TextBeforeEdge},
                                {"text-before-edge", Baseline::TextBeforeEdge},
                                {"top", Baseline::TextBeforeEdge},
                                {"after-edge", Baseline::TextAfterEdge},
                                {"text-after-edge", Baseline::TextAfterEdge},
                                {"bottom", Baseline::TextAfterEdge},
                                {"alphabetic", Baseline::Alphabetic},
                                {"ideographic", Baseline::Ideographic},
                                {"middle", Baseline::Middle},
                                {"central", Baseline::Central},
                                {"center", Baseline::Central},
                                {"mathematical", Baseline::Mathematical},
                                {"hanging", Baseline::Hanging}});
}

// writing-mode (CSS Writing Modes 3, 3.1, with SVG 1.1's values, 7.1).
std::optional<WritingMode> parse_writing_mode(std::string_view v) {
    return lookup<WritingMode>(v, {{"horizontal-tb", WritingMode::HorizontalTb},
                                   {"lr-tb", WritingMode::HorizontalTb},
                                   {"lr", WritingMode::HorizontalTb},
                                   {"rl-tb", WritingMode::HorizontalTb},
                                   {"rl", WritingMode::HorizontalTb},
                                   {"vertical-rl", WritingMode::VerticalRl},
                                   {"tb-rl", WritingMode::VerticalRl},
                                   {"tb", WritingMode::VerticalRl},
                                   {"vertical-lr", WritingMode::VerticalLr}});
}

std::optional<UnicodeBidi> parse_unicode_bidi(std::string_view v) {
    return lookup<UnicodeBidi>(v, {{"normal", UnicodeBidi::Normal},
                                   {"embed", UnicodeBidi::Embed},
                                   {"isolate", UnicodeBidi::Isolate},
                                   {"bidi-override", UnicodeBidi::BidiOverride},
                                   {"isolate-override", UnicodeBidi::IsolateOverride},
                                   {"plaintext", UnicodeBidi::Plaintext}});
}

// The flag of a text-decoration-line keyword (blink's is `blink`), or null.
bool* line_flag(std::string_view w, TextDecorationLines& d, bool& blink) {
    if (iequals(w, "underline")) return &d.underline;
    if (iequals(w, "overline")) return &d.overline;
    if (iequals(w, "line-through")) return &d.line_through;
    return iequals(w, "blink") ? &blink : nullptr;
}

// Whether a word of the text-decoration shorthand is its style, thickness
// or color, each at most once (`seen`).
bool decoration_extra(std::string_view w, const LengthContext& ctx, std::array<bool, 3>& seen) {
    const auto once = [&](std::size_t k) { return !std::exchange(seen[k], true); };
    if (lookup<bool>(w, {{"solid", true},
                         {"double", true},
                         {"dotted", true},
                         {"dashed", true},
                         {"wavy", true}}))
        return once(0);
    if (iequals(w, "auto") || iequals(w, "from-font") || parse_length(w, 0, ctx)) return once(1);
    if (iequals(w, "currentColor") || parse_color(w)) return once(2);
    return false;
}

// text-decoration-line (CSS Text Decoration 3, 2.1): none, or lines, each
// at most once (blink is valid and not drawn). The text-decoration
// shorthand (2.4) may add a style, a thickness and a color, checked and
// dropped: the lines are drawn solid, in the element's paint (SVG 2, 11.12).
std::optional<TextDecorationLines> parse_decoration(std::string_view v, bool shorthand,
                                                    const LengthContext& ctx) {
    TextDecorationLines d;
    bool none = false, lines = false, blink = false;
    std::array<bool, 3> extras{};
    const std::vector<std::string_view> ws = words(v);
    if (ws.empty()) return std::nullopt;
    for (const std::string_view w : ws) {
        if (bool* line = line_flag(w, d, blink)) {
            if (none || *line) return std::nullopt;
            *line = lines = true;
        } else if (iequals(w, "none")) {
            if (none || lines) return std::nullopt;
            none = true;
        } else if (!shorthand || !decoration_extra(w, ctx, extras)) {
            return std::nullopt;
        }
    }
    return d;
}

std::optional<std::string> apply_layout_property(std::string_view name, std::string_view value,
                                                 const StyleState& parent, StyleState& style,
                                                 const LengthContext& ctx) {
    const Setter set{name, value};
    const TextState initial;
    TextState& t = style.text;
    const TextState& p = parent.text;
    if (name == "letter-spacing")
        return set(t.letter_spacing, p.letter_spacing, initial.letter_spacing,
                   parse_spacing(value, ctx), "normal or a length");
    if (name == "word-spacing")
        return set(t.word_spacing, p.word_spacing, initial.word_spacing, parse_spacing(value, ctx),
                   "normal or a length");
    if (name == "text-anchor")
        return set(t.anchor, p.anchor, initial.anchor,
                   lookup<TextAnchor>(value, {{"start", TextAnchor::Start},
                                              {"middle", TextAnchor::Middle},
                                              {"end", TextAnchor::End}}),
                   "start, middle or end");
    if (name == "dominant-baseline")
        return set(t.dominant_baseline, p.dominant_baseline, initial.dominant_baseline,
                   parse_dominant_baseline(value), "a baseline");
    if (name == "writing-mode")
        return set(t.writing_mode, p.writing_mode, initial.writing_mode, parse_writing_mode(value),
                   "a writing mode");
    if (name == "direction")
        return set(t.rtl, p.rtl, initial.rtl, lookup<bool>(value, {{"ltr", false}, {"rtl", true}}),
                   "ltr or rtl");
    if (name == "glyph-orientation-vertical")
        return set(
            t.glyph_orientation_vertical, p.glyph_orientation_vertical,
            initial.glyph_orientation_vertical,
            lookup<int>(value, {{"auto", -1}, {"0", 0}, {"90", 90}, {"0deg", 0}, {"90deg", 90}}),
            "auto, 0 or 90");
    // white-space (CSS Text 3, 3): pre-line collapses spaces as normal does.
    if (name == "white-space")
        return set(t.preserve_spaces, p.preserve_spaces, initial.preserve_spaces,
                   lookup<bool>(value, {{"normal", false},
                                        {"nowrap", false},
                                        {"pre-line", false},
                                        {"pre", true},
                                        {"pre-wrap", true},
                                        {"break-spaces", true}}),
                   "normal, pre, nowrap, pre-wrap, break-spaces or pre-line");
    return std::nullopt;
}

// text-rendering: valid or not; there is nothing to set, as outlines are
// never hinted.
bool text_rendering(std::string_view v) {
    for (const char* k : {"auto", "optimizeSpeed", "optimizeLegibility", "geometricPrecision"})
        if (iequals(v, k)) return true;
    return css_wide(v) != Wide::None;
}

std::optional<std::string> apply_element_property(std::string_view name, std::string_view value,
                                                  ElementProps& props, const LengthContext& ctx) {
    const Setter set{name, value};
    const TextProps initial;
    TextProps& t = props.text;
    if (name == "alignment-baseline")
        return set(t.alignment_baseline, initial.alignment_baseline, initial.alignment_baseline,
                   parse_alignment_baseline(value), "a baseline");
    if (name == "baseline-shift")
        return set(t.baseline_shift, initial.baseline_shift, initial.baseline_shift,
                   parse_baseline_shift(value, ctx), "baseline, sub, super or a length");
    if (name == "unicode-bidi")
        return set(t.unicode_bidi, initial.unicode_bidi, initial.unicode_bidi,
                   parse_unicode_bidi(value), "a unicode-bidi value");
    if (name == "text-decoration" || name == "text-decoration-line")
        return set(t.decoration, initial.decoration, initial.decoration,
                   parse_decoration(value, name == "text-decoration", ctx),
                   "none or underline, overline and line-through");
    if (name == "text-rendering")
        return text_rendering(value)
                   ? ""
                   : bad(name, value,
                         "auto, optimizeSpeed, optimizeLegibility or geometricPrecision");
    return std::nullopt;
}

} // namespace

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

std::optional<std::string> apply_text_property(std::string_view name, std::string_view value,
                                               const StyleState& parent, StyleState& style,
                                               ElementProps& props, const LengthContext& ctx) {
    value = trim(value);
    if (auto e = apply_font_property(name, value, parent, style, ctx)) return e;
    if (auto e = apply_layout_property(name, value, parent, style, ctx)) return e;
    return apply_element_property(name, value, props, ctx);
}

} // namespace casteljau
