#include "casteljau/svg/transform_list.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <vector>

namespace casteljau {

namespace {

bool is_sep(char c) { return std::isspace(static_cast<unsigned char>(c)) || c == ','; }

// The numbers between the parentheses, or false on anything malformed.
bool parse_args(std::string_view s, std::vector<double>& out) {
    out.clear();
    std::size_t i = 0;
    while (true) {
        while (i < s.size() && is_sep(s[i])) ++i;
        if (i == s.size()) return true;
        const std::size_t start = i + (s[i] == '+' ? 1 : 0);
        double v;
        const auto [end, ec] = std::from_chars(s.data() + start, s.data() + s.size(), v);
        if (ec != std::errc() || !std::isfinite(v)) return false;
        out.push_back(v);
        i = std::size_t(end - s.data());
        if (i < s.size() && !is_sep(s[i]) && s[i] != '-' && s[i] != '+' && s[i] != '.')
            return false;
    }
}

} // namespace

TransformResult parse_transform_list(std::string_view text) {
    TransformResult r;
    std::vector<double> a;
    std::size_t i = 0;
    while (true) {
        while (i < text.size() && is_sep(text[i])) ++i;
        if (i == text.size()) return r;
        std::size_t j = i;
        while (j < text.size() && std::isalpha(static_cast<unsigned char>(text[j]))) ++j;
        const std::string name(text.substr(i, j - i));
        while (j < text.size() && std::isspace(static_cast<unsigned char>(text[j]))) ++j;
        const std::size_t close = text.find(')', j);
        if (name.empty() || j >= text.size() || text[j] != '(' || close == text.npos) {
            r.error = "malformed transform list at '" + std::string(text.substr(i, 20)) + "'";
            return r;
        }
        if (!parse_args(text.substr(j + 1, close - j - 1), a)) {
            r.error = name + "(): arguments are not numbers";
            return r;
        }
        const std::size_t n = a.size();
        const auto bad_count = [&] {
            r.error = name + "(): wrong number of arguments (" + std::to_string(n) + ")";
            return r;
        };
        Affine m;
        if (name == "matrix") {
            if (n != 6) return bad_count();
            m = {a[0], a[1], a[2], a[3], a[4], a[5]};
        } else if (name == "translate") {
            if (n != 1 && n != 2) return bad_count();
            m = Affine::translate({a[0], n == 2 ? a[1] : 0.0});
        } else if (name == "scale") {
            if (n != 1 && n != 2) return bad_count();
            m = Affine::scale(a[0], n == 2 ? a[1] : a[0]);
        } else if (name == "rotate") {
            if (n != 1 && n != 3) return bad_count();
            m = Affine::rotate(degrees_to_radians(a[0]));
            if (n == 3) m = Affine::translate({a[1], a[2]}) * m * Affine::translate({-a[1], -a[2]});
        } else if (name == "skewX" || name == "skewY") {
            if (n != 1) return bad_count();
            m = name == "skewX" ? Affine::skew_x(degrees_to_radians(a[0]))
                                : Affine::skew_y(degrees_to_radians(a[0]));
        } else {
            r.error = "unknown transform function '" + name + "'";
            return r;
        }
        r.transform = r.transform * m;
        i = close + 1;
    }
}

} // namespace casteljau
