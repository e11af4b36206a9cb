// Filter primitive elements (Filter Effects 1, 15) read into FilterOps, and
// their inputs and subregions (9.6, 9.7); see svg/filters.cpp.
//
// Attribute defaults and errors, per primitive, as the spec gives them: a
// number list of the wrong length or a malformed number is an error, and
// the attribute takes its initial value (feColorMatrix's values then the
// identity); a negative stdDeviation or radius disables the primitive
// (its result is its input); an invalid feConvolveMatrix (a kernel of the
// wrong size, a target outside it, a zero order) and a lighting primitive
// without a light source give transparent black. In objectBoundingBox
// primitiveUnits, lengths along x are fractions of the box's width, along y
// of its height, and others (a light's z, a displacement scale) of its
// normalised diagonal (SVG 1.1, 7.10).
#include "casteljau/filter/color_transform.h"
#include "casteljau/filter/run.h"
#include "casteljau/svg/detail/reader_impl.h"

#include <cmath>

namespace casteljau::svg_detail {

namespace {

// The most entries a convolution kernel may have (a 32 x 32 one): the work
// per pixel grows with it, and real files use 3 x 3 to 7 x 7. A larger
// order is an error (the primitive is transparent).
constexpr double kMaxKernelTaps = 1024;

// Numbers separated by whitespace and/or a comma; nullopt when malformed.
std::optional<std::vector<double>> numbers(std::string_view v) {
    std::vector<double> out;
    std::string word;
    for (std::size_t i = 0; i <= v.size(); ++i) {
        const char c = i < v.size() ? v[i] : ' ';
        if (c == ',' || std::isspace(static_cast<unsigned char>(c))) {
            if (word.empty()) continue;
            const auto n = parse_number(word);
            if (!n) return std::nullopt;
            out.push_back(*n);
            word.clear();
        } else {
            word += c;
        }
    }
    return out;
}

// 1 or 2 numbers (x, then y = x when alone), or `initial` for both.
std::pair<double, double> number_pair(const pugi::xml_node& e, const char* attr, double initial) {
    const auto v = numbers(e.attribute(attr).value());
    if (!v || v->empty() || v->size() > 2) return {initial, initial};
    return {(*v)[0], v->size() == 2 ? (*v)[1] : (*v)[0]};
}

double number(const pugi::xml_node& e, const char* attr, double initial) {
    const pugi::xml_attribute a = e.attribute(attr);
    if (!a) return initial;
    return parse_number(a.value()).value_or(initial);
}

int standard_input(std::string_view v) {
    using namespace filter_input;
    if (v == "SourceGraphic") return kSourceGraphic;
    if (v == "SourceAlpha") return kSourceAlpha;
    if (v == "BackgroundImage") return kBackgroundImage;
    if (v == "BackgroundAlpha") return kBackgroundAlpha;
    if (v == "FillPaint") return kFillPaint;
    if (v == "StrokePaint") return kStrokePaint;
    return 0;
}

// How many of in, in2 an operation reads (feMerge: its nodes).
std::size_t input_count(const FilterOp& op) {
    if (std::holds_alternative<Flood>(op) || std::holds_alternative<TurbulenceOp>(op) ||
        std::holds_alternative<ImageInput>(op))
        return 0;
    if (std::holds_alternative<Blend>(op) || std::holds_alternative<Composite>(op) ||
        std::holds_alternative<Displacement>(op))
        return 2;
    return 1;
}

EdgeMode edge_mode(const pugi::xml_node& e, EdgeMode initial) {
    const std::string_view v = e.attribute("edgeMode").value();
    return v == "none"        ? EdgeMode::None
           : v == "duplicate" ? EdgeMode::Duplicate
           : v == "wrap"      ? EdgeMode::Wrap
                              : initial;
}

Channel channel(const pugi::xml_node& e, const char* attr) {
    const std::string_view v = e.attribute(attr).value();
    return v == "R" ? Channel::R : v == "G" ? Channel::G : v == "B" ? Channel::B : Channel::A;
}

TransferFunction transfer_function(const pugi::xml_node& fn) {
    using T = TransferFunction::Type;
    TransferFunction t;
    const std::string_view type = fn.attribute("type").value();
    t.type = type == "table"      ? T::Table
             : type == "discrete" ? T::Discrete
             : type == "linear"   ? T::Linear
             : type == "gamma"    ? T::Gamma
                                  : T::Identity;
    if (const auto v = numbers(fn.attribute("tableValues").value()))
        for (double x : *v) t.table.push_back(float(x));
    t.slope = float(number(fn, "slope", 1));
    t.intercept = float(number(fn, "intercept", 0));
    t.amplitude = float(number(fn, "amplitude", 1));
    t.exponent = float(number(fn, "exponent", 1));
    t.offset = float(number(fn, "offset", 0));
    return t;
}

ColorMatrix color_matrix_of(const pugi::xml_node& e) {
    const std::string_view type = e.attribute("type").value();
    const auto v = numbers(e.attribute("values").value());
    const bool one = v && v->size() == 1;
    if (type == "saturate") return saturate_matrix(one ? float(std::max(0.0, (*v)[0])) : 1.0f);
    if (type == "hueRotate") return hue_rotate_matrix(one ? (*v)[0] : 0.0);
    if (type == "luminanceToAlpha") return luminance_to_alpha_matrix();
    ColorMatrix m;
    if (v && v->size() == 20)
        for (std::size_t i = 0; i < 20; ++i) m.m[i] = float((*v)[i]);
    return m;
}

std::optional<Convolve> convolve_of(const pugi::xml_node& e) {
    Convolve c;
    const auto order = numbers(e.attribute("order").value());
    if (e.attribute("order")) {
        if (!order || order->empty() || order->size() > 2) return std::nullopt;
        const double ox = (*order)[0], oy = order->size() == 2 ? (*order)[1] : ox;
        if (ox < 1 || oy < 1 || ox != std::floor(ox) || oy != std::floor(oy) ||
            ox * oy > kMaxKernelTaps)
            return std::nullopt;
        c.m.order_x = int(ox), c.m.order_y = int(oy);
    }
    const auto k = numbers(e.attribute("kernelMatrix").value());
    if (!k || k->size() != std::size_t(c.m.order_x * c.m.order_y)) return std::nullopt;
    double sum = 0;
    for (double x : *k) c.m.kernel.push_back(float(x)), sum += x;
    // The divisor: the kernel's sum by default, 1 where that is 0; a given 0 is an error.
    const double divisor = number(e, "divisor", sum == 0 ? 1 : sum);
    if (divisor == 0) return std::nullopt;
    c.m.divisor = float(divisor);
    c.m.bias = float(number(e, "bias", 0));
    c.m.target_x = int(number(e, "targetX", c.m.order_x / 2));
    c.m.target_y = int(number(e, "targetY", c.m.order_y / 2));
    if (c.m.target_x < 0 || c.m.target_x >= c.m.order_x || c.m.target_y < 0 ||
        c.m.target_y >= c.m.order_y)
        return std::nullopt;
    c.m.edge = edge_mode(e, EdgeMode::Duplicate);
    c.m.preserve_alpha = std::string_view(e.attribute("preserveAlpha").value()) == "true";
    return c;
}

Composite composite_of(const pugi::xml_node& e) {
    using Op = Composite::Op;
    const std::string_view v = e.attribute("operator").value();
    Composite c;
    c.op = v == "in"           ? Op::In
           : v == "out"        ? Op::Out
           : v == "atop"       ? Op::Atop
           : v == "xor"        ? Op::Xor
           : v == "lighter"    ? Op::Lighter
           : v == "arithmetic" ? Op::Arithmetic
                               : Op::Over;
    c.k1 = float(number(e, "k1", 0)), c.k2 = float(number(e, "k2", 0));
    c.k3 = float(number(e, "k3", 0)), c.k4 = float(number(e, "k4", 0));
    return c;
}

// The light source among a lighting primitive's children, in user space.
std::optional<LightSource> light_of(const pugi::xml_node& e, const PrimitiveUnits& u) {
    const Rect& b = u.bbox;
    const double diag =
        u.obb ? std::sqrt((b.width() * b.width() + b.height() * b.height()) / 2) : 1;
    const auto x = [&](double v) { return u.obb ? b.x0 + v * b.width() : v; };
    const auto y = [&](double v) { return u.obb ? b.y0 + v * b.height() : v; };
    for (const pugi::xml_node& c : e.children()) {
        const std::string_view name = c.name();
        if (name == "feDistantLight")
            return DistantLight{number(c, "azimuth", 0), number(c, "elevation", 0)};
        if (name == "fePointLight")
            return PointLight{x(number(c, "x", 0)), y(number(c, "y", 0)), number(c, "z", 0) * diag};
        if (name == "feSpotLight") {
            SpotLight s{x(number(c, "x", 0)),
                        y(number(c, "y", 0)),
                        number(c, "z", 0) * diag,
                        x(number(c, "pointsAtX", 0)),
                        y(number(c, "pointsAtY", 0)),
                        number(c, "pointsAtZ", 0) * diag,
                        number(c, "specularExponent", 1),
                        std::nullopt};
            if (c.attribute("limitingConeAngle")) s.cone_angle = number(c, "limitingConeAngle", 90);
            return s;
        }
    }
    return std::nullopt;
}

} // namespace

std::optional<FilterOp> Reader::filter_op(const pugi::xml_node& e, const PrimitiveUnits& u,
                                          const StyleState& style, const ElementProps& props,
                                          const Affine& m, Filter& f, int depth) {
    const std::string_view name = e.name();
    const double W = u.obb ? u.bbox.width() : 1, H = u.obb ? u.bbox.height() : 1;
    const double diag = std::sqrt((W * W + H * H) / 2);
    const auto color = [&](const std::optional<Rgba>& c, float opacity) {
        Rgba out = c.value_or(style.color);
        out.a *= opacity;
        return out;
    };
    const Flood transparent{{0, 0, 0, 0}};
    if (name == "feGaussianBlur") {
        const auto [sx, sy] = number_pair(e, "stdDeviation", 0);
        if (sx < 0 || sy < 0) return GaussianBlur{}; // 15.15: disabled, the input as it is
        return GaussianBlur{sx * W, sy * H, edge_mode(e, EdgeMode::None)};
    }
    if (name == "feOffset") return Offset{number(e, "dx", 0) * W, number(e, "dy", 0) * H};
    if (name == "feFlood") return Flood{color(props.flood_color, props.flood_opacity)};
    if (name == "feBlend")
        return Blend{parse_blend_mode(e.attribute("mode").value()).value_or(BlendMode::Normal)};
    if (name == "feComposite") return composite_of(e);
    if (name == "feMerge") return Merge{};
    if (name == "feColorMatrix") return color_matrix_of(e);
    if (name == "feComponentTransfer") {
        ComponentTransfer t;
        const char* funcs[] = {"feFuncR", "feFuncG", "feFuncB", "feFuncA"};
        for (const pugi::xml_node& c : e.children())
            for (std::size_t k = 0; k < 4; ++k)
                if (std::string_view(c.name()) == funcs[k]) t.f[k] = transfer_function(c);
        return t;
    }
    if (name == "feMorphology") {
        const auto [rx, ry] = number_pair(e, "radius", 0);
        return Morphology{std::string_view(e.attribute("operator").value()) == "dilate", rx * W,
                          ry * H};
    }
    if (name == "feConvolveMatrix") {
        if (auto c = convolve_of(e)) return *c;
        return transparent;
    }
    if (name == "feTurbulence") {
        const auto [fx, fy] = number_pair(e, "baseFrequency", 0);
        if (fx < 0 || fy < 0) return transparent;
        Turbulence t;
        t.base_x = fx / W, t.base_y = fy / H;
        // Each octave doubles the frequency: past 24 its features are far
        // below a pixel of any frame, and the work would only grow.
        t.octaves = int(std::clamp(number(e, "numOctaves", 1), 0.0, 24.0));
        t.seed = number(e, "seed", 0);
        t.fractal_noise = std::string_view(e.attribute("type").value()) == "fractalNoise";
        t.stitch = std::string_view(e.attribute("stitchTiles").value()) == "stitch";
        return TurbulenceOp{t};
    }
    if (name == "feDisplacementMap")
        return Displacement{number(e, "scale", 0) * diag, channel(e, "xChannelSelector"),
                            channel(e, "yChannelSelector")};
    if (name == "feTile") return Tile{};
    if (name == "feImage") return image_input(e, u, style, m, f, depth);
    if (name == "feDiffuseLighting" || name == "feSpecularLighting") {
        const bool specular = name == "feSpecularLighting";
        const auto light = light_of(e, u);
        const double exponent = number(e, "specularExponent", 1);
        if (!light || (specular && !(exponent >= 1 && exponent <= 128))) return transparent;
        Lighting l;
        l.specular = specular;
        l.surface_scale = number(e, "surfaceScale", 1);
        l.constant = number(e, specular ? "specularConstant" : "diffuseConstant", 1);
        l.specular_exponent = exponent;
        const Rgba c = color(props.lighting_color, 1);
        l.color = {c.r, c.g, c.b, 1};
        l.light = *light;
        return LightingOp{l};
    }
    if (name == "feDropShadow") {
        const auto [sx, sy] = number_pair(e, "stdDeviation", 2);
        return DropShadow{std::max(0.0, sx) * W, std::max(0.0, sy) * H, number(e, "dx", 2) * W,
                          number(e, "dy", 2) * H, color(props.flood_color, props.flood_opacity)};
    }
    return std::nullopt;
}

// feImage: an element of this document drawn as <use> would draw it, or an
// image file fitted into the primitive's subregion (the filter region by
// default) as <image> fits it into its viewport (preserveAspectRatio), in
// the filtered element's user space.
FilterOp Reader::image_input(const pugi::xml_node& e, const PrimitiveUnits& u,
                             const StyleState& style, const Affine& m, Filter& f, int depth) {
    Group content;
    const char* href = href_of(e);
    if (href[0] == '#') {
        const pugi::xml_node t = by_id(href + 1);
        if (!t || std::find(instancing_.begin(), instancing_.end(), t) != instancing_.end()) {
            problem(e,
                    std::string("href '") + href + "' names no element it can draw; transparent");
        } else {
            ElementProps unused;
            const StyleState parent = style_of(t.parent(), unused);
            instancing_.push_back(t);
            element(t, parent, m, content, depth + 1);
            instancing_.pop_back();
        }
    } else if (href[0]) {
        const Rect port =
            subregion(e, u, FilterPrimitive{ImageInput{}, {}, {}, true}, f.graph, style);
        if (port.width() > 0 && port.height() > 0) image(e, style, m, content, &port);
    }
    f.images.push_back(std::move(content));
    return ImageInput{int(f.images.size()) - 1};
}

bool Reader::read_primitives(const pugi::xml_node& filter, const PrimitiveUnits& u, const Affine& m,
                             Filter& f, int depth) {
    FilterGraph& g = f.graph;
    std::map<std::string, int, std::less<>> results;
    const auto input = [&](const pugi::xml_node& e, const char* attr) {
        const std::string_view v = e.attribute(attr).value();
        if (const int k = standard_input(v)) return k;
        if (const auto it = results.find(v); !v.empty() && it != results.end()) return it->second;
        return g.primitives.empty() ? filter_input::kSourceGraphic : int(g.primitives.size()) - 1;
    };
    for (const pugi::xml_node& e : filter.children()) {
        if (e.type() != pugi::node_element) continue;
        if (g.primitives.size() >= kMaxFilterPrimitives) {
            problem(e, "more than " + std::to_string(kMaxFilterPrimitives) +
                           " filter primitives (the limit); the rest are ignored");
            break;
        }
        ElementProps props;
        const StyleState style = style_of(e, props);
        std::optional<FilterOp> op = filter_op(e, u, style, props, m, f, depth);
        if (!op) continue;
        FilterPrimitive p{std::move(*op), {}, g.region, style.filters_linear};
        if (std::holds_alternative<Merge>(p.op)) {
            for (const pugi::xml_node& node : e.children("feMergeNode"))
                p.inputs.push_back(input(node, "in"));
        } else {
            const std::size_t n = input_count(p.op);
            if (n >= 1) p.inputs.push_back(input(e, "in"));
            if (n >= 2) p.inputs.push_back(input(e, "in2"));
        }
        p.subregion = subregion(e, u, p, g, style);
        if (!(p.subregion.width() > 0 && p.subregion.height() > 0)) {
            // A subregion with no area is an error that disables the whole
            // element, as resvg and browsers have it, not this primitive alone.
            problem(e, "a primitive subregion with no area; the element is not drawn");
            return false;
        }
        if (const char* r = e.attribute("result").value(); r[0])
            results[r] = int(g.primitives.size());
        g.primitives.push_back(std::move(p));
    }
    return true;
}

// 9.7: x, y, width, height each default to the union of the inputs'
// subregions, or to the filter region's.
Rect Reader::subregion(const pugi::xml_node& e, const PrimitiveUnits& u, const FilterPrimitive& p,
                       const FilterGraph& g, const StyleState& style) {
    Rect d = Rect::empty();
    bool whole = p.inputs.empty() || std::holds_alternative<Tile>(p.op);
    for (int k : p.inputs) {
        if (k < 0)
            whole = true;
        else
            d = d.united(g.primitives[std::size_t(k)].subregion);
    }
    if (whole) d = g.region;
    const LengthContext ctx = context(style);
    const auto at = [&](const char* attr, double origin, double size,
                        double full) -> std::optional<double> {
        const pugi::xml_attribute a = e.attribute(attr);
        if (!a) return std::nullopt;
        const auto v = parse_length(a.value(), u.obb ? 1 : full, ctx);
        if (!v) return std::nullopt;
        return u.obb ? origin + *v * size : *v;
    };
    const Rect& b = u.bbox;
    const double x = at("x", b.x0, b.width(), vw_).value_or(d.x0);
    const double y = at("y", b.y0, b.height(), vh_).value_or(d.y0);
    const double w = at("width", 0, b.width(), vw_).value_or(d.x1 - d.x0);
    const double h = at("height", 0, b.height(), vh_).value_or(d.y1 - d.y0);
    if (!(w >= 0 && h >= 0)) return Rect::empty();
    return {x, y, x + w, y + h};
}

} // namespace casteljau::svg_detail
