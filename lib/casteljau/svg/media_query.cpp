#include "casteljau/svg/media_query.h"

#include "casteljau/svg/detail/ascii.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

namespace casteljau {

using svg_detail::iequals;
using svg_detail::trim;

namespace {

// A length in px (16 px to the em: a media query has no font size); a bare
// 0 is 0.
std::optional<double> length_px(std::string_view v) {
    std::size_t i = 0;
    while (i < v.size() && (std::isdigit(static_cast<unsigned char>(v[i])) || v[i] == '.' ||
                            v[i] == '+' || v[i] == '-' || v[i] == 'e'))
        ++i;
    // An exponent's 'e' is taken only before a digit or sign ("2em" is 2 em).
    while (i > 0 && v[i - 1] == 'e') --i;
    const std::string number(v.substr(0, i));
    char* end = nullptr;
    const double n = number.empty() ? 0 : std::strtod(number.c_str(), &end);
    if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(n))
        return std::nullopt;
    const std::string_view unit = v.substr(i);
    if (unit.empty()) return n == 0 ? std::optional<double>(0) : std::nullopt;
    const struct {
        std::string_view unit;
        double px;
    } units[] = {{"px", 1},         {"em", 16},        {"rem", 16},
                 {"in", 96},        {"cm", 96 / 2.54}, {"mm", 9.6 / 2.54},
                 {"q", 2.4 / 2.54}, {"pt", 96.0 / 72}, {"pc", 16}};
    for (const auto& u : units)
        if (unit == u.unit) return n * u.px;
    return std::nullopt;
}

// A ratio, "a / b" or a number.
std::optional<double> ratio(std::string_view v) {
    const std::size_t slash = v.find('/');
    const std::string a(trim(v.substr(0, slash)));
    const std::string b(slash == std::string_view::npos ? "1" : trim(v.substr(slash + 1)));
    char *ea = nullptr, *eb = nullptr;
    const double x = std::strtod(a.c_str(), &ea), y = std::strtod(b.c_str(), &eb);
    if (a.empty() || b.empty() || ea != a.c_str() + a.size() || eb != b.c_str() + b.size() ||
        !(x > 0) || !(y > 0) || !std::isfinite(x / y))
        return std::nullopt;
    return x / y;
}

// How a size feature's actual value compares to one given: -1, 0 or 1.
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

// Answers a size feature (media_query.h): nullopt when `f` is no size
// feature; false with `known` false when there is no size or the value is
// malformed.
std::optional<bool> size_feature(std::string_view f, const MediaContext& m, bool& known) {
    known = m.width > 0 && m.height > 0;
    // The feature's actual value, by name (device- forms the same).
    const auto actual = [&](std::string_view name) -> std::optional<double> {
        if (name.substr(0, 7) == "device-") name.remove_prefix(7);
        if (name == "width") return m.width;
        if (name == "height") return m.height;
        if (name == "aspect-ratio") return m.height > 0 ? m.width / m.height : 0;
        return std::nullopt;
    };
    const auto value = [&](std::string_view name, std::string_view v) {
        return name.find("aspect-ratio") != std::string_view::npos ? ratio(v) : length_px(v);
    };
    const std::size_t op = f.find_first_of("<>=");
    const std::size_t colon = f.find(':');
    if (op != std::string_view::npos && colon == std::string_view::npos) {
        // Range syntax: [value op] name op value, or value op name.
        std::vector<std::string_view> parts;
        std::vector<std::string_view> ops;
        std::size_t start = 0;
        for (std::size_t i = 0; i < f.size();) {
            if (f[i] != '<' && f[i] != '>' && f[i] != '=') {
                ++i;
                continue;
            }
            parts.push_back(trim(f.substr(start, i - start)));
            const std::size_t len = i + 1 < f.size() && f[i + 1] == '=' && f[i] != '=' ? 2 : 1;
            ops.push_back(f.substr(i, len));
            i += len;
            start = i;
        }
        parts.push_back(trim(f.substr(start)));
        const auto compare = [](std::string_view o, bool flip) {
            if (o == "=") return Compare::Equal;
            const bool less = (o[0] == '<') != flip;
            return o.size() == 2 ? (less ? Compare::LessEqual : Compare::GreaterEqual)
                                 : (less ? Compare::Less : Compare::Greater);
        };
        const std::size_t at = actual(parts[0]) ? 0 : parts.size() > 1 && actual(parts[1]) ? 1 : 9;
        if (at == 9 || parts.size() > 3 || (parts.size() == 3 && at != 1)) return std::nullopt;
        if (!known) return false;
        const std::string_view name = parts[at];
        bool result = true;
        for (std::size_t k = 0; k < parts.size(); ++k) {
            if (k == at) continue;
            const std::optional<double> v = value(name, parts[k]);
            if (!v) return known = false;
            // "value op name" reads op from the value's side: flip it.
            result = result && holds(*actual(name), compare(ops[k < at ? k : k - 1], k < at), *v);
        }
        return result;
    }
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
    const std::optional<double> a = actual(name);
    if (!a) return std::nullopt;
    if (!known) return false;
    if (colon == std::string_view::npos) return c == Compare::Equal && *a != 0; // boolean
    const std::optional<double> v = value(name, trim(f.substr(colon + 1)));
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
