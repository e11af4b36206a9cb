#include "casteljau/svg/custom_properties.h"

#include "casteljau/svg/detail/ascii.h"

#include <cctype>

namespace casteljau {

using svg_detail::iequals;
using svg_detail::in_css_string;
using svg_detail::trim;

namespace {

bool ident_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' ||
           static_cast<unsigned char>(c) >= 0x80;
}

// Where the next var( starts at or after `from` (not inside a longer
// identifier such as `myvar(`, nor in a string), or npos.
std::size_t find_var(std::string_view v, std::size_t from) {
    char quote = 0;
    for (std::size_t i = from; i < v.size(); ++i)
        if (!in_css_string(v, i, quote) && i + 4 <= v.size() && iequals(v.substr(i, 4), "var(") &&
            (i == 0 || !ident_char(v[i - 1])))
            return i;
    return std::string_view::npos;
}

// The index of the ')' closing the '(' before `from`, nested parentheses and
// strings skipped; npos when unclosed.
std::size_t closing(std::string_view v, std::size_t from) {
    int depth = 1;
    char quote = 0;
    for (std::size_t i = from; i < v.size(); ++i) {
        if (in_css_string(v, i, quote)) continue;
        if (v[i] == '(') ++depth;
        if (v[i] == ')' && --depth == 0) return i;
    }
    return std::string_view::npos;
}

// The first comma at nesting depth 0 of `v`, or npos.
std::size_t top_comma(std::string_view v) {
    int depth = 0;
    for (std::size_t i = 0; i < v.size(); ++i) {
        if (v[i] == '(')
            ++depth;
        else if (v[i] == ')')
            --depth;
        else if (v[i] == ',' && depth == 0)
            return i;
    }
    return std::string_view::npos;
}

const std::string* lookup(const CustomProperties* custom, std::string_view name) {
    if (!custom) return nullptr;
    for (auto it = custom->rbegin(); it != custom->rend(); ++it)
        if (it->first == name) return &it->second;
    return nullptr;
}

bool substitute(std::string_view v, const CustomProperties* custom, std::size_t limit, int depth,
                std::string& out) {
    if (depth > kMaxVarDepth) return false;
    std::size_t at = 0;
    for (std::size_t start; (start = find_var(v, at)) != std::string_view::npos;) {
        out.append(v.substr(at, start - at));
        const std::size_t close = closing(v, start + 4);
        if (close == std::string_view::npos) return false;
        const std::string_view inner = v.substr(start + 4, close - start - 4);
        const std::size_t comma = top_comma(inner);
        const std::string_view name = trim(inner.substr(0, comma));
        if (name.size() < 3 || name.substr(0, 2) != "--") return false;
        if (const std::string* value = lookup(custom, name)) {
            if (!substitute(*value, custom, limit, depth + 1, out)) return false;
        } else if (comma != std::string_view::npos) {
            if (!substitute(trim(inner.substr(comma + 1)), custom, limit, depth + 1, out))
                return false;
        } else {
            return false;
        }
        if (out.size() > limit) return false;
        at = close + 1;
    }
    out.append(v.substr(at));
    return out.size() <= limit;
}

} // namespace

bool has_var(std::string_view value) { return find_var(value, 0) != std::string_view::npos; }

std::optional<std::string> substitute_vars(std::string_view value, const CustomProperties* custom,
                                           std::size_t limit) {
    std::string out;
    if (!substitute(value, custom, limit, 0, out)) return std::nullopt;
    return out;
}

} // namespace casteljau
