#include "casteljau/svg/transform_list.h"

#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/style.h"

#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <optional>

namespace casteljau {

using svg_detail::iequals;
using svg_detail::trim;

namespace {

bool is_space(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }
bool is_sep(char c) { return is_space(c) || c == ','; }
bool is_unit_char(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '%'; }

// 'text' followed by `what`. (Built by appending: GCC 12 warns falsely,
// -Wrestrict, about the same made of operator+.)
std::string quoted(std::string_view text, std::string_view what) {
    std::string s = "'";
    s.append(text).append("' ").append(what);
    return s;
}

// One argument as written: its number, its unit ("" for none), and its text
// (for parse_length's units).
struct Arg {
    double value;
    std::string_view unit, text;
};

// A number and the unit that follows it, at s[i]; i moves past them.
std::optional<Arg> number_at(std::string_view s, std::size_t& i) {
    const std::size_t start = i;
    const std::size_t digits = i + (i < s.size() && s[i] == '+' ? 1 : 0);
    double v;
    const auto [end, ec] = std::from_chars(s.data() + digits, s.data() + s.size(), v);
    if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    const std::size_t unit = std::size_t(end - s.data());
    i = unit;
    while (i < s.size() && is_unit_char(s[i])) ++i;
    return Arg{v, s.substr(unit, i - unit), s.substr(start, i - start)};
}

// The arguments between the parentheses. The attribute's: separated by
// whitespace, a comma or both, or by nothing before a sign or a point
// ("10-5"). CSS's: by one comma each, whitespace around it.
bool parse_args(std::string_view s, TransformSyntax syntax, std::vector<Arg>& out) {
    out.clear();
    std::size_t i = 0;
    while (true) {
        const std::size_t gap = i;
        int commas = 0;
        while (i < s.size() && is_space(s[i])) ++i;
        if (i < s.size() && s[i] == ',') {
            ++i, ++commas;
            while (i < s.size() && is_space(s[i])) ++i;
        }
        if (i == s.size()) return commas == 0;
        if (out.empty() ? commas != 0 : syntax == TransformSyntax::Css && commas != 1) return false;
        if (!out.empty() && i == gap && !(s[i] == '-' || s[i] == '+' || s[i] == '.')) return false;
        const std::optional<Arg> a = number_at(s, i);
        if (!a) return false;
        out.push_back(*a);
    }
}

// The function's arguments converted, or a message of what is wrong.
class Args {
  public:
    Args(const std::vector<Arg>& a, TransformSyntax syntax, const LengthContext& ctx)
        : a_(a), css_(syntax == TransformSyntax::Css), ctx_(ctx) {}

    std::size_t size() const { return a_.size(); }
    bool ok() const { return error_.empty(); }
    const std::string& error() const { return error_; }

    // A plain number (matrix's; scale's, which also takes a percentage).
    double number(std::size_t i, bool percent = false) {
        const Arg& a = a_[i];
        if (a.unit.empty()) return a.value;
        if (percent && a.unit == "%") return a.value / 100;
        return fail(quoted(a.text, "is not a number"));
    }
    // An angle in radians: deg, rad, grad, turn; unitless is degrees in the
    // attribute, only 0 in CSS.
    double angle(std::size_t i) {
        const Arg& a = a_[i];
        if (a.unit.empty() && (!css_ || a.value == 0)) return degrees_to_radians(a.value);
        const std::pair<std::string_view, double> units[] = {{"deg", std::numbers::pi / 180},
                                                             {"rad", 1},
                                                             {"grad", std::numbers::pi / 200},
                                                             {"turn", 2 * std::numbers::pi}};
        for (const auto& [unit, radians] : units)
            if (iequals(a.unit, unit)) return a.value * radians;
        return fail(quoted(a.text, "is not an angle"));
    }
    // A length in user units, and a percentage as a fraction of the
    // reference box's side (when `fraction` is given); unitless is user
    // units in the attribute, only 0 in CSS.
    double length(std::size_t i, double* fraction = nullptr) {
        const Arg& a = a_[i];
        if (a.unit == "%" && fraction) {
            *fraction = a.value / 100;
            return 0;
        }
        if (a.unit.empty() && css_ && a.value != 0) return fail(quoted(a.text, "has no unit"));
        if (a.unit != "%")
            if (const auto v = parse_length(a.text, 0, ctx_)) return *v;
        return fail(quoted(a.text, "is not a length"));
    }

  private:
    double fail(std::string message) {
        if (error_.empty()) error_ = std::move(message);
        return 0;
    }
    const std::vector<Arg>& a_;
    bool css_;
    const LengthContext& ctx_;
    std::string error_;
};

// One function's step, or an error message.
std::string step_of(std::string_view name, Args& a, TransformSyntax syntax,
                    TransformSteps::Step& step) {
    const bool css = syntax == TransformSyntax::Css;
    const auto is = [&](std::string_view n) { return css ? iequals(name, n) : name == n; };
    const std::size_t n = a.size();
    const auto count = [&](std::size_t lo, std::size_t hi) { return n >= lo && n <= hi; };
    Affine& m = step.m;
    Vec2& f = step.box_fraction;
    bool known = true, counted = true;
    if (is("matrix")) {
        if ((counted = n == 6))
            m = {a.number(0), a.number(1), a.number(2), a.number(3), a.number(4), a.number(5)};
    } else if (is("translate")) {
        if ((counted = count(1, 2)))
            m = Affine::translate({a.length(0, &f.x), n == 2 ? a.length(1, &f.y) : 0});
    } else if (is("translateX") || is("translateY")) {
        const bool y = name.back() == 'Y' || name.back() == 'y';
        if ((counted = n == 1))
            m = Affine::translate(y ? Vec2{0, a.length(0, &f.y)} : Vec2{a.length(0, &f.x), 0});
    } else if (is("scale")) {
        if ((counted = count(1, 2))) {
            const double sx = a.number(0, true);
            m = Affine::scale(sx, n == 2 ? a.number(1, true) : sx);
        }
    } else if (is("scaleX") || is("scaleY")) {
        const bool y = name.back() == 'Y' || name.back() == 'y';
        if ((counted = n == 1))
            m = y ? Affine::scale(1, a.number(0, true)) : Affine::scale(a.number(0, true), 1);
    } else if (is("rotate") || is("rotateZ")) {
        // rotate(a cx cy) about a point: the attribute's form only.
        if ((counted = n == 1 || (!css && n == 3 && is("rotate")))) {
            m = Affine::rotate(a.angle(0));
            if (n == 3) {
                const Vec2 c{a.length(1), a.length(2)};
                m = Affine::translate(c) * m * Affine::translate(-c);
            }
        }
    } else if (is("skew")) {
        if ((counted = count(1, 2)))
            m = {1, n == 2 ? std::tan(a.angle(1)) : 0, std::tan(a.angle(0)), 1, 0, 0};
    } else if (is("skewX") || is("skewY")) {
        const bool y = name.back() == 'Y' || name.back() == 'y';
        if ((counted = n == 1)) m = y ? Affine::skew_y(a.angle(0)) : Affine::skew_x(a.angle(0));
    } else {
        known = false;
    }
    if (!known) return "unknown transform function '" + std::string(name) + "'";
    if (!counted)
        return std::string(name) + "(): wrong number of arguments (" + std::to_string(n) + ")";
    if (!a.ok()) return std::string(name) + "(): " + a.error();
    // A finite list can still overflow (scale(1e300) twice): the caller
    // checks the product where it is used.
    return "";
}

} // namespace

Affine TransformSteps::at(double w, double h) const {
    Affine out = Affine::identity();
    for (const Step& s : steps)
        out = out * Affine::translate({s.box_fraction.x * w, s.box_fraction.y * h}) * s.m;
    return out;
}

bool TransformSteps::needs_box() const {
    for (const Step& s : steps)
        if (s.box_fraction.x != 0 || s.box_fraction.y != 0) return true;
    return false;
}

TransformParse parse_transform(std::string_view text, TransformSyntax syntax,
                               const LengthContext& ctx) {
    TransformParse r;
    const bool css = syntax == TransformSyntax::Css;
    if (css && iequals(trim(text), "none")) return r;
    std::vector<Arg> args;
    std::size_t i = 0;
    while (true) {
        while (i < text.size() && (css ? is_space(text[i]) : is_sep(text[i]))) ++i;
        if (i == text.size()) {
            // An empty attribute is no transform; CSS has none for that.
            if (css && r.value.steps.empty()) r.error = "empty transform list";
            return r;
        }
        std::size_t j = i;
        while (j < text.size() && std::isalnum(static_cast<unsigned char>(text[j]))) ++j;
        const std::string_view name = text.substr(i, j - i);
        if (!css) // the attribute allows spaces before the parenthesis
            while (j < text.size() && is_space(text[j])) ++j;
        const std::size_t close = text.find(')', j);
        if (name.empty() || j >= text.size() || text[j] != '(' || close == text.npos) {
            r.error = "malformed transform list at '" + std::string(text.substr(i, 20)) + "'";
            return r;
        }
        if (!parse_args(text.substr(j + 1, close - j - 1), syntax, args)) {
            r.error = std::string(name) + "(): arguments are not " +
                      (css ? "comma-separated numbers with units" : "numbers");
            return r;
        }
        Args a(args, syntax, ctx);
        TransformSteps::Step step;
        if (std::string e = step_of(name, a, syntax, step); !e.empty()) {
            r.error = std::move(e);
            return r;
        }
        r.value.steps.push_back(step);
        i = close + 1;
    }
}

TransformResult parse_transform_list(std::string_view text) {
    TransformParse p = parse_transform(text, TransformSyntax::Attribute, LengthContext{});
    if (p.error.empty() && p.value.needs_box()) p.error = "a percentage has no reference box here";
    return {p.error.empty() ? p.value.at(0, 0) : Affine::identity(), std::move(p.error)};
}

} // namespace casteljau
