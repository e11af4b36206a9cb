// The filter property (Filter Effects 1, 11): <filter> elements and CSS
// filter functions, resolved at read time into the group's filters
// (scene Filter, filter/graph.h).
//
// A <filter> (Filter Effects 1, 8): its region x, y, width, height in
// filterUnits (objectBoundingBox by default, -10%, -10%, 120%, 120%), its
// primitives' lengths in primitiveUnits (userSpaceOnUse by default), its
// attributes and, when it has none, its primitives inherited along its href
// chain. Each primitive's subregion (9.7) defaults, attribute by attribute,
// to the union of its inputs' subregions, or to the filter region when an
// input is a standard one, when it has no input, and for feTile. `in`
// names a standard input or the closest preceding `result`; a name that
// no primitive has is as if `in` were not given (9.6): the previous
// result, or SourceGraphic for the first primitive.
//
// Errors (8.3 and resvg's reading of it, which browsers share): a url that
// names no <filter>, a filter with no primitives, a region or a primitive
// subregion with no area, or objectBoundingBox units on an element whose box
// has no area: the element is not drawn, with a warning. Elements that are not primitives
// are ignored. A CSS filter function (12.2) is its own one-primitive
// graph in sRGB, over the element's box with its strokes, grown by what a
// blur or shadow spreads.
#include "casteljau/filter/color_transform.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/filter_functions.h"
#include "casteljau/svg/shapes.h"

#include <cmath>

namespace casteljau::svg_detail {

namespace {

// The box of what g draws, strokes included, in user space (to_user from device).
Rect ink_box(const Group& g, const Affine& to_user) {
    Rect r = Rect::empty();
    for (const Node& n : g.children) {
        if (const Group* c = std::get_if<Group>(&n.item)) {
            r = r.united(ink_box(*c, to_user));
            continue;
        }
        const Shape& s = std::get<Shape>(n.item);
        Path p = s.path;
        p.transform(to_user * s.transform);
        Rect b = p.bounds();
        if (s.stroke) {
            const StrokeGeometry& sg = s.stroke->geometry;
            b = b.inflated(0.5 * sg.width * std::max(sg.miter_limit, std::sqrt(2.0)) *
                           (to_user * s.transform).max_scale());
        }
        r = r.united(b);
    }
    return r;
}

ComponentTransfer linear_rgb_transfer(float slope, float intercept) {
    ComponentTransfer t;
    for (int c = 0; c < 3; ++c) {
        t.f[std::size_t(c)].type = TransferFunction::Type::Linear;
        t.f[std::size_t(c)].slope = slope;
        t.f[std::size_t(c)].intercept = intercept;
    }
    return t;
}

// Filter Effects 1, 12.2: the equivalent of each function.
FilterOp function_op(const FilterItem& item, Rgba current) {
    using K = FilterItem::Kind;
    const float a = float(item.amount), r = 1 - a;
    switch (item.kind) {
    case K::Blur:
        return GaussianBlur{item.amount, item.amount, EdgeMode::None};
    case K::DropShadow:
        return DropShadow{item.amount, item.amount, item.dx, item.dy, item.color.value_or(current)};
    case K::Brightness:
        return linear_rgb_transfer(a, 0);
    case K::Contrast:
        return linear_rgb_transfer(a, 0.5f - 0.5f * a);
    case K::Grayscale:
        return ColorMatrix{{0.2126f + 0.7874f * r,
                            0.7152f - 0.7152f * r,
                            0.0722f - 0.0722f * r,
                            0,
                            0,
                            0.2126f - 0.2126f * r,
                            0.7152f + 0.2848f * r,
                            0.0722f - 0.0722f * r,
                            0,
                            0,
                            0.2126f - 0.2126f * r,
                            0.7152f - 0.7152f * r,
                            0.0722f + 0.9278f * r,
                            0,
                            0,
                            0,
                            0,
                            0,
                            1,
                            0}};
    case K::HueRotate:
        return hue_rotate_matrix(item.amount);
    case K::Invert: {
        ComponentTransfer t;
        for (int c = 0; c < 3; ++c) {
            t.f[std::size_t(c)].type = TransferFunction::Type::Table;
            t.f[std::size_t(c)].table = {a, 1 - a};
        }
        return t;
    }
    case K::Opacity: {
        ComponentTransfer t;
        t.f[3].type = TransferFunction::Type::Table;
        t.f[3].table = {0, a};
        return t;
    }
    case K::Saturate:
        return saturate_matrix(a);
    case K::Sepia:
        return ColorMatrix{{0.393f + 0.607f * r,
                            0.769f - 0.769f * r,
                            0.189f - 0.189f * r,
                            0,
                            0,
                            0.349f - 0.349f * r,
                            0.686f + 0.314f * r,
                            0.168f - 0.168f * r,
                            0,
                            0,
                            0.272f - 0.272f * r,
                            0.534f - 0.534f * r,
                            0.131f + 0.869f * r,
                            0,
                            0,
                            0,
                            0,
                            0,
                            1,
                            0}};
    case K::Url:
        break;
    }
    return ColorMatrix{};
}

// How far a function's result spreads beyond its input (user units).
double function_spread(const FilterItem& item) {
    if (item.kind == FilterItem::Kind::Blur) return 3 * item.amount;
    if (item.kind == FilterItem::Kind::DropShadow)
        return 3 * item.amount + std::max(std::fabs(item.dx), std::fabs(item.dy));
    return 0;
}

} // namespace

bool Reader::apply_filters(const pugi::xml_node& n, const ElementProps& props, const Affine& m,
                           Group& g, const BoxOf& bbox, int depth) {
    ElementProps own;
    const StyleState style = style_of(n, own);
    const auto items = parse_filter_list(props.filter, context(style));
    if (!items) return true; // checked by the cascade already
    const Affine to_user = m.inverse();
    for (const FilterItem& item : *items) {
        if (item.kind != FilterItem::Kind::Url) {
            const Rect ink = ink_box(g, to_user);
            if (ink.is_empty()) continue; // draws nothing: nothing to filter
            auto f = std::make_shared<Filter>();
            f->transform = m;
            f->graph.region = ink.inflated(function_spread(item));
            f->graph.primitives.push_back(
                {function_op(item, style.color), {}, f->graph.region, false});
            g.filters.push_back(std::move(f));
            continue;
        }
        const pugi::xml_node t = by_id(item.id);
        if (!t || std::strcmp(t.name(), "filter") != 0) {
            problem(n, "url(#" + item.id + ") names no <filter>; the element is not drawn");
            return false;
        }
        if (std::find(instancing_.begin(), instancing_.end(), t) != instancing_.end()) {
            problem(n, "<filter> #" + item.id + " refers back to itself; the element is not drawn");
            return false;
        }
        std::shared_ptr<Filter> f = filter_element(n, t, m, bbox, depth);
        if (!f) return false;
        g.filters.push_back(std::move(f));
    }
    return true;
}

std::shared_ptr<Filter> Reader::filter_element(const pugi::xml_node& n, const pugi::xml_node& f,
                                               const Affine& m, const BoxOf& bbox, int depth) {
    const std::vector<pugi::xml_node> chain = same_kind_chain(f);
    const bool region_obb = units_of(chain, "filterUnits", true);
    PrimitiveUnits pu{units_of(chain, "primitiveUnits", false), Rect::empty()};
    if (region_obb || pu.obb) {
        pu.bbox = bbox();
        if (!(pu.bbox.width() > 0 && pu.bbox.height() > 0)) {
            problem(n, "a filter in objectBoundingBox units on an element with no area; not drawn");
            return nullptr;
        }
    }
    ElementProps fprops;
    const LengthContext ctx = context(style_of(f, fprops));
    const auto at = [&](const char* name, double initial, double full) {
        const pugi::xml_attribute a = chain_attribute(chain, name);
        const auto v = a ? parse_length(a.value(), region_obb ? 1 : full, ctx) : std::nullopt;
        if (a && !v) problem(f, std::string(name) + ": '" + a.value() + "' is not a length");
        return v.value_or(region_obb ? initial : initial * full);
    };
    double x = at("x", -0.1, vw_), y = at("y", -0.1, vh_);
    double w = at("width", 1.2, vw_), h = at("height", 1.2, vh_);
    if (region_obb) {
        const Rect& b = pu.bbox;
        x = b.x0 + x * b.width(), y = b.y0 + y * b.height();
        w *= b.width(), h *= b.height();
    }
    if (!(w > 0 && h > 0)) {
        problem(f, "the filter region has no area; the element is not drawn");
        return nullptr;
    }
    auto out = std::make_shared<Filter>();
    out->transform = m;
    out->graph.region = {x, y, x + w, y + h};
    // The primitives: the first filter of the chain that has any.
    pugi::xml_node source = f;
    for (const pugi::xml_node& e : chain)
        if (e.find_child([](const pugi::xml_node& c) { return c.type() == pugi::node_element; })) {
            source = e;
            break;
        }
    instancing_.push_back(f);
    const bool ok = read_primitives(source, pu, m, *out, depth);
    instancing_.pop_back();
    if (!ok) return nullptr;
    filter_paints(n, m, *out);
    if (out->graph.primitives.empty()) {
        problem(f, "a filter with no primitives; the element is not drawn");
        return nullptr;
    }
    return out;
}

// FillPaint and StrokePaint (9.6): the element's fill and stroke paints
// over the filter region (their opacities apart, as the spec has "the value
// of the fill property"), drawn only when a primitive reads them.
void Reader::filter_paints(const pugi::xml_node& n, const Affine& m, Filter& f) {
    bool fill = false, stroke = false;
    for (const FilterPrimitive& p : f.graph.primitives)
        for (int k : p.inputs) {
            fill = fill || k == filter_input::kFillPaint;
            stroke = stroke || k == filter_input::kStrokePaint;
        }
    if (!fill && !stroke) return;
    ElementProps props;
    const StyleState style = style_of(n, props);
    const Rect& r = f.graph.region;
    const Path path = rect_path(r.x0, r.y0, r.width(), r.height(), 0, 0);
    const auto draw = [&](const PaintSpec& spec, Group& out) {
        const auto p = paint(n, spec, style, path, m);
        if (!p) return;
        Shape s;
        s.path = path;
        s.transform = m;
        s.fill = Fill{p->color, p->gradient, 1, FillRule::NonZero, p->pattern};
        out.children.push_back(Node{std::move(s)});
    };
    if (fill) draw(style.fill, f.fill_paint);
    if (stroke) draw(style.stroke, f.stroke_paint);
}

} // namespace casteljau::svg_detail
