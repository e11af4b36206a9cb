#include "casteljau/svg/css_math.h"

#include "casteljau/svg/detail/ascii.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

namespace casteljau {

using svg_detail::iequals;

namespace {

// A value and whether it is a length (else a number).
struct Quantity {
    double v = 0;
    bool length = false;
};

class MathParser {
  public:
    MathParser(std::string_view s,
               const std::function<std::optional<double>(std::string_view)>& leaf)
        : s_(s), leaf_(leaf) {}

    std::optional<Quantity> whole() {
        const std::optional<Quantity> q = value(0);
        skip_space();
        if (!q || i_ != s_.size()) return std::nullopt;
        return q;
    }

  private:
    void skip_space() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    bool take(char c) {
        skip_space();
        if (i_ < s_.size() && s_[i_] == c) return ++i_, true;
        return false;
    }

    std::optional<Quantity> sum(int depth) {
        std::optional<Quantity> q = product(depth);
        while (q) {
            // + and - need whitespace on both sides (CSS Values 4, 10.1).
            const std::size_t before = i_;
            skip_space();
            if (i_ == before || i_ + 1 >= s_.size() || (s_[i_] != '+' && s_[i_] != '-') ||
                !std::isspace(static_cast<unsigned char>(s_[i_ + 1]))) {
                i_ = before;
                return q;
            }
            const bool minus = s_[i_++] == '-';
            const std::optional<Quantity> r = product(depth);
            if (!r || r->length != q->length) return std::nullopt;
            q->v += minus ? -r->v : r->v;
        }
        return q;
    }

    std::optional<Quantity> product(int depth) {
        std::optional<Quantity> q = value(depth);
        while (q) {
            const std::size_t before = i_;
            const bool times = take('*');
            if (!times && !take('/')) {
                i_ = before;
                return q;
            }
            const std::optional<Quantity> r = value(depth);
            if (!r || (times && q->length && r->length) || (!times && (r->length || r->v == 0)))
                return std::nullopt;
            q->v = times ? q->v * r->v : q->v / r->v;
            q->length = q->length || r->length;
        }
        return q;
    }

    std::optional<Quantity> value(int depth) {
        if (depth > kMaxCssMathDepth) return std::nullopt;
        skip_space();
        if (take('(')) return closed(sum(depth + 1));
        std::size_t j = i_;
        while (j < s_.size() && std::isalpha(static_cast<unsigned char>(s_[j]))) ++j;
        if (j > i_ && j < s_.size() && s_[j] == '(') {
            const std::string_view name = s_.substr(i_, j - i_);
            i_ = j + 1;
            if (iequals(name, "calc")) return closed(sum(depth + 1));
            const bool is_min = iequals(name, "min"), is_max = iequals(name, "max");
            if (!is_min && !is_max && !iequals(name, "clamp")) return std::nullopt;
            std::vector<Quantity> args;
            do {
                const std::optional<Quantity> a = sum(depth + 1);
                if (!a || (!args.empty() && a->length != args[0].length)) return std::nullopt;
                args.push_back(*a);
            } while (take(','));
            if (!take(')') || (!is_min && !is_max && args.size() != 3)) return std::nullopt;
            Quantity out = args[0];
            if (is_min || is_max)
                for (const Quantity& a : args)
                    out.v = is_min ? std::min(out.v, a.v) : std::max(out.v, a.v);
            else
                out.v = std::max(args[0].v, std::min(args[1].v, args[2].v));
            return out;
        }
        return leaf();
    }

    std::optional<Quantity> closed(std::optional<Quantity> q) {
        if (!q || !take(')')) return std::nullopt;
        return q;
    }

    // A number, a dimension or a percentage.
    std::optional<Quantity> leaf() {
        const std::size_t start = i_;
        if (i_ < s_.size() && (s_[i_] == '+' || s_[i_] == '-')) ++i_;
        double v;
        const auto [end, ec] = std::from_chars(s_.data() + i_, s_.data() + s_.size(), v);
        if (ec != std::errc()) return std::nullopt;
        i_ = std::size_t(end - s_.data());
        const std::size_t unit = i_;
        while (i_ < s_.size() &&
               (std::isalpha(static_cast<unsigned char>(s_[i_])) || s_[i_] == '%'))
            ++i_;
        const std::string_view text = s_.substr(start, i_ - start);
        if (i_ == unit) {
            if (text.front() == '-') v = -v;
            return Quantity{v, false};
        }
        const std::optional<double> len = leaf_(text);
        if (!len) return std::nullopt;
        return Quantity{*len, true};
    }

    std::string_view s_;
    std::size_t i_ = 0;
    const std::function<std::optional<double>(std::string_view)>& leaf_;
};

} // namespace

bool is_css_math(std::string_view text) {
    text = svg_detail::trim(text);
    for (const std::string_view f : {"calc(", "min(", "max(", "clamp("})
        if (text.size() > f.size() && iequals(text.substr(0, f.size()), f)) return true;
    return false;
}

std::optional<double>
eval_css_math(std::string_view text,
              const std::function<std::optional<double>(std::string_view)>& leaf) {
    const std::optional<Quantity> q = MathParser(svg_detail::trim(text), leaf).whole();
    if (!q || !std::isfinite(q->v)) return std::nullopt;
    return q->v;
}

} // namespace casteljau
