#include "casteljau/svg/media_query.h"

#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/style.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <vector>

namespace casteljau {

using svg_detail::iequals;
using svg_detail::trim;

namespace {

// A length in px (style.h's parse_length, 16 px to the em: a media query
// has no font size), with a unit unless it is 0, and no percentage.
std::optional<double> length_px(std::string_view v, const MediaContext& m) {
    std::string_view unit;
    const std::optional<double> n = parse_number(v, &unit);
    if (!n || (unit.empty() && *n != 0) || unit == "%") return std::nullopt;
    return parse_length(v, 0, LengthContext{16, 16, m.width, m.height});
}

// A ratio, "a / b" or a number, both positive.
std::optional<double> ratio(std::string_view v) {
    const std::size_t slash = v.find('/');
    const auto a = parse_number(trim(v.substr(0, slash)));
    const auto b = slash == std::string_view::npos ? std::optional<double>(1)
                                                   : parse_number(trim(v.substr(slash + 1)));
    if (!a || !b || !(*a > 0) || !(*b > 0) || !std::isfinite(*a / *b)) return std::nullopt;
    return *a / *b;
}

// How a size feature's actual value must compare with one given.
enum class Compare { Less, LessEqual, Equal, GreaterEqual, Greater };

bool holds(double actual, Compare c, double given) {
    // Equality within rounding: a width of 32 px computed from 0.5in x 64.
    const double eps = 1e-9 * std::max(1.0, std::fabs(given));
    switch (c) {
    case Compare::Less:
        return actual < given - eps;
    case Compare::LessEqual:
        return actual <= given + eps;
    case Compare::Equal:
        return std::fabs(actual - given) <= eps;
    case Compare::GreaterEqual:
        return actual >= given - eps;
    case Compare::Greater:
        return actual > given + eps;
    }
    return false;
}

// A size feature's actual value, by name (the device- forms the same).
std::optional<double> actual(std::string_view name, const MediaContext& m) {
    if (name.substr(0, 7) == "device-") name.remove_prefix(7);
    if (name == "width") return m.width;
    if (name == "height") return m.height;
    if (name == "aspect-ratio") return m.height > 0 ? m.width / m.height : 0;
    return std::nullopt;
}

// A value given for the feature `name`: a ratio or a length.
std::optional<double> given(std::string_view name, std::string_view v, const MediaContext& m) {
    return name.find("aspect-ratio") != std::string_view::npos ? ratio(v) : length_px(v, m);
}

// The range syntax (4.1): name op value, value op name, or value op name op
// value. nullopt when `f` names no size feature; false with `known` false
// when the value is malformed.
std::optional<bool> range_feature(std::string_view f, const MediaContext& m, bool& known) {
    std::vector<std::string_view> parts, ops;
    std::size_t start = 0;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (f[i] != '<' && f[i] != '>' && f[i] != '=') continue;
        parts.push_back(trim(f.substr(start, i - start)));
        const std::size_t len = i + 1 < f.size() && f[i + 1] == '=' && f[i] != '=' ? 2 : 1;
        ops.push_back(f.substr(i, len));
        i += len - 1;
        start = i + 1;
    }
    parts.push_back(trim(f.substr(start)));
    if (parts.size() > 3) return std::nullopt;
    const std::size_t at = parts.size() == 3 || !actual(parts[0], m) ? 1 : 0; // the name
    const std::optional<double> a = actual(parts[at], m);
    if (!a) return std::nullopt;
    if (!known) return false;
    bool result = true;
    for (std::size_t k = 0; k < parts.size(); ++k) {
        if (k == at) continue;
        const std::optional<double> v = given(parts[at], parts[k], m);
        if (!v) return known = false;
        // "value op name" reads op from the value's side: flipped.
        const std::string_view o = ops[k < at ? k : k - 1];
        const bool less = (o[0] == '<') != (k < at);
        const Compare c = o == "="        ? Compare::Equal
                          : o.size() == 2 ? (less ? Compare::LessEqual : Compare::GreaterEqual)
                                          : (less ? Compare::Less : Compare::Greater);
        result = result && holds(*a, c, *v);
    }
    return result;
}

// Answers a size feature (media_query.h): nullopt when `f` is no size
// feature; false with `known` false when there is no size or the value is
// malformed.
std::optional<bool> size_feature(std::string_view f, const MediaContext& m, bool& known) {
    known = m.width > 0 && m.height > 0;
    const std::size_t colon = f.find(':');
    if (colon == std::string_view::npos && f.find_first_of("<>=") != std::string_view::npos)
        return range_feature(f, m, known);
    std::string_view name = trim(f.substr(0, colon));
    Compare c = Compare::Equal;
    if (name.substr(0, 4) == "min-")
        c = Compare::GreaterEqual, name.remove_prefix(4);
    else if (name.substr(0, 4) == "max-")
        c = Compare::LessEqual, name.remove_prefix(4);
    if (name == "orientation") {
        if (!known || colon == std::string_view::npos) return known;
        const std::string_view v = trim(f.substr(colon + 1));
        if (v != "portrait" && v != "landscape") return known = false;
        return (v == "portrait") == (m.height >= m.width);
    }
    const std::optional<double> a = actual(name, m);
    if (!a) return std::nullopt;
    if (!known) return false;
    if (colon == std::string_view::npos) return c == Compare::Equal && *a != 0; // boolean
    const std::optional<double> v = given(name, trim(f.substr(colon + 1)), m);
    if (!v) return known = false;
    return holds(*a, c, *v);
}

// Words and parenthesised groups of one query, lowercased: "not", "screen",
// "and", "(prefers-color-scheme: dark)".
class Query {
  public:
    Query(std::string_view q, const MediaContext& media, std::string* unknown)
        : media_(media), unknown_(unknown) {
        for (std::size_t i = 0; i < q.size();) {
            if (std::isspace(static_cast<unsigned char>(q[i]))) {
                ++i;
                continue;
            }
            const std::size_t start = i;
            if (q[i] == '(') {
                int depth = 0;
                do depth += q[i] == '(' ? 1 : q[i] == ')' ? -1 : 0;
                while (++i < q.size() && depth > 0);
                if (depth != 0) ok_ = false;
            } else {
                while (i < q.size() && !std::isspace(static_cast<unsigned char>(q[i])) &&
                       q[i] != '(')
                    ++i;
            }
            std::string w(q.substr(start, i - start));
            for (char& c : w) c = char(std::tolower(static_cast<unsigned char>(c)));
            words_.push_back(std::move(w));
        }
    }

    // The query's value: false when malformed or unknown.
    bool value() {
        if (!ok_ || words_.empty()) return false;
        std::size_t i = 0;
        if (words_[0][0] != '(' && words_[0] != "not") return typed(0);
        if (words_[0] == "not" && words_.size() > 1 && words_[1][0] != '(') return typed(0);
        const std::optional<bool> c = condition(i);
        return c && i == words_.size() && *c && !unknown_seen_;
    }

  private:
    // [not|only]? type [and condition]?
    bool typed(std::size_t i) {
        const bool negate = words_[i] == "not";
        if (negate || words_[i] == "only") ++i;
        if (i >= words_.size()) return false;
        const std::string& type = words_[i++];
        bool match = type == "all" || type == "screen";
        if (i < words_.size()) {
            if (words_[i++] != "and") return false;
            const std::optional<bool> c = condition(i);
            if (!c || i != words_.size()) return false;
            match = match && *c;
        }
        return !unknown_seen_ && match != negate;
    }

    std::optional<bool> condition(std::size_t& i) {
        if (i < words_.size() && words_[i] == "not") {
            ++i;
            const std::optional<bool> c = in_parens(i);
            return c ? std::optional<bool>(!*c) : std::nullopt;
        }
        std::optional<bool> c = in_parens(i);
        std::string joiner;
        while (c && i < words_.size() && (words_[i] == "and" || words_[i] == "or")) {
            if (!joiner.empty() && words_[i] != joiner) return std::nullopt; // no mixing
            joiner = words_[i++];
            const std::optional<bool> next = in_parens(i);
            if (!next) return std::nullopt;
            c = joiner == "and" ? *c && *next : *c || *next;
        }
        return c;
    }

    std::optional<bool> in_parens(std::size_t& i) {
        if (i >= words_.size() || words_[i].size() < 2 || words_[i][0] != '(') return std::nullopt;
        const std::string_view inner =
            trim(std::string_view(words_[i]).substr(1, words_[i].size() - 2));
        ++i;
        if (!inner.empty() && (inner[0] == '(' || inner.substr(0, 4) == "not ")) {
            Query sub(inner, media_, unknown_);
            std::size_t j = 0;
            const std::optional<bool> c = sub.ok_ ? sub.condition(j) : std::nullopt;
            unknown_seen_ = unknown_seen_ || sub.unknown_seen_;
            return c && j == sub.words_.size() ? c : std::nullopt;
        }
        return feature(inner);
    }

    // A feature's answer (top of media_query.h); an unknown one is false and noted.
    std::optional<bool> feature(std::string_view f) {
        const std::size_t colon = f.find(':');
        const std::string_view name = trim(f.substr(0, colon));
        const std::string_view value =
            colon == std::string_view::npos ? std::string_view() : trim(f.substr(colon + 1));
        // The value that matches, and the answer to the bare feature (true
        // unless the value is none, 0 or no-preference, 4.2 "boolean context").
        const struct {
            std::string_view name, yes;
            bool bare;
        } answers[] = {{"prefers-color-scheme", media_.dark ? "dark" : "light", true},
                       {"prefers-reduced-motion", "no-preference", false},
                       {"prefers-contrast", "no-preference", false},
                       {"prefers-reduced-transparency", "no-preference", false},
                       {"forced-colors", "none", false},
                       {"inverted-colors", "none", false},
                       {"scripting", "none", false},
                       {"color", "", true},
                       {"monochrome", "0", false},
                       {"grid", "0", false}};
        for (const auto& a : answers)
            if (name == a.name && (value.empty() || !a.yes.empty()))
                return value.empty() ? a.bare : value == a.yes;
        bool known = false;
        if (const std::optional<bool> size = size_feature(f, media_, known); size && known)
            return size;
        unknown_seen_ = true;
        if (unknown_ && unknown_->empty()) unknown_->append("(").append(f).append(")");
        return false;
    }

    const MediaContext& media_;
    std::string* unknown_;
    std::vector<std::string> words_;
    bool ok_ = true;
    bool unknown_seen_ = false;
};

} // namespace

bool media_matches(std::string_view query, const MediaContext& media, std::string* unknown) {
    if (unknown) unknown->clear();
    query = trim(query);
    if (query.empty()) return true;
    int depth = 0;
    std::size_t start = 0;
    for (std::size_t i = 0; i <= query.size(); ++i) {
        if (i < query.size()) {
            depth += query[i] == '(' ? 1 : query[i] == ')' ? -1 : 0;
            if (query[i] != ',' || depth != 0) continue;
        }
        if (Query(query.substr(start, i - start), media, unknown).value()) return true;
        start = i + 1;
    }
    return false;
}

} // namespace casteljau
