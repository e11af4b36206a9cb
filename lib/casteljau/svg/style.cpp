#include "casteljau/svg/style.h"

#include "casteljau/svg/color.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace casteljau {

namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::optional<double> parse_number(std::string_view s, std::string_view* rest = nullptr) {
    s = trim(s);
    if (!s.empty() && s.front() == '+') s.remove_prefix(1);
    double v;
    const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    const std::string_view tail = s.substr(std::size_t(end - s.data()));
    if (rest)
        *rest = tail;
    else if (!trim(tail).empty())
        return std::nullopt;
    return v;
}

std::optional<PaintSpec> parse_paint(std::string_view v) {
    v = trim(v);
    if (v == "none") return PaintSpec{PaintSpec::Kind::None, {}, false, {}};
    if (v == "currentColor") return PaintSpec{PaintSpec::Kind::CurrentColor, {}, false, {}};
    if (v.rfind("url(", 0) == 0) {
        const std::size_t close = v.find(')');
        if (close == v.npos) return std::nullopt;
        std::string_view ref = trim(v.substr(4, close - 4));
        if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'') &&
            ref.back() == ref.front())
            ref = ref.substr(1, ref.size() - 2);
        if (ref.empty() || ref.front() != '#') return std::nullopt; // only local references
        const std::string_view fallback = trim(v.substr(close + 1));
        std::optional<PaintSpec> p = PaintSpec{PaintSpec::Kind::None, {}, true, {}};
        if (!fallback.empty() && !(p = parse_paint(fallback))) return std::nullopt;
        p->from_url = true;
        p->url = std::string(ref.substr(1));
        return p;
    }
    if (const auto c = parse_color(v)) return PaintSpec{PaintSpec::Kind::Color, *c, false, {}};
    return std::nullopt;
}

std::optional<float> parse_opacity(std::string_view v) {
    std::string_view rest;
    auto n = parse_number(v, &rest);
    if (!n) return std::nullopt;
    rest = trim(rest);
    if (rest == "%")
        *n /= 100;
    else if (!rest.empty())
        return std::nullopt;
    return float(std::clamp(*n, 0.0, 1.0));
}

std::optional<std::vector<double>> parse_dashes(std::string_view v) {
    std::vector<double> out;
    if (trim(v) == "none") return out;
    std::string token;
    for (std::size_t i = 0; i <= v.size(); ++i) {
        if (i == v.size() || v[i] == ',' || std::isspace(static_cast<unsigned char>(v[i]))) {
            if (!token.empty()) {
                const auto d = parse_length(token);
                if (!d || *d < 0) return std::nullopt;
                out.push_back(*d);
                token.clear();
            }
        } else {
            token += v[i];
        }
    }
    return out;
}

std::string bad(std::string_view name, std::string_view value, const char* expected) {
    return "property " + std::string(name) + ": '" + std::string(value) + "' is not " + expected;
}

} // namespace

std::optional<double> parse_length(std::string_view text, double percent_of) {
    std::string_view unit;
    const auto v = parse_number(text, &unit);
    if (!v) return std::nullopt;
    unit = trim(unit);
    // CSS absolute units at 96 px per inch; em and ex at the initial font
    // size of 16 px (font properties are outside the supported subset).
    double k = 1;
    if (unit.empty() || unit == "px")
        k = 1;
    else if (unit == "pt")
        k = 96.0 / 72;
    else if (unit == "pc")
        k = 16;
    else if (unit == "mm")
        k = 96 / 25.4;
    else if (unit == "cm")
        k = 96 / 2.54;
    else if (unit == "in")
        k = 96;
    else if (unit == "em")
        k = 16;
    else if (unit == "ex")
        k = 8;
    else if (unit == "%")
        k = percent_of / 100;
    else
        return std::nullopt;
    return *v * k;
}

std::optional<Rgba> resolve_paint(const PaintSpec& p, const StyleState& s) {
    switch (p.kind) {
    case PaintSpec::Kind::None:
        return std::nullopt;
    case PaintSpec::Kind::Color:
        return p.color;
    case PaintSpec::Kind::CurrentColor:
        return s.color;
    }
    return std::nullopt;
}

std::string apply_property(std::string_view name, std::string_view value, const StyleState& parent,
                           StyleState& s, ElementProps& props) {
    value = trim(value);
    const bool inherit = value == "inherit";
    const auto paint = [&](PaintSpec& target, const PaintSpec& from) -> std::string {
        if (inherit) return target = from, "";
        const auto p = parse_paint(value);
        if (!p) return bad(name, value, "a paint (none, a color, currentColor or url(#id))");
        target = *p;
        return "";
    };
    const auto opacity = [&](float& target, float from) -> std::string {
        if (inherit) return target = from, "";
        const auto o = parse_opacity(value);
        if (!o) return bad(name, value, "an opacity");
        target = *o;
        return "";
    };
    if (name == "fill") return paint(s.fill, parent.fill);
    if (name == "stroke") return paint(s.stroke, parent.stroke);
    if (name == "fill-opacity") return opacity(s.fill_opacity, parent.fill_opacity);
    if (name == "stroke-opacity") return opacity(s.stroke_opacity, parent.stroke_opacity);
    if (name == "opacity") return opacity(props.opacity, 1.0f);
    if (name == "fill-rule") {
        if (inherit)
            s.fill_rule = parent.fill_rule;
        else if (value == "nonzero")
            s.fill_rule = FillRule::NonZero;
        else if (value == "evenodd")
            s.fill_rule = FillRule::EvenOdd;
        else
            return bad(name, value, "nonzero or evenodd");
        return "";
    }
    if (name == "color") {
        if (inherit) return s.color = parent.color, "";
        const auto c = parse_color(value);
        if (!c) return bad(name, value, "a color");
        s.color = *c;
        return "";
    }
    if (name == "stroke-width" || name == "stroke-miterlimit" || name == "stroke-dashoffset") {
        double& target = name == "stroke-width"        ? s.stroke_width
                         : name == "stroke-miterlimit" ? s.miter_limit
                                                       : s.dash_offset;
        const double from = name == "stroke-width"        ? parent.stroke_width
                            : name == "stroke-miterlimit" ? parent.miter_limit
                                                          : parent.dash_offset;
        if (inherit) return target = from, "";
        const auto v = parse_length(value);
        if (!v || (name != "stroke-dashoffset" && *v < 0) ||
            (name == "stroke-miterlimit" && *v < 1))
            return bad(name, value,
                       name == "stroke-miterlimit" ? "a number >= 1" : "a valid length");
        target = *v;
        return "";
    }
    if (name == "stroke-dasharray") {
        if (inherit) return s.dashes = parent.dashes, "";
        const auto d = parse_dashes(value);
        if (!d) return bad(name, value, "a list of non-negative lengths");
        s.dashes = *d;
        return "";
    }
    if (name == "stroke-linejoin") {
        if (inherit)
            s.stroke_join = parent.stroke_join;
        else if (value == "miter")
            s.stroke_join = LineJoin::Miter;
        else if (value == "round")
            s.stroke_join = LineJoin::Round;
        else if (value == "bevel")
            s.stroke_join = LineJoin::Bevel;
        else
            return bad(name, value, "miter, round or bevel");
        return "";
    }
    if (name == "stroke-linecap") {
        if (inherit)
            s.stroke_cap = parent.stroke_cap;
        else if (value == "butt")
            s.stroke_cap = LineCap::Butt;
        else if (value == "round")
            s.stroke_cap = LineCap::Round;
        else if (value == "square")
            s.stroke_cap = LineCap::Square;
        else
            return bad(name, value, "butt, round or square");
        return "";
    }
    if (name == "display") {
        props.display_none = value == "none";
        return "";
    }
    if (name == "visibility") {
        if (inherit)
            s.visible = parent.visible;
        else
            s.visible = value == "visible";
        return "";
    }
    return "";
}

std::string apply_style_attribute(std::string_view css, const StyleState& parent, StyleState& style,
                                  ElementProps& props) {
    while (!css.empty()) {
        const std::size_t semi = css.find(';');
        const std::string_view decl = css.substr(0, semi);
        css = semi == css.npos ? std::string_view() : css.substr(semi + 1);
        const std::size_t colon = decl.find(':');
        if (trim(decl).empty()) continue;
        if (colon == decl.npos)
            return "style: malformed declaration '" + std::string(trim(decl)) + "'";
        std::string_view value = trim(decl.substr(colon + 1));
        if (value.size() > 10 && value.substr(value.size() - 10) == "!important")
            value = trim(value.substr(0, value.size() - 10));
        const std::string e =
            apply_property(trim(decl.substr(0, colon)), value, parent, style, props);
        if (!e.empty()) return e;
    }
    return "";
}

} // namespace casteljau
