#include "casteljau/svg/media_query.h"

#include "casteljau/svg/detail/ascii.h"

#include <cctype>
#include <optional>
#include <vector>

namespace casteljau {

using svg_detail::iequals;
using svg_detail::trim;

namespace {

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
