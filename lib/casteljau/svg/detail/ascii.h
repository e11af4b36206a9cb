// Internal to the SVG reader (not installed): the ASCII text helpers CSS
// and SVG values share (CSS Syntax 3: whitespace, and keywords compared
// ASCII case-insensitively).
#pragma once

#include <algorithm>
#include <cctype>
#include <string_view>
#include <vector>

namespace casteljau::svg_detail {

/// Whether v[i] belongs to a string (opens it, is in it, or closes it),
/// `quote` being the open string's quote or 0; an escape steps i past the
/// escaped character.
inline bool in_css_string(std::string_view v, std::size_t& i, char& quote) {
    const char c = v[i];
    if (quote) {
        if (c == '\\')
            ++i;
        else if (c == quote)
            quote = 0;
        return true;
    }
    if (c != '"' && c != '\'') return false;
    quote = c;
    return true;
}

/// XML's white space (XML 1.0, 2.3: space, tab, CR, LF).
inline bool is_xml_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n'; }

/// `s` without leading and trailing whitespace.
inline std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

/// Whether a and b are equal but for ASCII case (CSS keywords).
inline bool iequals(std::string_view a, std::string_view b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
               return std::tolower(static_cast<unsigned char>(x)) ==
                      std::tolower(static_cast<unsigned char>(y));
           });
}

/// The whitespace-separated words of `s`.
inline std::vector<std::string_view> words(std::string_view s) {
    std::vector<std::string_view> out;
    for (std::size_t i = 0; i < s.size();) {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        const std::size_t start = i;
        while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        if (i > start) out.push_back(s.substr(start, i - start));
    }
    return out;
}

} // namespace casteljau::svg_detail
