// The text properties (svg/text_properties.h) but the font ones: SVG 2,
// 11.10 (text-anchor, text-rendering); CSS Text 3 (white-space,
// letter-spacing, word-spacing); CSS Text Decoration 3 (text-decoration and
// text-decoration-line, 2); CSS Inline 3 (dominant-baseline,
// alignment-baseline, baseline-shift); CSS Writing Modes 3 (direction,
// unicode-bidi, writing-mode with SVG 1.1's values); SVG 1.1, 10.7.3
// (glyph-orientation-vertical); the CSS-wide keywords of CSS Cascade 4, 7.3
// (inherit, initial, unset). apply_text_property hands the font properties
// (CSS Fonts 4) to svg/font_properties.cpp first.
#include "casteljau/svg/text_properties.h"

#include "casteljau/svg/color.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/text_property_parsing.h"
#include "casteljau/svg/style.h"

#include <array>
#include <utility>
#include <vector>

namespace casteljau {

namespace {

using svg_detail::iequals;
using svg_detail::trim;
using svg_detail::text_parsing::bad;
using svg_detail::text_parsing::css_wide;
using svg_detail::text_parsing::lookup;
using svg_detail::text_parsing::Setter;
using svg_detail::text_parsing::Wide;
using svg_detail::text_parsing::words;

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
                                                  const TextProps& p, ElementProps& props,
                                                  const LengthContext& ctx) {
    const Setter set{name, value};
    const TextProps initial;
    TextProps& t = props.text;
    if (name == "alignment-baseline")
        return set(t.alignment_baseline, p.alignment_baseline, initial.alignment_baseline,
                   parse_alignment_baseline(value), "a baseline");
    if (name == "baseline-shift")
        return set(t.baseline_shift, p.baseline_shift, initial.baseline_shift,
                   parse_baseline_shift(value, ctx), "baseline, sub, super or a length");
    if (name == "unicode-bidi")
        return set(t.unicode_bidi, p.unicode_bidi, initial.unicode_bidi, parse_unicode_bidi(value),
                   "a unicode-bidi value");
    if (name == "text-decoration" || name == "text-decoration-line")
        return set(t.decoration, p.decoration, initial.decoration,
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

std::optional<std::string> apply_text_property(std::string_view name, std::string_view value,
                                               const StyleState& parent, StyleState& style,
                                               ElementProps& props, const LengthContext& ctx) {
    value = trim(value);
    if (auto e = svg_detail::apply_font_property(name, value, parent, style, ctx)) return e;
    if (auto e = apply_layout_property(name, value, parent, style, ctx)) return e;
    return apply_element_property(name, value, parent.own_text, props, ctx);
}

} // namespace casteljau
