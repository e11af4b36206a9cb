#include "casteljau/svg/reader.h"

#include "casteljau/curve/path_data.h"
#include "casteljau/io/text_file.h"
#include "casteljau/svg/conditional.h"
#include "casteljau/svg/detail/gradients.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/transform_list.h"
#include "casteljau/svg/viewport.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <pugixml.hpp>
#include <set>

namespace casteljau {

std::string SvgDiagnostic::text() const {
    return file + ":" + std::to_string(line) + ": <" + element + ">: " + message;
}

namespace {

struct Failure {
    std::string message;
};

// Elements that are never rendered by themselves: skipped without a warning.
bool silently_skipped(std::string_view n) {
    return n == "title" || n == "desc" || n == "metadata" || n == "defs" || n == "linearGradient" ||
           n == "radialGradient" || n == "stop" || n == "script";
}

// SVG elements that change what a file shows and that this reader does not
// draw yet: skipped with a warning. Any other element (but symbol, drawn only
// through use) is unknown to SVG, and an unknown element is not rendered
// (SVG 2, 5.9 "unknown elements"): no warning.
bool unsupported(std::string_view n) {
    static const std::set<std::string_view> names = {"image",  "text",   "clipPath",
                                                     "mask",   "marker", "pattern",
                                                     "filter", "style",  "foreignObject"};
    return names.count(n) != 0;
}

bool is_shape(std::string_view n) {
    return n == "path" || n == "rect" || n == "circle" || n == "ellipse" || n == "line" ||
           n == "polyline" || n == "polygon";
}

class Reader {
  public:
    Reader(std::string_view text, std::string name, const SvgOptions& options)
        : text_(text), name_(std::move(name)), options_(options) {
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') newlines_.push_back(i);
    }

    SvgResult run() {
        SvgResult r;
        try {
            r.scene = read();
        } catch (const Failure& f) {
            r.error = f.message;
        }
        r.warnings = std::move(warnings_);
        return r;
    }

  private:
    int line_of(std::ptrdiff_t offset) const {
        if (offset < 0) return 0;
        return int(std::lower_bound(newlines_.begin(), newlines_.end(), std::size_t(offset)) -
                   newlines_.begin()) +
               1;
    }
    SvgDiagnostic located(const pugi::xml_node& n, const std::string& what) const {
        return {name_, line_of(n.offset_debug()), n.name(), what};
    }
    [[noreturn]] void fail(const pugi::xml_node& n, const std::string& what) const {
        throw Failure{located(n, what).text()};
    }
    [[noreturn]] void fail_at(std::ptrdiff_t offset, const std::string& what) const {
        throw Failure{name_ + ":" + std::to_string(line_of(offset)) + ": " + what};
    }
    void warn(const pugi::xml_node& n, const std::string& what) {
        warnings_.push_back(located(n, what));
    }
    // A problem the spec says how to recover from: a warning, and the caller
    // recovers; with `strict`, the error that ends the read.
    void problem(const pugi::xml_node& n, const std::string& what) {
        if (options_.strict) fail(n, what);
        warn(n, what);
    }

    LengthContext context(const StyleState& s) const {
        return {s.font_size, root_font_size_, vw_, vh_};
    }

    // A length attribute; nullopt when absent, auto, or invalid (a problem).
    std::optional<double> length(const pugi::xml_node& n, const char* attr, double percent_of,
                                 const LengthContext& ctx) {
        const pugi::xml_attribute a = n.attribute(attr);
        if (!a || std::strcmp(a.value(), "auto") == 0) return std::nullopt;
        const auto v = parse_length(a.value(), percent_of, ctx);
        if (!v)
            problem(n, std::string("attribute ") + attr + ": '" + a.value() +
                           "' is not a length; ignored");
        return v;
    }

    Scene read() {
        pugi::xml_document doc;
        const pugi::xml_parse_result res =
            doc.load_buffer(text_.data(), text_.size(), pugi::parse_default | pugi::parse_doctype);
        if (!res) fail_at(res.offset, std::string("malformed XML: ") + res.description());
        // pugixml never expands entities nor fetches a DTD; a document that
        // declares entities is refused rather than read without them
        // (entity bombs, external entities).
        for (const pugi::xml_node& n : doc.children())
            if (n.type() == pugi::node_doctype && std::strstr(n.value(), "<!ENTITY"))
                fail_at(n.offset_debug(), "<!DOCTYPE>: entity declarations are not supported");
        const pugi::xml_node root = root_ = doc.document_element();
        if (std::strcmp(root.name(), "svg") != 0)
            fail_at(root.offset_debug(),
                    std::string("the root element is <") + root.name() + ">, not <svg>");
        Scene scene;
        StyleState style;
        // The root's font-size first: it is what rem means, and its own
        // lengths (width="20em") and the viewport depend on it.
        apply_declarations(root, style, style, nullptr, {});
        root_font_size_ = style.font_size;
        const std::optional<Affine> view = viewport(root, scene, context(style));
        ElementProps props;
        apply_declarations(root, style, style, &props, context(style));
        if (!view) return scene; // a zero-sized viewBox: nothing is drawn
        if (const std::size_t n = expanded_size(root, 0); n > options_.max_elements)
            fail(root, "more than " + std::to_string(options_.max_elements) +
                           " elements once <use> is expanded (the limit)");
        walk(root, style, *view, scene.root, 1);
        if (props.opacity < 1)
            scene.root = Group{1, {Node{Group{props.opacity, std::move(scene.root.children)}}}};
        return scene;
    }

    // The root's width and height: an absolute length, or (absent, auto or
    // a percentage) that fraction of the viewBox's size, or of 100 x 100
    // without a viewBox (resvg's default; a standalone file has no
    // containing block). Then the viewBox mapping (SVG 1.1, 7.7 and 7.8).
    // Nothing to draw (nullopt) when the viewBox is zero-sized.
    std::optional<Affine> viewport(const pugi::xml_node& root, Scene& scene,
                                   const LengthContext& ctx) {
        std::optional<ViewBox> box;
        if (const pugi::xml_attribute a = root.attribute("viewBox")) {
            ViewBoxResult vb = parse_view_box(a.value());
            if (!vb.error.empty()) problem(root, vb.error);
            box = vb.box;
        }
        const auto side = [&](const char* attr, double from_box) {
            const double full = box ? from_box : 100;
            std::string v = root.attribute(attr).value();
            if (v.empty() || v == "auto") return full;
            if (const auto len = parse_length(v, full, ctx)) return *len;
            problem(root,
                    std::string("attribute ") + attr + ": '" + v + "' is not a length; ignored");
            return full;
        };
        scene.width = side("width", box ? box->w : 0);
        scene.height = side("height", box ? box->h : 0);
        for (const double d : {scene.width, scene.height}) {
            char size[32]; // "%g": 1e+308, not its 309 digits
            std::snprintf(size, sizeof size, "%g", d);
            if (!(d > 0))
                fail(root, std::string("the document size ") + size + " must be positive");
            if (d > options_.max_size)
                fail(root, std::string("the document size ") + size + " px exceeds the limit of " +
                               std::to_string(int(options_.max_size)) + " px");
        }
        vw_ = box ? box->w : scene.width;
        vh_ = box ? box->h : scene.height;
        gradients_.emplace(root, vw_, vh_);
        if (!box) return Affine::identity();
        if (box->w == 0 || box->h == 0) {
            warn(root, "viewBox: a zero width or height disables rendering");
            return std::nullopt;
        }
        AspectRatio ar;
        if (const pugi::xml_attribute a = root.attribute("preserveAspectRatio")) {
            if (const auto parsed = parse_aspect_ratio(a.value()))
                ar = *parsed;
            else
                problem(root, std::string("preserveAspectRatio: '") + a.value() +
                                  "' is invalid; xMidYMid meet is used");
        }
        return view_box_transform(*box, ar, 0, 0, scene.width, scene.height);
    }

    void check_length_limit(const pugi::xml_node& n, const pugi::xml_attribute& a) const {
        if (const std::size_t len = std::strlen(a.value()); len > options_.max_attribute_bytes)
            fail(n, std::string("attribute ") + a.name() + " is " + std::to_string(len) +
                        " bytes, over the limit of " +
                        std::to_string(options_.max_attribute_bytes) + " bytes");
    }

    // The element's presentation attributes, then its style attribute's
    // declarations (which win, 6.4). Without `props`, only font-size: the
    // first of two passes, since every other length may be in em. An
    // invalid value is a problem, and the property keeps what it had.
    void apply_declarations(const pugi::xml_node& n, const StyleState& parent, StyleState& style,
                            ElementProps* props, const LengthContext& ctx) {
        ElementProps unused;
        const auto apply = [&](std::string_view name, std::string_view value, bool in_style) {
            if ((name == "font-size") == (props != nullptr)) return;
            const std::string e =
                apply_property(name, value, parent, style, props ? *props : unused, ctx);
            if (!e.empty()) problem(n, (in_style ? "style: " : "") + e + "; ignored");
        };
        for (const pugi::xml_attribute& a : n.attributes()) {
            if (!props) check_length_limit(n, a);
            if (std::strcmp(a.name(), "style") != 0) apply(a.name(), a.value(), false);
        }
        if (const pugi::xml_attribute a = n.attribute("style")) {
            std::vector<std::string_view> malformed;
            for (const Declaration& d : split_style_attribute(a.value(), malformed))
                apply(d.name, d.value, true);
            if (props)
                for (const std::string_view m : malformed)
                    problem(n, "style: '" + std::string(m) + "' is not a declaration; ignored");
        }
    }

    void walk(const pugi::xml_node& parent, const StyleState& parent_style, const Affine& ctm,
              Group& out, int depth) {
        for (const pugi::xml_node& n : parent.children())
            if (n.type() == pugi::node_element) element(n, parent_style, ctm, out, depth);
    }

    // Whether the element's conditional attributes let it be rendered.
    bool conditions_hold(const pugi::xml_node& n) const {
        Conditions c;
        if (const pugi::xml_attribute a = n.attribute("systemLanguage"))
            c.system_language = a.value();
        if (const pugi::xml_attribute a = n.attribute("requiredExtensions"))
            c.required_extensions = a.value();
        return casteljau::conditions_hold(c, options_.languages);
    }

    // Adds a group's children to `out`, or the group itself when it needs a
    // layer (opacity below 1).
    static void add_group(Group& out, Group g) {
        if (g.opacity >= 1.0f)
            std::move(g.children.begin(), g.children.end(), std::back_inserter(out.children));
        else if (!g.children.empty())
            out.children.push_back(Node{std::move(g)});
    }

    // One element and what it holds, drawn into `out`. Every element visited
    // counts against the element limit, instances of <use> included, so a
    // nest of uses that would expand past it stops there (billion laughs).
    void element(const pugi::xml_node& n, const StyleState& parent_style, const Affine& ctm,
                 Group& out, int depth) {
        if (++elements_ > options_.max_elements)
            fail(n, "more than " + std::to_string(options_.max_elements) +
                        " elements, <use> instances included (the limit)");
        if (depth > options_.max_depth)
            fail(n, "elements nested deeper than " + std::to_string(options_.max_depth) +
                        ", <use> instances included (the limit)");
        const std::string_view name = n.name();
        if (name.find(':') != name.npos || silently_skipped(name)) return; // foreign namespaces
        const bool group = name == "g" || name == "a";
        const bool structure = group || name == "switch" || name == "svg" || name == "use";
        if (!structure && !is_shape(name)) {
            if (unsupported(name)) warn(n, "not supported yet; skipped");
            return; // symbol too: drawn only through <use>
        }
        if (!conditions_hold(n)) return;
        StyleState style = parent_style;
        ElementProps props;
        apply_declarations(n, parent_style, style, nullptr, context(parent_style));
        apply_declarations(n, parent_style, style, &props, context(style));
        if (props.display_none) return;
        Affine m = ctm;
        if (const pugi::xml_attribute t = n.attribute("transform")) {
            const TransformResult tr = parse_transform_list(t.value());
            const Vec2 o = props.transform_origin;
            if (tr.error.empty())
                m = ctm * Affine::translate(o) * tr.transform * Affine::translate(-o);
            else
                problem(n, "transform: " + tr.error + "; ignored");
        }
        Group g{props.opacity, {}};
        if (group) {
            walk(n, style, m, g, depth + 1);
        } else if (name == "switch") {
            for (const pugi::xml_node& c : n.children())
                if (c.type() == pugi::node_element && conditions_hold(c)) {
                    element(c, style, m, g, depth + 1);
                    break;
                }
        } else if (name == "svg") {
            nested_viewport(n, n, style, m, g, depth);
        } else if (name == "use") {
            use(n, style, m, g, depth);
        } else if (std::optional<Shape> sh = shape(n, name, style, m, props)) {
            out.children.push_back(Node{std::move(*sh)});
            return;
        }
        add_group(out, std::move(g));
    }

    // <use> (SVG 1.1, 5.6; SVG 2, 5.6): the referenced element drawn as if it
    // were the use's child, inheriting the use's style, moved by x, y; a
    // <symbol> or <svg> becomes a viewport of the use's width and height. A
    // reference to itself or to an element being instanced (a cycle) is a
    // problem, and nothing is drawn.
    void use(const pugi::xml_node& n, const StyleState& style, const Affine& m, Group& out,
             int depth) {
        const char* href =
            n.attribute("href") ? n.attribute("href").value() : n.attribute("xlink:href").value();
        const pugi::xml_node target = href[0] == '#' ? by_id(href + 1) : pugi::xml_node();
        if (!target) {
            if (href[0]) problem(n, std::string("href '") + href + "' names no element; skipped");
            return;
        }
        for (pugi::xml_node a = n; a; a = a.parent())
            if (a == target)
                return problem(n,
                               std::string("href '") + href + "' contains the use itself; skipped");
        if (std::find(instancing_.begin(), instancing_.end(), target) != instancing_.end())
            return problem(n, std::string("href '") + href + "' makes a cycle; skipped");
        const LengthContext ctx = context(style);
        const auto at = [&](const char* attr, double percent_of) {
            return length(n, attr, percent_of, ctx).value_or(0);
        };
        const Affine moved = m * Affine::translate({at("x", vw_), at("y", vh_)});
        instancing_.push_back(target);
        const std::string_view kind = target.name();
        if (kind == "symbol" || kind == "svg") {
            if (conditions_hold(target)) {
                StyleState inner = style;
                ElementProps props;
                apply_declarations(target, style, inner, nullptr, ctx);
                apply_declarations(target, style, inner, &props, context(inner));
                if (!props.display_none) {
                    Group g{props.opacity, {}};
                    nested_viewport(target, n, inner, moved, g, depth + 1);
                    add_group(out, std::move(g));
                }
            }
        } else {
            element(target, style, moved, out, depth + 1);
        }
        instancing_.pop_back();
    }

    // A new viewport (SVG 1.1, 7.9): a nested <svg>, or a <symbol> or <svg>
    // instanced by a <use>. Its x, y, width and height come from `sizes` (the
    // element itself, or the use: x and y are the use's translation then, and
    // its width and height win over the element's), percentages of the
    // enclosing viewport; width and height are 100% when absent; a negative
    // one is an error and a zero one disables rendering. Its viewBox,
    // preserveAspectRatio and, for a symbol, refX and refY (SVG 2) map its
    // content. Percentages inside refer to it. Not clipped to it yet: the
    // overflow property needs clip paths.
    void nested_viewport(const pugi::xml_node& n, const pugi::xml_node& sizes,
                         const StyleState& style, const Affine& m, Group& out, int depth) {
        const LengthContext ctx = context(style);
        const auto side = [&](const char* attr, double full) -> std::optional<double> {
            std::optional<double> v = length(sizes, attr, full, ctx);
            if (!v && sizes != n) v = length(n, attr, full, ctx);
            return non_negative(sizes, attr, v ? v : full);
        };
        const auto w = side("width", vw_), h = side("height", vh_);
        if (!w || !h || *w == 0 || *h == 0) return;
        Affine inner = m;
        if (sizes == n) {
            inner = inner * Affine::translate({length(n, "x", vw_, ctx).value_or(0),
                                               length(n, "y", vh_, ctx).value_or(0)});
        }
        std::optional<ViewBox> box;
        if (const pugi::xml_attribute a = n.attribute("viewBox")) {
            ViewBoxResult vb = parse_view_box(a.value());
            if (!vb.error.empty()) problem(n, vb.error);
            box = vb.box;
            if (box && (box->w == 0 || box->h == 0)) return;
        }
        // refX, refY (SVG 2, 5.5): the symbol's point placed at the use's x, y.
        // Absent, the viewport's corner is (the point is not 0 0: that would
        // undo the alignment, which librsvg and browsers keep).
        std::optional<Point> ref;
        if (std::string_view(n.name()) == "symbol" && (n.attribute("refX") || n.attribute("refY")))
            ref = Point{length(n, "refX", vw_, ctx).value_or(0),
                        length(n, "refY", vh_, ctx).value_or(0)};
        Affine view = Affine::identity();
        if (box) {
            AspectRatio ar;
            if (const pugi::xml_attribute a = n.attribute("preserveAspectRatio")) {
                if (const auto parsed = parse_aspect_ratio(a.value()))
                    ar = *parsed;
                else
                    problem(n, std::string("preserveAspectRatio: '") + a.value() +
                                   "' is invalid; xMidYMid meet is used");
            }
            view = view_box_transform(*box, ar, 0, 0, *w, *h);
        }
        if (ref) view = Affine::translate(Point{0, 0} - view * *ref) * view;
        inner = inner * view;
        const double saved_w = vw_, saved_h = vh_;
        vw_ = box ? box->w : *w;
        vh_ = box ? box->h : *h;
        walk(n, style, inner, out, depth + 1);
        vw_ = saved_w, vh_ = saved_h;
    }

    // How many elements the walk would visit under `n`, <use> instances
    // counted as their targets' trees, saturating just past the limit: a nest
    // of uses that would expand to 10^9 elements (billion laughs) is refused
    // before any of it is built, in time linear in the document (each
    // target's count is kept). Recursion is as deep as the nesting depth
    // limit: deeper, the walk will stop with that limit's error.
    std::size_t expanded_size(const pugi::xml_node& n, int depth) {
        const std::size_t over = options_.max_elements + 1;
        if (depth > options_.max_depth) return 1;
        if (const auto it = sizes_.find(n.internal_object()); it != sizes_.end()) return it->second;
        sizes_[n.internal_object()] = 1; // a cycle back to n: the walk skips it
        std::size_t total = 1;
        if (std::string_view(n.name()) == "use") {
            const char* href = n.attribute("href") ? n.attribute("href").value()
                                                   : n.attribute("xlink:href").value();
            if (const pugi::xml_node t = href[0] == '#' ? by_id(href + 1) : pugi::xml_node())
                total += expanded_size(t, depth + 1);
        } else if (!silently_skipped(n.name())) {
            for (const pugi::xml_node& c : n.children())
                if (c.type() == pugi::node_element)
                    total = std::min(over, total + expanded_size(c, depth + 1));
        }
        return sizes_[n.internal_object()] = std::min(over, total);
    }

    pugi::xml_node by_id(const std::string& id) {
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

    std::optional<Shape> shape(const pugi::xml_node& n, std::string_view name,
                               const StyleState& style, const Affine& m,
                               const ElementProps& props) {
        Path path = geometry(n, name, context(style));
        if (!style.visible || path.empty()) return std::nullopt;
        Shape s;
        s.path = std::move(path);
        s.transform = m;
        s.opacity = props.opacity;
        s.source_line = line_of(n.offset_debug());
        if (const auto p = paint(n, style.fill, style))
            s.fill = Fill{p->color, p->gradient, style.fill_opacity, style.fill_rule};
        if (const auto p = paint(n, style.stroke, style); p && style.stroke_geometry.width > 0)
            s.stroke = Stroke{p->color, p->gradient, style.stroke_opacity, style.stroke_geometry};
        return s;
    }

    // A paint: a color, or a gradient by url(#id) with its fallback color
    // when the reference names no usable gradient (SVG 1.1, 11.2).
    struct ResolvedPaint {
        Rgba color;
        std::shared_ptr<const Gradient> gradient;
    };
    std::optional<ResolvedPaint> paint(const pugi::xml_node& n, const PaintSpec& spec,
                                       const StyleState& style) {
        if (spec.from_url) {
            const svg_detail::GradientRef g = gradients_->resolve(spec.url);
            for (const svg_detail::GradientProblem& p : gradients_->take_problems())
                problem(p.where, p.message);
            if (!g.warning.empty() && warned_.insert(g.warning).second)
                warn(g.where ? g.where : n, g.warning);
            if (g.gradient) return ResolvedPaint{{}, g.gradient};
        }
        if (const auto c = resolve_paint(spec, style)) return ResolvedPaint{*c, nullptr};
        return std::nullopt;
    }

    // A required length that must not be negative: nullopt, and the element
    // is not drawn, when it is (SVG 1.1, 9: "a negative value is an error").
    std::optional<double> non_negative(const pugi::xml_node& n, const char* attr,
                                       std::optional<double> v) {
        if (v && *v < 0) {
            problem(n, std::string("attribute ") + attr +
                           ": a negative value is an error; the element is not drawn");
            return std::nullopt;
        }
        return v ? v : 0.0;
    }

    Path geometry(const pugi::xml_node& n, std::string_view name, const LengthContext& ctx) {
        if (name == "path") {
            PathDataResult r = parse_path_data(n.attribute("d").value());
            if (r.error)
                problem(n, "attribute d: path data: at offset " + std::to_string(r.error->offset) +
                               ": " + r.error->message + " (drawn up to there)");
            return std::move(r.path);
        }
        if (name == "polyline" || name == "polygon") {
            PointList pts = parse_point_list(n.attribute("points").value());
            if (!pts.error.empty()) problem(n, "attribute " + pts.error + " (drawn up to there)");
            if (pts.points.size() < 2) return {};
            return poly_path(pts.points, name == "polygon");
        }
        // Percentages of the viewport: x against its width, y against its
        // height, radii against its normalised diagonal (SVG 1.1, 7.10).
        const double w = vw_, h = vh_, d = ctx.diagonal();
        const auto len = [&](const char* attr, double percent_of) {
            return length(n, attr, percent_of, ctx);
        };
        const auto at = [&](const char* attr, double percent_of) {
            return len(attr, percent_of).value_or(0);
        };
        if (name == "line")
            return line_path({at("x1", w), at("y1", h)}, {at("x2", w), at("y2", h)});
        if (name == "rect") {
            const auto rw = non_negative(n, "width", len("width", w));
            const auto rh = non_negative(n, "height", len("height", h));
            // rx, ry: absent or auto (-1) take the other's value (9.2).
            const auto rx = len("rx", w), ry = len("ry", h);
            if (!rw || !rh || !non_negative(n, "rx", rx) || !non_negative(n, "ry", ry)) return {};
            if (*rw == 0 || *rh == 0) return {};
            return rect_path(at("x", w), at("y", h), *rw, *rh, rx.value_or(-1), ry.value_or(-1));
        }
        if (name == "circle") {
            const auto r = non_negative(n, "r", len("r", d));
            if (!r || *r == 0) return {};
            return ellipse_path(at("cx", w), at("cy", h), *r, *r);
        }
        // ellipse: an absent or auto radius takes the other's (SVG 2, 10.4).
        auto rx = len("rx", w), ry = len("ry", h);
        if (!rx) rx = ry;
        if (!ry) ry = rx;
        if (!non_negative(n, "rx", rx) || !non_negative(n, "ry", ry) || !rx || *rx == 0 || *ry == 0)
            return {};
        return ellipse_path(at("cx", w), at("cy", h), *rx, *ry);
    }

    std::string_view text_;
    std::string name_;
    SvgOptions options_;
    std::vector<std::size_t> newlines_;
    std::vector<SvgDiagnostic> warnings_;
    std::set<std::string> warned_;
    std::size_t elements_ = 0;
    double root_font_size_ = 16;
    double vw_ = 0, vh_ = 0; // viewport size in user units, for percentages
    std::optional<svg_detail::GradientIndex> gradients_;
    pugi::xml_node root_;
    std::map<std::string, pugi::xml_node> ids_; // built at the first <use>
    std::vector<pugi::xml_node> instancing_;    // the <use> targets being drawn
    std::map<const void*, std::size_t> sizes_;  // expanded_size's, per element
};

} // namespace

SvgResult parse_svg(std::string_view text, const std::string& name, const SvgOptions& options) {
    if (text.size() > options.max_file_bytes) {
        SvgResult r;
        r.error = name + ": " + std::to_string(text.size()) + " bytes exceed the limit of " +
                  std::to_string(options.max_file_bytes);
        return r;
    }
    return Reader(text, name, options).run();
}

SvgResult read_svg_file(const std::string& path, const SvgOptions& options) {
    const TextFile file = read_text_file(path, options.max_file_bytes);
    if (!file.error.empty()) {
        SvgResult r;
        r.error = file.error;
        r.io_error = file.io_error;
        return r;
    }
    return parse_svg(file.text, path, options);
}

} // namespace casteljau
