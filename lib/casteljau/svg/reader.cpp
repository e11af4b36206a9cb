#include "casteljau/svg/reader.h"

#include "casteljau/curve/path_data.h"
#include "casteljau/io/text_file.h"
#include "casteljau/svg/detail/gradients.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/transform_list.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <pugixml.hpp>
#include <set>
#include <sstream>

namespace casteljau {

namespace {

struct Failure {
    std::string message;
};

// Elements that are never rendered by themselves: skipped without a warning.
bool silently_skipped(std::string_view n) {
    return n == "title" || n == "desc" || n == "metadata" || n == "defs" || n == "linearGradient" ||
           n == "radialGradient";
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
    std::string where(const pugi::xml_node& n) const {
        return name_ + ":" + std::to_string(line_of(n.offset_debug())) + ": <" + n.name() + ">";
    }
    [[noreturn]] void fail(const pugi::xml_node& n, const std::string& what) const {
        throw Failure{where(n) + ": " + what};
    }
    void warn(const pugi::xml_node& n, const std::string& what) {
        warnings_.push_back(where(n) + ": " + what);
    }
    void warn_once(const pugi::xml_node& n, const std::string& what) {
        if (warned_.insert(what).second) warn(n, what);
    }

    double length(const pugi::xml_node& n, const char* attr, double fallback, double percent_of,
                  bool non_negative = false) const {
        const pugi::xml_attribute a = n.attribute(attr);
        if (!a) return fallback;
        const auto v = parse_length(a.value(), percent_of);
        if (!v)
            fail(n,
                 std::string("attribute ") + attr + ": '" + a.value() + "' is not a finite length");
        if (non_negative && *v < 0)
            fail(n, std::string("attribute ") + attr + ": " + a.value() + " is negative");
        return *v;
    }

    Scene read() {
        pugi::xml_document doc;
        const pugi::xml_parse_result res =
            doc.load_buffer(text_.data(), text_.size(), pugi::parse_default | pugi::parse_doctype);
        if (!res)
            throw Failure{name_ + ":" + std::to_string(line_of(res.offset)) +
                          ": malformed XML: " + res.description()};
        // pugixml never expands entities nor fetches a DTD; a document that
        // declares entities is refused rather than read without them
        // (entity bombs, external entities).
        for (const pugi::xml_node& n : doc.children())
            if (n.type() == pugi::node_doctype && std::strstr(n.value(), "<!ENTITY"))
                throw Failure{name_ + ":" + std::to_string(line_of(n.offset_debug())) +
                              ": <!DOCTYPE>: entity declarations are not supported"};
        const pugi::xml_node root = doc.document_element();
        if (std::strcmp(root.name(), "svg") != 0)
            throw Failure{name_ + ":" + std::to_string(line_of(root.offset_debug())) +
                          ": the root element is <" + root.name() + ">, not <svg>"};
        Scene scene;
        const Affine view = viewport(root, scene);
        StyleState style;
        ElementProps props;
        apply_attributes(root, style, style, props);
        walk(root, style, view, scene.root, 1);
        scene.root.opacity = 1;
        if (props.opacity < 1)
            scene.root = Group{1, {Node{Group{props.opacity, std::move(scene.root.children)}}}};
        return scene;
    }

    // Root width/height and the viewBox mapping (SVG 1.1, 7.7 and 7.8).
    Affine viewport(const pugi::xml_node& root, Scene& scene) {
        double vb[4] = {0, 0, 0, 0};
        const pugi::xml_attribute box = root.attribute("viewBox");
        if (box) {
            std::string tok;
            int n = 0;
            std::string s = box.value();
            std::replace(s.begin(), s.end(), ',', ' ');
            std::istringstream words(s);
            while (words >> tok) {
                const auto v = parse_length(tok);
                if (!v || n == 4)
                    fail(root, "viewBox: '" + std::string(box.value()) + "' is not four numbers");
                vb[n++] = *v;
            }
            if (n != 4)
                fail(root, "viewBox: '" + std::string(box.value()) + "' is not four numbers");
            if (!(vb[2] > 0 && vb[3] > 0)) fail(root, "viewBox: width and height must be positive");
        }
        const auto side = [&](const char* attr, double from_box) {
            const pugi::xml_attribute a = root.attribute(attr);
            const std::string v = a ? a.value() : "";
            if (!a || (!v.empty() && v.back() == '%')) {
                if (!box)
                    fail(root, std::string("no ") + attr + " and no viewBox: the size is unknown");
                return from_box;
            }
            const auto len = parse_length(v);
            if (!len)
                fail(root,
                     std::string("attribute ") + attr + ": '" + v + "' is not a finite length");
            return *len;
        };
        scene.width = side("width", vb[2]);
        scene.height = side("height", vb[3]);
        for (const double d : {scene.width, scene.height}) {
            char size[32]; // "%g": 1e+308, not its 309 digits
            std::snprintf(size, sizeof size, "%g", d);
            if (!(d > 0))
                fail(root, std::string("the document size ") + size + " must be positive");
            if (d > options_.max_size)
                fail(root, std::string("the document size ") + size + " px exceeds the limit of " +
                               std::to_string(int(options_.max_size)) + " px");
        }
        vw_ = box ? vb[2] : scene.width;
        vh_ = box ? vb[3] : scene.height;
        gradients_.emplace(root, vw_, vh_);
        if (!box) return Affine::identity();
        return view_box_transform(root, scene, vb);
    }

    Affine view_box_transform(const pugi::xml_node& root, const Scene& scene, const double vb[4]) {
        std::string align = "xMidYMid";
        bool slice = false;
        if (const pugi::xml_attribute a = root.attribute("preserveAspectRatio")) {
            std::istringstream words(a.value());
            std::string w;
            words >> w;
            if (w == "defer") words >> w;
            align = w;
            if (words >> w) {
                if (w == "slice")
                    slice = true;
                else if (w != "meet")
                    fail(root, "preserveAspectRatio: '" + w + "' is not meet or slice");
            }
            static const std::set<std::string> valid = {
                "none",     "xMinYMin", "xMidYMin", "xMaxYMin", "xMinYMid",
                "xMidYMid", "xMaxYMid", "xMinYMax", "xMidYMax", "xMaxYMax"};
            if (!valid.count(align))
                fail(root, "preserveAspectRatio: '" + align + "' is not an alignment");
        }
        double sx = scene.width / vb[2], sy = scene.height / vb[3];
        if (align == "none") return Affine::scale(sx, sy) * Affine::translate({-vb[0], -vb[1]});
        const double s = slice ? std::max(sx, sy) : std::min(sx, sy);
        const auto offset = [&](char where, double avail, double used) {
            return where == 'n' ? 0.0 : (where == 'd' ? (avail - used) / 2 : avail - used);
        };
        // align is x{Min,Mid,Max}Y{Min,Mid,Max}: the letters at 3 and 7 (n, d, x) tell which.
        const double tx = offset(align[3], scene.width, vb[2] * s),
                     ty = offset(align[7], scene.height, vb[3] * s);
        return Affine::translate({tx, ty}) * Affine::scale(s) * Affine::translate({-vb[0], -vb[1]});
    }

    // Bad path data or point list: an error, or (partial_path_data) a warning
    // and the shape up to the error.
    void bad_data(const pugi::xml_node& n, const std::string& what) {
        if (!options_.partial_path_data) fail(n, what);
        warn(n, what + " (drawn up to there)");
    }

    void apply_attributes(const pugi::xml_node& n, const StyleState& parent, StyleState& style,
                          ElementProps& props) {
        for (const pugi::xml_attribute& a : n.attributes()) {
            if (const std::size_t len = std::strlen(a.value()); len > options_.max_attribute_bytes)
                fail(n, std::string("attribute ") + a.name() + " is " + std::to_string(len) +
                            " bytes, over the limit of " +
                            std::to_string(options_.max_attribute_bytes) + " bytes");
            if (std::strcmp(a.name(), "style") == 0) continue;
            const std::string e = apply_property(a.name(), a.value(), parent, style, props);
            if (!e.empty()) fail(n, e);
        }
        if (const pugi::xml_attribute a = n.attribute("style")) {
            const std::string e = apply_style_attribute(a.value(), parent, style, props);
            if (!e.empty()) fail(n, e);
        }
    }

    void walk(const pugi::xml_node& parent, const StyleState& parent_style, const Affine& ctm,
              Group& out, int depth) {
        for (const pugi::xml_node& n : parent.children()) {
            if (n.type() != pugi::node_element) continue;
            if (++elements_ > options_.max_elements)
                fail(n, "more than " + std::to_string(options_.max_elements) +
                            " elements (the limit)");
            if (depth > options_.max_depth)
                fail(n, "elements nested deeper than " + std::to_string(options_.max_depth) +
                            " (the limit)");
            const std::string_view name = n.name();
            if (name.find(':') != name.npos || silently_skipped(name))
                continue; // foreign namespaces
            const bool group = name == "g" || name == "a";
            if (!group && !is_shape(name)) {
                warn(n, "unsupported element skipped");
                continue;
            }
            StyleState style = parent_style;
            ElementProps props;
            apply_attributes(n, parent_style, style, props);
            if (props.display_none) continue;
            Affine m = ctm;
            if (const pugi::xml_attribute t = n.attribute("transform")) {
                const TransformResult tr = parse_transform_list(t.value());
                if (!tr.error.empty()) fail(n, "transform: " + tr.error);
                m = ctm * tr.transform;
            }
            if (group) {
                Group g{props.opacity, {}};
                walk(n, style, m, g, depth + 1);
                if (g.opacity >= 1.0f)
                    std::move(g.children.begin(), g.children.end(),
                              std::back_inserter(out.children));
                else
                    out.children.push_back(Node{std::move(g)});
                continue;
            }
            if (std::optional<Shape> s = shape(n, name, style, m, props))
                out.children.push_back(Node{std::move(*s)});
        }
    }

    static bool is_shape(std::string_view n) {
        return n == "path" || n == "rect" || n == "circle" || n == "ellipse" || n == "line" ||
               n == "polyline" || n == "polygon";
    }

    std::optional<Shape> shape(const pugi::xml_node& n, std::string_view name,
                               const StyleState& style, const Affine& m,
                               const ElementProps& props) {
        Path path = geometry(n, name);
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
            if (!g.error.empty()) fail(g.where, g.error);
            if (!g.warning.empty()) warn_once(g.where ? g.where : n, g.warning);
            if (g.gradient) return ResolvedPaint{{}, g.gradient};
        }
        if (const auto c = resolve_paint(spec, style)) return ResolvedPaint{*c, nullptr};
        return std::nullopt;
    }

    Path geometry(const pugi::xml_node& n, std::string_view name) {
        if (name == "path") {
            PathDataResult r = parse_path_data(n.attribute("d").value());
            if (r.error)
                bad_data(n, "attribute d: path data: at offset " + std::to_string(r.error->offset) +
                                ": " + r.error->message);
            return std::move(r.path);
        }
        // Percentages of the viewport: x against its width, y against its
        // height, radii against its normalised diagonal (SVG 1.1, 7.10).
        const double w = vw_, h = vh_, d = std::sqrt((w * w + h * h) / 2);
        if (name == "rect") {
            const double rw = length(n, "width", 0, w, true), rh = length(n, "height", 0, h, true);
            if (rw == 0 || rh == 0) return {};
            return rect_path(length(n, "x", 0, w), length(n, "y", 0, h), rw, rh,
                             length(n, "rx", -1, w, true), length(n, "ry", -1, h, true));
        }
        if (name == "circle") {
            const double r = length(n, "r", 0, d, true);
            return r == 0 ? Path{}
                          : ellipse_path(length(n, "cx", 0, w), length(n, "cy", 0, h), r, r);
        }
        if (name == "ellipse") {
            const double rx = length(n, "rx", 0, w, true), ry = length(n, "ry", 0, h, true);
            return rx == 0 || ry == 0
                       ? Path{}
                       : ellipse_path(length(n, "cx", 0, w), length(n, "cy", 0, h), rx, ry);
        }
        if (name == "line")
            return line_path({length(n, "x1", 0, w), length(n, "y1", 0, h)},
                             {length(n, "x2", 0, w), length(n, "y2", 0, h)});
        PointList pts = parse_point_list(n.attribute("points").value());
        if (!pts.error.empty()) bad_data(n, "attribute points: " + pts.error);
        return poly_path(pts.points, name == "polygon");
    }

    std::string_view text_;
    std::string name_;
    SvgOptions options_;
    std::vector<std::size_t> newlines_;
    std::vector<std::string> warnings_;
    std::set<std::string> warned_;
    std::size_t elements_ = 0;
    double vw_ = 0, vh_ = 0; // viewport size in user units, for percentages
    std::optional<svg_detail::GradientIndex> gradients_;
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
