#include "casteljau/svg/style.h"

#include "casteljau/paint/blend.h"
#include "casteljau/svg/color.h"
#include "casteljau/svg/css_math.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/filter_functions.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>

namespace casteljau {

namespace {

using svg_detail::iequals;
using svg_detail::trim;

std::optional<PaintSpec> parse_paint(std::string_view v) {
    v = trim(v);
    if (v == "none") return PaintSpec{PaintSpec::Kind::None, {}, false, {}};
    if (iequals(v, "currentColor")) return PaintSpec{PaintSpec::Kind::CurrentColor, {}, false, {}};
    if (v == "context-fill") return PaintSpec{PaintSpec::Kind::ContextFill, {}, false, {}};
    if (v == "context-stroke") return PaintSpec{PaintSpec::Kind::ContextStroke, {}, false, {}};
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

// A reference to an element (markers, clip-path, mask): none, or url(#id)
// (quotes allowed); the id, "" for none.
std::optional<std::string> parse_reference(std::string_view v) {
    v = trim(v);
    if (v == "none") return std::string();
    if (v.rfind("url(", 0) != 0 || v.back() != ')') return std::nullopt;
    std::string_view ref = trim(v.substr(4, v.size() - 5));
    if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'') && ref.back() == ref.front())
        ref = ref.substr(1, ref.size() - 2);
    if (ref.size() < 2 || ref.front() != '#') return std::nullopt;
    return std::string(ref.substr(1));
}

// paint-order: normal, or some of fill, stroke and markers in the order to
// paint them, each at most once; the ones left out follow in their normal
// order. The result gives each its position: fill, stroke, markers.
std::optional<std::array<int, 3>> parse_paint_order(std::string_view v) {
    v = trim(v);
    if (v == "normal") return std::array<int, 3>{0, 1, 2};
    std::vector<int> order;
    for (const std::string_view w : svg_detail::words(v)) {
        const int k = w == "fill" ? 0 : w == "stroke" ? 1 : w == "markers" ? 2 : -1;
        if (k < 0 || std::find(order.begin(), order.end(), k) != order.end()) return std::nullopt;
        order.push_back(k);
    }
    if (order.empty()) return std::nullopt;
    for (int k = 0; k < 3; ++k)
        if (std::find(order.begin(), order.end(), k) == order.end()) order.push_back(k);
    std::array<int, 3> position{};
    for (int p = 0; p < 3; ++p) position[std::size_t(order[std::size_t(p)])] = p;
    return position;
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

std::optional<std::vector<double>> parse_dashes(std::string_view v, const LengthContext& ctx) {
    std::vector<double> out;
    if (trim(v) == "none") return out;
    std::string token;
    for (std::size_t i = 0; i <= v.size(); ++i) {
        if (i == v.size() || v[i] == ',' || std::isspace(static_cast<unsigned char>(v[i]))) {
            if (!token.empty()) {
                const auto d = parse_length(token, ctx.diagonal(), ctx);
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

// The enumerator a keyword names, if it is one of `words`.
template <class E>
std::optional<E> lookup(std::string_view value,
                        std::initializer_list<std::pair<std::string_view, E>> words) {
    for (const auto& [word, e] : words)
        if (value == word) return e;
    return std::nullopt;
}

// A length no smaller than `min`.
std::optional<double> at_least(std::optional<double> v, double min) {
    return v && *v >= min ? v : std::nullopt;
}

} // namespace

std::optional<double> parse_number(std::string_view s, std::string_view* rest) {
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

double LengthContext::diagonal() const {
    return std::sqrt((viewport_w * viewport_w + viewport_h * viewport_h) / 2);
}

std::optional<double> parse_length(std::string_view text, double percent_of,
                                   const LengthContext& ctx) {
    if (is_css_math(text))
        return eval_css_math(
            text, [&](std::string_view leaf) { return parse_length(leaf, percent_of, ctx); });
    std::string_view unit;
    const auto v = parse_number(text, &unit);
    if (!v) return std::nullopt;
    // The unit follows the number directly: "1 px" is not a length.
    if (const std::string_view t = trim(unit); !t.empty() && t.data() != unit.data())
        return std::nullopt;
    unit = trim(unit);
    std::string u(unit);
    std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::tolower(c); });
    const double em = ctx.font_size;
    const double vw = ctx.viewport_w / 100, vh = ctx.viewport_h / 100;
    // CSS absolute units at 96 px per inch (CSS Values 3, 6.2).
    const std::pair<std::string_view, double> units[] = {{"", 1},
                                                         {"px", 1},
                                                         {"in", 96},
                                                         {"cm", 96 / 2.54},
                                                         {"mm", 96 / 25.4},
                                                         {"q", 96 / 101.6},
                                                         {"pt", 96.0 / 72},
                                                         {"pc", 16},
                                                         {"em", em},
                                                         {"ex", em / 2},
                                                         {"ch", em / 2},
                                                         {"rem", ctx.root_font_size},
                                                         {"%", percent_of / 100},
                                                         {"vw", vw},
                                                         {"vh", vh},
                                                         {"vmin", std::min(vw, vh)},
                                                         {"vmax", std::max(vw, vh)}};
    for (const auto& [name, k] : units)
        if (u == name) {
            const double r = *v * k;
            return std::isfinite(r) ? std::optional<double>(r) : std::nullopt;
        }
    return std::nullopt;
}

// font-size (CSS Fonts 4, 2.5): a keyword of the absolute-size scale (medium
// is the initial 16 px), larger or smaller (a factor of 1.2, as browsers
// step), or a non-negative length; em and % against the parent's size.
std::optional<double> parse_font_size(std::string_view v, double parent, const LengthContext& ctx) {
    const std::pair<std::string_view, double> keywords[] = {
        {"xx-small", 16 * 3.0 / 5}, {"x-small", 16 * 3.0 / 4},
        {"small", 16 * 8.0 / 9},    {"medium", 16},
        {"large", 16 * 6.0 / 5},    {"x-large", 16 * 3.0 / 2},
        {"xx-large", 16 * 2.0},     {"xxx-large", 16 * 3.0},
        {"larger", parent * 1.2},   {"smaller", parent / 1.2}};
    for (const auto& [word, px] : keywords)
        if (v == word) return px;
    LengthContext of_parent = ctx;
    of_parent.font_size = parent;
    return at_least(parse_length(v, parent, of_parent), 0);
}

// transform-origin: one to three values, each a length, a percentage or a
// keyword (left, center, right for x; top, center, bottom for y; a single y
// keyword leaves x at center), the third (z) ignored in 2D.
std::optional<BoxPoint> parse_transform_origin(std::string_view v, const LengthContext& ctx) {
    const std::vector<std::string_view> words = svg_detail::words(v);
    if (words.empty() || words.size() > 3) return std::nullopt;
    const auto keyword = [](std::string_view w) -> std::optional<std::pair<char, double>> {
        if (w == "left") return std::pair{'x', 0.0};
        if (w == "right") return std::pair{'x', 1.0};
        if (w == "top") return std::pair{'y', 0.0};
        if (w == "bottom") return std::pair{'y', 1.0};
        if (w == "center") return std::pair{'c', 0.5};
        return std::nullopt;
    };
    double px[2] = {0, 0}, fraction[2] = {0.5, 0.5};
    bool set[2] = {false, false};
    for (std::size_t i = 0; i < std::min<std::size_t>(words.size(), 2); ++i) {
        if (const auto k = keyword(words[i])) {
            // A y keyword first ("top left") puts the other value on x.
            const int axis = k->first == 'y' || (k->first == 'c' && set[0]) ? 1 : 0;
            if (set[axis]) return std::nullopt;
            fraction[axis] = k->second;
            set[axis] = true;
            continue;
        }
        const int axis = set[0] ? 1 : int(i);
        if (set[axis]) return std::nullopt;
        // A percentage as a fraction of the box (100% of 1), a length as is.
        if (const auto f = parse_length(words[i], 1, ctx); f && words[i].back() == '%') {
            fraction[axis] = *f;
        } else if (const auto len = parse_length(words[i], 0, ctx); len && words[i].back() != '%') {
            px[axis] = *len, fraction[axis] = 0;
        } else {
            return std::nullopt;
        }
        set[axis] = true;
    }
    if (words.size() == 3 && !parse_length(words[2], 0, ctx)) return std::nullopt;
    return BoxPoint{{px[0], px[1]}, {fraction[0], fraction[1]}};
}

namespace {

// clip: auto, or rect(top, right, bottom, left), each a length or auto
// (auto: that edge of the viewport), separated by commas or, as CSS 2.1
// also allows, by white space.
std::optional<std::array<std::optional<double>, 4>> parse_clip_rect(std::string_view v,
                                                                    const LengthContext& ctx) {
    std::array<std::optional<double>, 4> r;
    v = trim(v);
    if (iequals(v, "auto")) return r;
    if (v.size() < 6 || !iequals(v.substr(0, 5), "rect(") || v.back() != ')') return std::nullopt;
    v = v.substr(5, v.size() - 6);
    std::size_t n = 0;
    for (std::size_t i = 0; i <= v.size() && n <= 4;) {
        std::size_t end = i;
        while (end < v.size() && v[end] != ',' && !std::isspace(static_cast<unsigned char>(v[end])))
            ++end;
        const std::string_view word = v.substr(i, end - i);
        if (!word.empty()) {
            if (n == 4) return std::nullopt;
            if (!iequals(word, "auto")) {
                const auto len = parse_length(word, 0, ctx);
                if (!len) return std::nullopt;
                r[n] = len;
            }
            ++n;
        }
        i = end + 1;
    }
    if (n != 4) return std::nullopt;
    return r;
}

} // namespace

std::optional<Rgba> resolve_paint(const PaintSpec& p, const StyleState& s) {
    switch (p.kind) {
    case PaintSpec::Kind::None:
    case PaintSpec::Kind::ContextFill: // the reader's: it knows the context element
    case PaintSpec::Kind::ContextStroke:
        return std::nullopt;
    case PaintSpec::Kind::Color:
        return p.color;
    case PaintSpec::Kind::CurrentColor:
        return s.color;
    }
    return std::nullopt;
}

std::string apply_property(std::string_view name, std::string_view value, const StyleState& parent,
                           StyleState& s, ElementProps& props, const LengthContext& ctx) {
    value = trim(value);
    if (auto e = apply_text_property(name, value, parent, s, props, ctx)) return *e;
    const bool inherit = value == "inherit";
    // Every property the same way: `inherit` takes the parent's value, a
    // value that parses is taken, anything else is an error.
    const auto set = [&](auto& target, const auto& from, const auto& parsed,
                         const char* expected) -> std::string {
        if (inherit) return target = from, "";
        if (!parsed) return bad(name, value, expected);
        target = *parsed;
        return "";
    };
    constexpr const char* kPaint =
        "a paint (none, a color, currentColor, context-fill, context-stroke or url(#id))";
    StrokeGeometry& g = s.stroke_geometry;
    const StrokeGeometry& pg = parent.stroke_geometry;
    if (name == "fill") return set(s.fill, parent.fill, parse_paint(value), kPaint);
    constexpr const char* kMarker = "none or url(#id)";
    if (name == "marker-start")
        return set(s.marker_start, parent.marker_start, parse_reference(value), kMarker);
    if (name == "marker-mid")
        return set(s.marker_mid, parent.marker_mid, parse_reference(value), kMarker);
    if (name == "marker-end")
        return set(s.marker_end, parent.marker_end, parse_reference(value), kMarker);
    if (name == "marker") {
        const std::string e =
            set(s.marker_start, parent.marker_start, parse_reference(value), kMarker);
        if (e.empty()) s.marker_mid = s.marker_end = s.marker_start;
        if (e.empty() && inherit)
            s.marker_mid = parent.marker_mid, s.marker_end = parent.marker_end;
        return e;
    }
    if (name == "stroke") return set(s.stroke, parent.stroke, parse_paint(value), kPaint);
    if (name == "fill-opacity")
        return set(s.fill_opacity, parent.fill_opacity, parse_opacity(value), "an opacity");
    if (name == "stroke-opacity")
        return set(s.stroke_opacity, parent.stroke_opacity, parse_opacity(value), "an opacity");
    if (name == "opacity") return set(props.opacity, 1.0f, parse_opacity(value), "an opacity");
    if (name == "color") return set(s.color, parent.color, parse_color(value), "a color");
    if (name == "fill-rule")
        return set(s.fill_rule, parent.fill_rule,
                   lookup<FillRule>(
                       value, {{"nonzero", FillRule::NonZero}, {"evenodd", FillRule::EvenOdd}}),
                   "nonzero or evenodd");
    const double diag = ctx.diagonal();
    if (name == "font-size")
        return set(s.font_size, parent.font_size, parse_font_size(value, parent.font_size, ctx),
                   "a font size");
    if (name == "stroke-width")
        return set(g.width, pg.width, at_least(parse_length(value, diag, ctx), 0),
                   "a non-negative length");
    if (name == "stroke-miterlimit")
        return set(g.miter_limit, pg.miter_limit, at_least(parse_number(value), 1),
                   "a number >= 1");
    if (name == "stroke-dashoffset")
        return set(g.dash_offset, pg.dash_offset, parse_length(value, diag, ctx), "a length");
    if (name == "stroke-dasharray")
        return set(g.dashes, pg.dashes, parse_dashes(value, ctx),
                   "none or a list of non-negative lengths");
    if (name == "stroke-linejoin")
        return set(g.join, pg.join,
                   lookup<LineJoin>(value, {{"miter", LineJoin::Miter},
                                            {"round", LineJoin::Round},
                                            {"bevel", LineJoin::Bevel}}),
                   "miter, round or bevel");
    if (name == "stroke-linecap")
        return set(g.cap, pg.cap,
                   lookup<LineCap>(value, {{"butt", LineCap::Butt},
                                           {"round", LineCap::Round},
                                           {"square", LineCap::Square}}),
                   "butt, round or square");
    if (name == "vector-effect")
        return set(props.non_scaling_stroke, false,
                   lookup<bool>(value, {{"none", false},
                                        {"non-scaling-stroke", true},
                                        {"non-scaling-size", false},
                                        {"non-rotation", false},
                                        {"fixed-position", false}}),
                   "none or non-scaling-stroke");
    if (name == "paint-order")
        return set(s.paint_order, parent.paint_order, parse_paint_order(value),
                   "normal or an order of fill, stroke and markers");
    if (name == "shape-rendering")
        return set(s.antialias, parent.antialias,
                   lookup<bool>(value, {{"auto", true},
                                        {"geometricPrecision", true},
                                        {"crispEdges", false},
                                        {"optimizeSpeed", false}}),
                   "auto, optimizeSpeed, crispEdges or geometricPrecision");
    if (name == "transform-origin")
        return set(props.transform_origin, std::optional<BoxPoint>(),
                   parse_transform_origin(value, ctx), "a transform origin");
    if (name == "transform-box")
        return set(props.transform_box, TransformBox::ViewBox,
                   lookup<TransformBox>(value, {{"view-box", TransformBox::ViewBox},
                                                {"fill-box", TransformBox::FillBox},
                                                {"content-box", TransformBox::FillBox},
                                                {"stroke-box", TransformBox::StrokeBox},
                                                {"border-box", TransformBox::StrokeBox}}),
                   "view-box, fill-box, stroke-box, content-box or border-box");
    constexpr const char* kReference = "none or url(#id)";
    if (name == "clip-path") {
        // A reference, or a basic shape (svg/basic_shape.h): one replaces the other.
        std::optional<BasicShape> shape;
        const std::optional<std::string> id = parse_reference(value);
        if (!id && !inherit && !(shape = parse_basic_shape(value, ctx)))
            return bad(name, value, "none, url(#id), a basic shape or a geometry box");
        props.clip_path = id.value_or(std::string()), props.clip_shape = std::move(shape);
        return "";
    }
    if (name == "mask") return set(props.mask, std::string(), parse_reference(value), kReference);
    if (name == "clip-rule")
        return set(s.clip_rule, parent.clip_rule,
                   lookup<FillRule>(
                       value, {{"nonzero", FillRule::NonZero}, {"evenodd", FillRule::EvenOdd}}),
                   "nonzero or evenodd");
    if (name == "mix-blend-mode")
        return set(props.blend, BlendMode::Normal, parse_mix_blend_mode(value), "a blend mode");
    if (name == "isolation")
        return set(props.isolate, false, lookup<bool>(value, {{"auto", false}, {"isolate", true}}),
                   "auto or isolate");
    if (name == "mask-type")
        return set(props.mask_alpha, false,
                   lookup<bool>(value, {{"luminance", false}, {"alpha", true}}),
                   "luminance or alpha");
    if (name == "color-interpolation-filters")
        return set(s.filters_linear, parent.filters_linear,
                   lookup<bool>(value, {{"auto", false}, {"sRGB", false}, {"linearRGB", true}}),
                   "auto, sRGB or linearRGB");
    if (name == "filter") {
        if (!parse_filter_list(value, ctx))
            return bad(name, value, "none, url(#id) or filter functions");
        props.filter = value == "none" ? std::string() : std::string(value);
        return "";
    }
    // A color or currentColor (nullopt inside), or nothing when invalid.
    const auto color_or_current = [&](std::string_view v) -> std::optional<std::optional<Rgba>> {
        if (iequals(v, "currentColor")) return std::optional<Rgba>();
        if (const auto c = parse_color(v)) return std::optional<Rgba>(*c);
        return std::nullopt;
    };
    if (name == "flood-color")
        return set(props.flood_color, std::optional<Rgba>(Rgba{0, 0, 0, 1}),
                   color_or_current(value), "a color");
    if (name == "flood-opacity")
        return set(props.flood_opacity, 1.0f, parse_opacity(value), "an opacity");
    if (name == "lighting-color")
        return set(props.lighting_color, std::optional<Rgba>(Rgba{1, 1, 1, 1}),
                   color_or_current(value), "a color");
    if (name == "color-interpolation")
        return set(s.linear_rgb, parent.linear_rgb,
                   lookup<bool>(value, {{"auto", false}, {"sRGB", false}, {"linearRGB", true}}),
                   "auto, sRGB or linearRGB");
    if (name == "image-rendering")
        return set(s.smooth_images, parent.smooth_images,
                   lookup<bool>(value, {{"auto", true},
                                        {"optimizeQuality", true},
                                        {"smooth", true},
                                        {"high-quality", true},
                                        {"optimizeSpeed", false},
                                        {"pixelated", false},
                                        {"crisp-edges", false}}),
                   "auto, optimizeQuality, optimizeSpeed, smooth, pixelated or crisp-edges");
    if (name == "clip")
        return set(props.clip_rect, std::array<std::optional<double>, 4>{},
                   parse_clip_rect(value, ctx), "auto or rect(top, right, bottom, left)");
    // overflow: visible and auto show what is outside a viewport; hidden,
    // scroll and clip clip it (SVG 1.1, 14.3.3: auto is visible).
    if (name == "overflow")
        return set(props.overflow_visible, parent.own_overflow,
                   lookup<bool>(value, {{"visible", true},
                                        {"auto", true},
                                        {"hidden", false},
                                        {"scroll", false},
                                        {"clip", false}}),
                   "visible, hidden, scroll, auto or clip");
    if (name == "display") {
        props.display_none = value == "none";
        return "";
    }
    if (name == "visibility")
        return set(s.visible, parent.visible,
                   lookup<bool>(value, {{"visible", true}, {"hidden", false}, {"collapse", false}}),
                   "visible, hidden or collapse");
    return "";
}

} // namespace casteljau
