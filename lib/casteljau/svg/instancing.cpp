// What one element draws in another's place, resolved at read time: <use>
// (its target, or a symbol or svg as a viewport), nested <svg> viewports,
// markers (SVG 2, 13.7: a marker's content drawn at each vertex of a path,
// line, polyline or polygon, as groups after the shape), and, before any of
// it is built, the count of what instancing expands to.
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/viewport.h"

#include <cmath>
#include <numbers>
#include <tuple>

namespace casteljau::svg_detail {

// <use> (SVG 1.1, 5.6; SVG 2, 5.6): the referenced element drawn as if it
// were the use's child, inheriting the use's style, moved by x, y; a
// <symbol> or <svg> becomes a viewport of the use's width and height. A
// reference to itself or to an element being instanced (a cycle) is a
// problem, and nothing is drawn. An element of another file: external_use.cpp.
void Reader::use(const pugi::xml_node& n, const StyleState& parent_style, const StyleState& style,
                 const Affine& m, Group& out, int depth) {
    const std::string_view href = use_href(n);
    if (href.empty()) return;
    if (href[0] != '#') return external_use(n, href, parent_style, style, m, out, depth);
    local_use(n, by_id(std::string(href.substr(1))), "href '" + std::string(href) + "'",
              parent_style, style, m, out, depth);
}

// A use of `target`, an element of this document (null: none), its href
// `quoted` for the problems.
void Reader::local_use(const pugi::xml_node& n, const pugi::xml_node& target,
                       const std::string& quoted, const StyleState& parent_style,
                       const StyleState& style, const Affine& m, Group& out, int depth) {
    if (!target) return problem(n, quoted + " names no element; skipped");
    for (pugi::xml_node a = n; a; a = a.parent())
        if (a == target) return problem(n, quoted + " contains the use itself; skipped");
    if (std::find(instancing_.begin(), instancing_.end(), target) != instancing_.end())
        return problem(n, quoted + " makes a cycle; skipped");
    draw_use(n, *this, target, parent_style, style, m, out, depth);
}

// What the use `n` gives the element it draws, `target` of document `doc`
// (this one, or another file's, `key` its "path#id"): its translation, its
// paints for context-fill and context-stroke, and for a symbol or svg its
// size; then the target is drawn by its own document's reader.
void Reader::draw_use(const pugi::xml_node& n, Reader& doc, const pugi::xml_node& target,
                      const StyleState& parent_style, const StyleState& style, const Affine& m,
                      Group& out, int depth, const std::string& key) {
    const LengthContext ctx = context(style);
    const auto at = [&](const char* attr, double percent_of) {
        return length(n, attr, percent_of, ctx).value_or(0);
    };
    const Affine moved = m * Affine::translate({at("x", vw_), at("y", vh_)});
    const std::string_view kind = target.name();
    if (clip_mode_ && !is_shape(kind)) return; // a clip path's use must name a shape
    // A symbol's or svg's size: the use's width and height win over its own;
    // a negative one is an error, and nothing is drawn.
    UseSize size;
    if (kind == "symbol" || kind == "svg") {
        for (auto [attr, full, side] :
             {std::tuple{"width", vw_, &size.width}, std::tuple{"height", vh_, &size.height}}) {
            if (const std::optional<double> v = length(n, attr, full, ctx)) {
                *side = non_negative(n, attr, v);
                if (!*side) return;
            }
        }
    }
    // The use is the context element of what it draws (SVG 2, 13.3): a
    // gradient or pattern it is painted with lies in its user space and
    // takes its box, what it draws (fill_box; while that very walk measures
    // it, a color, so that its shapes are there to be measured).
    ContextPaints paints{ResolvedPaint{{0, 0, 0, 1}, nullptr, nullptr}, std::nullopt, m};
    if (measuring_ != n) {
        Rect b{0, 0, 0, 0};
        if (style.fill.from_url || style.stroke.from_url)
            b = fill_box(n, "use", parent_style, style, false, depth);
        if (b.is_empty()) b = Rect{0, 0, 0, 0};
        const Path box = rect_path(b.x0, b.y0, b.width(), b.height(), 0, 0);
        paints.fill = in_box(paint(n, style.fill, style, box, m), b);
        paints.stroke = in_box(paint(n, style.stroke, style, box, m), b);
    }
    if (&doc == this)
        instance(target, style, moved, std::move(paints), size, out, depth + 1);
    else
        external_instance(doc, key, target, style, moved, std::move(paints), size, out, depth + 1);
}

// Draws `target` as a use's instance: `style` is the use's, `m` its
// transform moved by its x, y.
void Reader::instance(const pugi::xml_node& target, const StyleState& style, const Affine& m,
                      ContextPaints paints, const UseSize& size, Group& out, int depth) {
    context_.push_back(std::move(paints));
    instancing_.push_back(target);
    const std::string_view kind = target.name();
    if (kind == "symbol" || kind == "svg") {
        if (conditions_hold(target)) {
            StyleState inner = style;
            ElementProps props;
            apply_declarations(target, style, inner, nullptr, context(style));
            apply_declarations(target, style, inner, &props, context(inner));
            if (!props.display_none) {
                Group g{props.opacity, {}};
                nested_viewport(target, &size, inner, props, m, g, depth);
                if (has_effects(props)) apply_effects(target, props, m, g, depth);
                add_group(out, std::move(g));
            }
        }
    } else {
        element(target, style, m, out, depth);
    }
    context_.pop_back();
    instancing_.pop_back();
}

// A new viewport (SVG 1.1, 7.9): a nested <svg>, or a <symbol> or <svg>
// instanced by a <use>. Its x, y, width and height are its own (for an
// instance, x and y are the use's translation, and the use's width and
// height, `use`, win over the element's), percentages of the
// enclosing viewport; width and height are 100% when absent; a negative
// one is an error and a zero one disables rendering. Its viewBox,
// preserveAspectRatio and, for a symbol, refX and refY (SVG 2) map its
// content. Percentages inside refer to it. Its content is clipped to it
// (or to its clip property's rectangle) unless its overflow is visible or
// auto (SVG 1.1, 14.3.3; hidden is the UA style sheet's value for these
// elements).
void Reader::nested_viewport(const pugi::xml_node& n, const UseSize* use, const StyleState& style,
                             const ElementProps& props, const Affine& m, Group& out, int depth) {
    const LengthContext ctx = context(style);
    const auto side = [&](const char* attr, const std::optional<double>& given,
                          double full) -> std::optional<double> {
        if (given) return given; // the use's, checked
        return non_negative(n, attr, length(n, attr, full, ctx).value_or(full));
    };
    const auto w = side("width", use ? use->width : std::nullopt, vw_),
               h = side("height", use ? use->height : std::nullopt, vh_);
    if (!w || !h || *w == 0 || *h == 0) return;
    Affine inner = m;
    if (!use) {
        inner = inner * Affine::translate({length(n, "x", vw_, ctx).value_or(0),
                                           length(n, "y", vh_, ctx).value_or(0)});
    }
    const std::optional<ViewBox> box = view_box(n);
    if (box && (box->w == 0 || box->h == 0)) return;
    // refX, refY (SVG 2, 5.5): the symbol's point placed at the use's x, y.
    // Absent, the viewport's corner is (the point is not 0 0: that would
    // undo the alignment, which librsvg and browsers keep).
    std::optional<Point> ref;
    if (std::string_view(n.name()) == "symbol" && (n.attribute("refX") || n.attribute("refY")))
        ref =
            Point{length(n, "refX", vw_, ctx).value_or(0), length(n, "refY", vh_, ctx).value_or(0)};
    Affine view = box ? view_map(n, *box, *w, *h) : Affine::identity();
    if (ref) view = Affine::translate(Point{0, 0} - view * *ref) * view;
    const Affine port = inner; // the viewport's own coordinates: it is [0, w] x [0, h]
    inner = inner * view;
    const double saved_w = vw_, saved_h = vh_;
    vw_ = box ? box->w : *w;
    vh_ = box ? box->h : *h;
    Group content;
    walk(n, style, inner, content, depth + 1);
    vw_ = saved_w, vh_ = saved_h;
    if (!props.overflow_visible.value_or(false) && !clip_mode_)
        content.clip = viewport_clip(content, clip_box(props, *w, *h), port);
    add_group(out, std::move(content));
}

// What a viewport of w x h clips its content to where overflow hides it:
// itself, or the clip property's rectangle (its offsets from the viewport's
// corner; auto, an edge of the viewport).
Rect Reader::clip_box(const ElementProps& props, double w, double h) {
    const auto& [top, right, bottom, left] = props.clip_rect;
    return {left.value_or(0), top.value_or(0), right.value_or(w), bottom.value_or(h)};
}

// How many elements the walk would visit under `n`, <use> instances
// counted as their targets' trees, saturating just past the limit: a nest
// of uses that would expand to 10^9 elements (billion laughs) is refused
// before any of it is built, in time linear in the document (each
// target's count is kept). Recursion is as deep as the nesting depth
// limit: deeper, the walk will stop with that limit's error.
std::size_t Reader::expanded_size(const pugi::xml_node& n, int depth) {
    const std::size_t over = options_.max_elements + 1;
    if (depth > options_.max_depth) return 1;
    if (const auto it = sizes_.find(n.internal_object()); it != sizes_.end()) return it->second;
    sizes_[n.internal_object()] = 1; // a cycle back to n: the walk skips it
    std::size_t total = 1;
    if (std::string_view(n.name()) == "use") {
        const std::string_view href = use_href(n);
        if (const pugi::xml_node t =
                href.starts_with('#') ? by_id(std::string(href.substr(1))) : pugi::xml_node())
            total += expanded_size(t, depth + 1);
    } else if (!silently_skipped(n.name())) {
        for (const pugi::xml_node& c : n.children())
            if (c.type() == pugi::node_element)
                total = std::min(over, total + expanded_size(c, depth + 1));
    }
    return sizes_[n.internal_object()] = std::min(over, total);
}

pugi::xml_node Reader::by_id(const std::string& id) {
    if (ids_.empty()) {
        struct Walker : pugi::xml_tree_walker {
            std::map<std::string, pugi::xml_node>* map;
            bool for_each(pugi::xml_node& e) override {
                if (e.type() == pugi::node_element)
                    if (const pugi::xml_attribute a = e.attribute("id"))
                        map->emplace(a.value(), e); // the first of an id wins
                return true;
            }
        } walker;
        walker.map = &ids_;
        root_.traverse(walker);
        ids_.emplace("", pugi::xml_node()); // indexed: not empty any more
    }
    const auto it = ids_.find(id);
    return it == ids_.end() ? pugi::xml_node() : it->second;
}

// The computed style of an element from its document ancestors (a marker's
// content inherits from the marker's ancestors, not from the path that uses
// it), and its own non-inherited properties. Quiet: the walk tells the
// problems of the elements it reaches.
StyleState Reader::style_of(const pugi::xml_node& n, ElementProps& props) {
    std::vector<pugi::xml_node> chain;
    for (pugi::xml_node a = n; a && a.type() == pugi::node_element; a = a.parent())
        chain.push_back(a);
    StyleState s;
    const ScopedValue quiet(quiet_, true); // the ancestors' problems were told
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
        StyleState next = s;
        props = {};
        apply_declarations(*it, s, next, nullptr, context(s));
        apply_declarations(*it, s, next, &props, context(next));
        keep_own_values(next, props, it->name());
        s = std::move(next);
    }
    return s;
}

void Reader::markers(const pugi::xml_node& n, const Shape& s, const StyleState& style, Group& out,
                     int depth) {
    const std::vector<MarkerVertex> vertices = marker_vertices(s.path);
    const auto id_of = [&](MarkerSlot slot) -> const std::string& {
        return slot == MarkerSlot::Start ? style.marker_start
               : slot == MarkerSlot::End ? style.marker_end
                                         : style.marker_mid;
    };
    // Markers on every vertex of a long path can expand past the element
    // limit: counted before any is built.
    std::size_t total = 0;
    for (const MarkerVertex& v : vertices)
        if (const std::string& id = id_of(v.slot); !id.empty())
            if (const pugi::xml_node mk = by_id(id))
                for (const pugi::xml_node& c : mk.children()) // the marker itself is skipped
                    if (c.type() == pugi::node_element)
                        total = std::min(total + expanded_size(c, depth + 1),
                                         options_.max_elements + 1);
    if (elements_ + total > options_.max_elements)
        fail(n, "more than " + std::to_string(options_.max_elements) +
                    " elements once its markers are drawn (the limit)");
    for (const MarkerVertex& v : vertices) {
        const std::string& id = id_of(v.slot);
        if (id.empty()) continue;
        const pugi::xml_node mk = by_id(id);
        if (!mk || std::strcmp(mk.name(), "marker") != 0) {
            if (warned_.insert("marker:" + id).second)
                problem(n, "url(#" + id + ") names no marker; none is drawn");
            continue;
        }
        if (std::find(instancing_.begin(), instancing_.end(), mk) != instancing_.end()) {
            problem(n, "marker #" + id + " is drawn inside itself; skipped");
            continue;
        }
        marker(mk, v, s, style.stroke_geometry.width, out, depth);
    }
}

namespace {

// orient (SVG 2, 13.7.2): auto, auto-start-reverse, or an angle (a number
// of degrees, or with deg, grad, rad or turn).
std::optional<double> fixed_orient_deg(std::string_view v) {
    std::string_view unit;
    const auto a = parse_number(v, &unit);
    if (!a) return std::nullopt;
    const std::pair<std::string_view, double> units[] = {
        {"", 1}, {"deg", 1}, {"grad", 0.9}, {"rad", 180 / std::numbers::pi}, {"turn", 360}};
    for (const auto& [name, k] : units)
        if (unit == name) return *a * k;
    return std::nullopt;
}

} // namespace

// One marker at one vertex: its viewport of markerWidth x markerHeight
// (default 3 x 3; scaled by the stroke width unless markerUnits is
// userSpaceOnUse), its viewBox and preserveAspectRatio, refX/refY (in
// view-box units) on the vertex, turned by orient; clipped to its
// viewport unless its overflow is visible or auto.
void Reader::marker(const pugi::xml_node& mk, const MarkerVertex& v, const Shape& s,
                    double stroke_width, Group& out, int depth) {
    ElementProps props;
    const StyleState style = style_of(mk, props);
    const LengthContext ctx = context(style);
    const auto size = [&](const char* attr) {
        return non_negative(mk, attr,
                            length(mk, attr, attr[6] == 'W' ? vw_ : vh_, ctx).value_or(3));
    };
    const auto w = size("markerWidth"), h = size("markerHeight");
    if (!w || !h || *w == 0 || *h == 0) return;
    double k = stroke_width;
    if (const pugi::xml_attribute u = mk.attribute("markerUnits")) {
        const std::string_view units = u.value();
        if (units == "userSpaceOnUse")
            k = 1;
        else if (units != "strokeWidth")
            problem(mk,
                    "markerUnits: '" + std::string(units) + "' is invalid; strokeWidth is used");
    }
    double angle = 0;
    if (const pugi::xml_attribute o = mk.attribute("orient")) {
        const std::string_view orient = o.value();
        if (orient == "auto")
            angle = v.angle_deg;
        else if (orient == "auto-start-reverse")
            angle = v.angle_deg + (v.slot == MarkerSlot::Start ? 180 : 0);
        else if (const auto fixed = fixed_orient_deg(orient))
            angle = *fixed;
        else
            problem(mk, "orient: '" + std::string(orient) + "' is invalid; 0 is used");
    }
    const std::optional<ViewBox> box = view_box(mk);
    if (box && (box->w == 0 || box->h == 0)) return;
    const Affine view = box ? view_map(mk, *box, *w, *h) : Affine::identity();
    const Point ref{length(mk, "refX", vw_, ctx).value_or(0),
                    length(mk, "refY", vh_, ctx).value_or(0)};
    // The marker's viewport is [0, w] x [0, h] in `port`, with refX, refY
    // (mapped by the viewBox) on the vertex.
    const Affine port = s.transform * Affine::translate(v.at - Point{0, 0}) *
                        Affine::rotate(angle * std::numbers::pi / 180) * Affine::scale(k) *
                        Affine::translate(Point{0, 0} - view * ref);
    Group g{props.opacity, {}};
    instancing_.push_back(mk);
    // The shape is the context element of its markers (SVG 2, 13.3).
    const auto context_of = [&](const auto& p) -> std::optional<ResolvedPaint> {
        if (!p) return std::nullopt;
        return in_box(ResolvedPaint{p->color, p->gradient, p->pattern}, s.path.bounds());
    };
    context_.push_back({context_of(s.fill), context_of(s.stroke), s.transform});
    walk(mk, style, port * view, g, depth + 1);
    context_.pop_back();
    instancing_.pop_back();
    if (!props.overflow_visible.value_or(false))
        g.clip = viewport_clip(g, clip_box(props, *w, *h), port);
    add_group(out, std::move(g));
}

} // namespace casteljau::svg_detail
