// Internal to the SVG reader (not installed): what the parsers of the text
// properties (svg/text_properties.cpp) and of the font properties
// (svg/font_properties.cpp) share: the words of a value, keywords (ASCII
// case-insensitive), the CSS-wide keywords of CSS Cascade 4, 7.3 (inherit,
// initial, unset) and applying a parsed value; and the entry point of the
// font properties, which apply_text_property tries first.
#pragma once

#include "casteljau/svg/detail/ascii.h"

#include <cctype>
#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace casteljau {

struct StyleState;
struct LengthContext;

} // namespace casteljau

namespace casteljau::svg_detail {

/// Applies a font property (svg/font_properties.cpp), as apply_text_property
/// does (svg/text_properties.h), `value` trimmed: nullopt when `name` is not
/// one; "" when applied; otherwise what is wrong with the value.
std::optional<std::string> apply_font_property(std::string_view name, std::string_view value,
                                               const StyleState& parent, StyleState& style,
                                               const LengthContext& ctx);

namespace text_parsing {

inline bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)); }

inline void skip_spaces(std::string_view v, std::size_t& i) {
    while (i < v.size() && is_space(v[i])) ++i;
}

// The whitespace-separated words of a value, a parenthesised group kept
// whole (a color as "rgb(1, 2, 3)").
inline std::vector<std::string_view> words(std::string_view v) {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; skip_spaces(v, i), i < v.size();) {
        const std::size_t start = i;
        for (int depth = 0; i < v.size() && (depth > 0 || !is_space(v[i])); ++i)
            depth += v[i] == '(' ? 1 : v[i] == ')' ? -1 : 0;
        out.push_back(v.substr(start, i - start));
    }
    return out;
}

inline std::string bad(std::string_view name, std::string_view value, const char* expected) {
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

inline Wide css_wide(std::string_view value) {
    if (iequals(value, "inherit") || iequals(value, "unset")) return Wide::Inherit;
    return iequals(value, "initial") ? Wide::Initial : Wide::None;
}

// Applies one value the way apply_property does: a CSS-wide keyword takes
// `inherited` or `initial`, a value that parses is taken, anything else is
// an error. For a property that is not inherited, `inherited` is the
// parent's own value (StyleState::own_text).
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

} // namespace text_parsing

} // namespace casteljau::svg_detail
