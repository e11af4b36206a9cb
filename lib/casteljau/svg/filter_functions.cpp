// Parsing the filter property (Filter Effects 1, 11 and 12.2).
//
// Each function takes at most one argument but drop-shadow, and each has
// a default: blur() 0, hue-rotate() 0deg, the others 1. Numbers may be
// percentages (50% = 0.5); negative values are invalid (12.2). grayscale,
// invert, opacity and sepia clamp their amount to 1. drop-shadow takes a
// color (before or after) and two or three lengths: dx, dy and the blur's
// standard deviation (0 when left out). An invalid item makes the whole
// value invalid, as CSS drops the declaration.
#include "casteljau/svg/filter_functions.h"

#include "casteljau/svg/color.h"
#include "casteljau/svg/detail/ascii.h"

#include <algorithm>
#include <cctype>
#include <numbers>

namespace casteljau {

namespace {

using svg_detail::iequals;
using svg_detail::trim;

// The whitespace-separated words of v, keeping parenthesised parts whole.
std::vector<std::string_view> words(std::string_view v) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < v.size()) {
        while (i < v.size() && std::isspace(static_cast<unsigned char>(v[i]))) ++i;
        const std::size_t start = i;
        int depth = 0;
        while (i < v.size() && (depth > 0 || !std::isspace(static_cast<unsigned char>(v[i])))) {
            depth += v[i] == '(' ? 1 : v[i] == ')' ? -1 : 0;
            ++i;
        }
        if (i > start) out.push_back(v.substr(start, i - start));
    }
    return out;
}

// A non-negative number or percentage; `initial` when empty.
std::optional<double> amount(std::string_view arg, double initial) {
    if (arg.empty()) return initial;
    std::string_view unit;
    const auto n = parse_number(arg, &unit);
    if (!n || *n < 0) return std::nullopt;
    if (unit == "%") return *n / 100;
    if (!unit.empty()) return std::nullopt;
    return *n;
}

// An angle in degrees (deg, grad, rad, turn; a bare 0).
std::optional<double> angle(std::string_view arg) {
    if (arg.empty()) return 0.0;
    std::string_view unit;
    const auto n = parse_number(arg, &unit);
    if (!n) return std::nullopt;
    if (unit.empty()) return *n == 0 ? std::optional<double>(0.0) : std::nullopt;
    const std::pair<std::string_view, double> units[] = {
        {"deg", 1}, {"grad", 0.9}, {"rad", 180 / std::numbers::pi}, {"turn", 360}};
    for (const auto& [name, k] : units)
        if (iequals(unit, name)) return *n * k;
    return std::nullopt;
}

bool drop_shadow(std::string_view arg, const LengthContext& ctx, FilterItem& item) {
    const std::vector<std::string_view> ws = words(arg);
    std::vector<double> lengths;
    std::size_t color_at = ws.size(); // none yet
    for (std::size_t i = 0; i < ws.size(); ++i) {
        if (const auto len = parse_length(ws[i], 0, ctx)) {
            lengths.push_back(*len);
            continue;
        }
        const bool current = iequals(ws[i], "currentColor");
        const auto c = current ? std::nullopt : parse_color(ws[i]);
        if (color_at != ws.size() || (!current && !c)) return false;
        color_at = i;
        item.color = c;
    }
    // The color before or after the lengths, never between them.
    if (color_at != ws.size() && color_at != 0 && color_at + 1 != ws.size()) return false;
    if (lengths.size() < 2 || lengths.size() > 3 || (lengths.size() == 3 && lengths[2] < 0))
        return false;
    item.dx = lengths[0];
    item.dy = lengths[1];
    item.amount = lengths.size() == 3 ? lengths[2] : 0;
    return true;
}

std::optional<FilterItem> function(std::string_view name, std::string_view arg,
                                   const LengthContext& ctx) {
    using K = FilterItem::Kind;
    FilterItem item;
    arg = trim(arg);
    if (iequals(name, "blur")) {
        item.kind = K::Blur;
        const auto len = arg.empty() ? std::optional<double>(0) : parse_length(arg, 0, ctx);
        if (!len || *len < 0) return std::nullopt;
        item.amount = *len;
        return item;
    }
    if (iequals(name, "drop-shadow")) {
        item.kind = K::DropShadow;
        if (!drop_shadow(arg, ctx, item)) return std::nullopt;
        return item;
    }
    if (iequals(name, "hue-rotate")) {
        item.kind = K::HueRotate;
        const auto a = angle(arg);
        if (!a) return std::nullopt;
        item.amount = *a;
        return item;
    }
    const std::pair<std::string_view, K> numeric[] = {{"brightness", K::Brightness},
                                                      {"contrast", K::Contrast},
                                                      {"grayscale", K::Grayscale},
                                                      {"invert", K::Invert},
                                                      {"opacity", K::Opacity},
                                                      {"saturate", K::Saturate},
                                                      {"sepia", K::Sepia}};
    for (const auto& [fname, kind] : numeric) {
        if (!iequals(name, fname)) continue;
        const auto a = amount(arg, 1);
        if (!a) return std::nullopt;
        item.kind = kind;
        const bool clamped =
            kind == K::Grayscale || kind == K::Invert || kind == K::Opacity || kind == K::Sepia;
        item.amount = clamped ? std::min(*a, 1.0) : *a;
        return item;
    }
    return std::nullopt;
}

} // namespace

std::optional<std::vector<FilterItem>> parse_filter_list(std::string_view value,
                                                         const LengthContext& ctx) {
    value = trim(value);
    std::vector<FilterItem> out;
    if (iequals(value, "none")) return out;
    for (std::string_view w : words(value)) {
        const std::size_t open = w.find('(');
        if (open == std::string_view::npos || w.back() != ')') return std::nullopt;
        const std::string_view name = w.substr(0, open);
        const std::string_view arg = w.substr(open + 1, w.size() - open - 2);
        if (iequals(name, "url")) {
            std::string_view ref = trim(arg);
            if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'') &&
                ref.back() == ref.front())
                ref = ref.substr(1, ref.size() - 2);
            if (ref.size() < 2 || ref.front() != '#') return std::nullopt;
            FilterItem item;
            item.id = std::string(ref.substr(1));
            out.push_back(std::move(item));
            continue;
        }
        const auto f = function(name, arg, ctx);
        if (!f) return std::nullopt;
        out.push_back(*f);
    }
    if (out.empty()) return std::nullopt;
    return out;
}

} // namespace casteljau
