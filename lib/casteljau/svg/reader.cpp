#include "casteljau/svg/reader.h"

#include "casteljau/curve/path_data.h"
#include "casteljau/io/gunzip.h"
#include "casteljau/io/text_file.h"
#include "casteljau/render/output_size.h"
#include "casteljau/svg/conditional.h"
#include "casteljau/svg/custom_properties.h"
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/css_pugi.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/detail/xml_namespaces.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/svg/transform_list.h"
#include "casteljau/svg/viewport.h"
#include "casteljau/svg/xml_encoding.h"
#include "casteljau/svg/xml_entities.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>

namespace casteljau {

std::string SvgDiagnostic::text() const {
    return file + ":" + std::to_string(line) + ": <" + element + ">: " + message;
}

namespace svg_detail {

namespace {

// SVG 2's geometry properties (x, y, width, height, cx, cy, r, rx, ry; 9.2 to
// 9.4, 12.3): CSS properties of the elements below, so a style sheet or a
// style attribute may set them. Browsers (and resvg) take them there only:
// an svg's or a use's width in CSS is ignored.
bool geometry_property(std::string_view element, std::string_view attr) {
    if (element == "rect")
        return attr == "x" || attr == "y" || attr == "width" || attr == "height" || attr == "rx" ||
               attr == "ry";
    if (element == "image")
        return attr == "x" || attr == "y" || attr == "width" || attr == "height";
    if (element == "circle") return attr == "cx" || attr == "cy" || attr == "r";
    if (element == "ellipse") return attr == "cx" || attr == "cy" || attr == "rx" || attr == "ry";
    return false;
}

// Whether a style attribute's text has a declaration of `property` (its name
// before a colon, ASCII case aside). A false yes, in a comment or a string,
// only costs a cascade.
bool declares(std::string_view style, std::string_view property) {
    while (!style.empty()) {
        const std::size_t semicolon = std::min(style.find(';'), style.size());
        const std::string_view declaration = style.substr(0, semicolon);
        const std::size_t colon = declaration.find(':');
        if (colon != std::string_view::npos &&
            iequals(trim(declaration.substr(0, colon)), property))
            return true;
        style.remove_prefix(std::min(semicolon + 1, style.size()));
    }
    return false;
}

} // namespace

// Whether CSS declares `property` for the element: a style sheet does, or
// its style attribute names it. The cascade of a geometry property is read
// only then: most elements have neither, and cascade() parses the style
// attribute again.
bool Reader::in_css(const pugi::xml_node& n, std::string_view property) {
    for (const CssDeclaration* d : matched(n))
        if (d->name == property) return true;
    return declares(n.attribute("style").value(), property);
}

// A length attribute, or for a geometry property its cascaded value (the
// last valid declaration); nullopt when absent, auto, or invalid (a problem
// for each invalid declaration).
std::optional<double> Reader::length(const pugi::xml_node& n, const char* attr, double percent_of,
                                     const LengthContext& ctx) {
    std::optional<double> value;
    const auto take = [&](std::string_view v, const char* from) {
        if (v == "auto") return void(value = std::nullopt);
        if (const auto len = parse_length(v, percent_of, ctx)) return void(value = len);
        problem(n, (*from ? std::string(from) + "property " : std::string("attribute ")) + attr +
                       ": '" + std::string(v) + "' is not a length; ignored");
    };
    if (!geometry_property(n.name(), attr) || !in_css(n, attr)) {
        if (const pugi::xml_attribute a = n.attribute(attr)) take(a.value(), "");
        return value;
    }
    cascade(n, false, [&](std::string_view name, std::string_view v, const char* from) {
        if (name == attr) take(v, from);
    });
    return value;
}

// Parses the text and reads its style sheets: what drawing any of its
// elements needs (read(), and a document a <use> draws from, external_use.cpp).
pugi::xml_node Reader::load() {
    // Decoded to UTF-8 first (svg/xml_encoding.h): at most 3 bytes a byte.
    DecodedDocument decoded = decode_document(text_);
    if (!decoded.warning.empty()) problem_at({name_, 1, "?xml", decoded.warning});
    if (decoded.changed) {
        decoded_ = std::move(decoded.text);
        set_text(decoded_);
    }
    EntityExpansion entities = expand_entities(text_, options_.max_entity_bytes);
    if (!entities.error.empty()) fail_at(std::ptrdiff_t(entities.offset), entities.error);
    if (entities.changed) {
        expanded_ = std::move(entities.text);
        set_text(expanded_);
    }
    const pugi::xml_parse_result res =
        // parse_ws_pcdata: the spaces between a text's tspans are its text.
        doc_.load_buffer(text_.data(), text_.size(),
                         pugi::parse_default | pugi::parse_doctype | pugi::parse_ws_pcdata);
    if (!res) fail_at(res.offset, std::string("malformed XML: ") + res.description());
    // A DOCTYPE the expansion did not find, which pugixml did: its entities
    // would go unexpanded (the text is UTF-8 by now, so a guard).
    if (!entities.doctype)
        for (const pugi::xml_node& n : doc_.children())
            if (n.type() == pugi::node_doctype && std::strstr(n.value(), "<!ENTITY"))
                fail_at(n.offset_debug(), "<!DOCTYPE>: its entity declarations could not be read");
    if (declares_own_prefixes(text_)) renamed_ = normalize_namespaces(doc_); // svg:svg, ns0:rect
    const pugi::xml_node root = root_ = doc_.document_element();
    if (std::strcmp(root.name(), "svg") != 0) {
        const std::string written = written_name(root);
        fail_at(offset_of(root), "the root element is <" + written + ">, not <svg>" +
                                     (written == "svg" ? " of the SVG namespace" : ""));
    }
    read_style_sheets(root);
    return root;
}

Scene Reader::read() {
    const pugi::xml_node root = load();
    Scene scene;
    StyleState style;
    // The root's font-size first: it is what rem means, and its own
    // lengths (width="20em") and the viewport depend on it.
    apply_declarations(root, style, style, nullptr, {});
    root_font_size_ = style.font_size;
    const std::optional<Affine> view = viewport(root, scene, context(style));
    ElementProps props;
    apply_declarations(root, style, style, &props, context(style));
    keep_own_values(style, props, "svg");
    // A zero-sized viewBox, or display: none on the root: nothing is drawn.
    if (!view || props.display_none) return scene;
    if (const std::size_t n = expanded_size(root, 0); n > options_.max_elements)
        fail(root, "more than " + std::to_string(options_.max_elements) +
                       " elements once <use> is expanded (the limit)");
    const Affine m = root_transform(props, scene.width, scene.height) * *view;
    walk(root, style, m, scene.root, 1);
    Group top{props.opacity, std::move(scene.root.children)};
    if (has_effects(props)) apply_effects(root, props, m, top, 1);
    scene.root = {};
    add_group(scene.root, std::move(top));
    return scene;
}

// The root's width and height (SVG 2, 8.2, with CSS 2.1 10.3.2 and 10.6.2
// for a replaced element's size): an absolute length as given; a side that
// is absent, auto or a percentage (of no containing block: a standalone file
// has none) while the other is absolute follows the viewBox's aspect ratio,
// as in browsers' <img> and librsvg; with neither absolute, each is that
// fraction (auto: all) of the viewBox's size, or of 100 x 100 without a
// viewBox (resvg's default). Then the viewBox mapping (SVG 1.1, 7.7 and
// 7.8; the root's own transform goes before it, root_transform). Nothing to
// draw (nullopt) when the viewBox is zero-sized.
// What @media queries are answered for (svg/media_query.h): the color
// scheme, and the viewport the picture is drawn at: the document's size
// before any style sheet (font sizes of 16 px), mapped as
// SvgOptions::media_size asks (render/output_size.h). No size when the
// document's is unusable (the read fails on it later anyway).
MediaContext Reader::media_context(const pugi::xml_node& root) {
    MediaContext m{options_.dark};
    const auto [w, h] = [&] {
        const ScopedValue quiet(quiet_, true); // told when the document's size is read
        return document_size(root, view_box(root), LengthContext{16, 16, 0, 0});
    }();
    if (!(w > 0) || !(h > 0) || w > options_.max_size || h > options_.max_size) return m;
    const OutputSize size = output_size(w, h, options_.media_size);
    if (!size.error.empty()) return m;
    m.width = size.width, m.height = size.height;
    return m;
}

// The root's size (see viewport below); problems with its attributes are
// told (unless quiet), and not checked against the limits.
std::pair<double, double> Reader::document_size(const pugi::xml_node& root,
                                                const std::optional<ViewBox>& box,
                                                const LengthContext& ctx) {
    struct Side {
        double length;
        bool absolute;
    };
    const auto side = [&](const char* attr, double from_box) {
        const double full = box ? from_box : 100;
        std::string v = root.attribute(attr).value();
        if (v.empty() || v == "auto") return Side{full, false};
        const auto len = parse_length(v, full, ctx);
        // Negative: an error that invalidates the attribute (SVG 2, 8.2), so
        // auto, as an unparsable value; zero is valid and disables rendering.
        if (len && *len >= 0) return Side{*len, v.find('%') == std::string::npos};
        problem(root, std::string("attribute ") + attr + ": '" + v + "' is " +
                          (len ? "negative" : "not a length") + "; ignored");
        return Side{full, false};
    };
    const Side w = side("width", box ? box->w : 0), h = side("height", box ? box->h : 0);
    const bool ratio = box && box->w > 0 && box->h > 0 && w.absolute != h.absolute;
    return {ratio && h.absolute ? h.length * box->w / box->h : w.length,
            ratio && w.absolute ? w.length * box->h / box->w : h.length};
}

// The document's gradients, their percentages of the viewport vw_ x vh_.
void Reader::index_gradients(const pugi::xml_node& root) {
    // A stop's stop-color and stop-opacity come from the cascade; its
    // currentColor is its computed color (style_of, quiet).
    gradients_.emplace(root, vw_, vh_,
                       GradientStyle{[this](const pugi::xml_node& n, const char* property) {
                                         return declarations(n, property);
                                     },
                                     [this](const pugi::xml_node& n) {
                                         ElementProps props;
                                         return style_of(n, props).color;
                                     }});
}

std::optional<Affine> Reader::viewport(const pugi::xml_node& root, Scene& scene,
                                       const LengthContext& ctx) {
    const std::optional<ViewBox> box = view_box(root);
    std::tie(scene.width, scene.height) = document_size(root, box, ctx);
    for (const double d : {scene.width, scene.height}) {
        char size[32]; // "%g": 1e+308, not its 309 digits
        std::snprintf(size, sizeof size, "%g", d);
        if (!(d > 0)) fail(root, std::string("the document size ") + size + " must be positive");
        if (d > options_.max_size)
            fail(root, std::string("the document size ") + size + " px exceeds the limit of " +
                           std::to_string(int(options_.max_size)) + " px");
    }
    vw_ = box ? box->w : scene.width;
    vh_ = box ? box->h : scene.height;
    index_gradients(root);
    if (box && (box->w == 0 || box->h == 0)) {
        warn(root, "viewBox: a zero width or height disables rendering");
        return std::nullopt;
    }
    return box ? view_map(root, *box, scene.width, scene.height) : Affine::identity();
}

// The element's viewBox: nullopt when absent, or in error (a problem; the
// element is then drawn as if it had none). A zero-sized box is returned:
// the caller disables rendering.
std::optional<ViewBox> Reader::view_box(const pugi::xml_node& n) {
    const pugi::xml_attribute a = n.attribute("viewBox");
    if (!a) return std::nullopt;
    ViewBoxResult vb = parse_view_box(a.value());
    if (!vb.error.empty()) problem(n, vb.error);
    return vb.box;
}

// `box` onto a w x h viewport at the origin, aligned by the element's
// preserveAspectRatio (invalid: a problem, and xMidYMid meet).
Affine Reader::view_map(const pugi::xml_node& n, const ViewBox& box, double w, double h) {
    AspectRatio ar;
    if (const pugi::xml_attribute a = n.attribute("preserveAspectRatio")) {
        if (const auto parsed = parse_aspect_ratio(a.value()))
            ar = *parsed;
        else
            problem(n, std::string("preserveAspectRatio: '") + a.value() +
                           "' is invalid; xMidYMid meet is used");
    }
    return view_box_transform(box, ar, 0, 0, w, h);
}

// The element's declarations in cascade order (CSS Cascade 4, 6.1; SVG 2,
// 6.9), each later one winning: presentation attributes, the style sheets'
// normal declarations (ascending specificity, then source order), the style
// attribute's normal ones, the sheets' !important ones, the style
// attribute's !important ones. `visit` is given each one's name, value and
// where it is from as problems name it ("", "style sheet: " or "style: "),
// and must not call matched() (the sheet's declarations are matched_).
// With `tell`, the style attribute's syntax problems are problems.
void Reader::cascade(const pugi::xml_node& n, bool tell, const DeclarationVisitor& visit) {
    // The shorthands marker and font, and Compositing 1's mix-blend-mode and
    // isolation, are CSS's only, not presentation attributes (SVG 2, 6.6),
    // as browsers and librsvg read them.
    const auto presentation = [](const char* name) {
        for (const char* css_only : {"style", "marker", "font", "mix-blend-mode", "isolation"})
            if (std::strcmp(name, css_only) == 0) return false;
        return true;
    };
    for (const pugi::xml_attribute& a : n.attributes())
        if (presentation(a.name())) visit(a.name(), a.value(), "");
    const std::vector<const CssDeclaration*>& sheet = matched(n);
    std::vector<CssDeclaration> inline_style;
    if (const pugi::xml_attribute a = n.attribute("style")) {
        std::vector<CssProblem> problems;
        inline_style = parse_css_declarations(a.value(), problems);
        if (tell)
            for (const CssProblem& p : problems) problem(n, "style: " + p.message);
    }
    // A CSS declaration's var()s substituted from the element's custom
    // properties (svg/custom_properties.h); one that cannot be is dropped.
    const auto css = [&](const std::string& name, std::string_view value, const char* from) {
        if (!vars_ || name.rfind("--", 0) == 0 || !has_var(value)) return visit(name, value, from);
        if (const auto v = substitute_vars(value, custom_.get(), options_.max_attribute_bytes))
            return visit(name, *v, from);
        if (tell)
            problem(n, std::string(from) + "property " + name + ": '" + std::string(value) +
                           "': a var() names no custom property and has no fallback, or "
                           "refers back to itself; ignored");
    };
    for (const bool important : {false, true}) {
        for (const CssDeclaration* d : sheet)
            if (d->important == important) css(d->name, d->value, "style sheet: ");
        for (const CssDeclaration& d : inline_style)
            if (d.important == important) css(d.name, d.value, "style: ");
    }
}

// The element's custom properties: its parent's (already in `style`) and
// those its CSS declares, in cascade order.
void Reader::collect_custom(const pugi::xml_node& n, StyleState& style) {
    std::shared_ptr<CustomProperties> own;
    cascade(n, false, [&](std::string_view name, std::string_view value, const char* from) {
        if (!*from || name.size() < 3 || name.substr(0, 2) != "--") return;
        if (!own)
            own = style.custom ? std::make_shared<CustomProperties>(*style.custom)
                               : std::make_shared<CustomProperties>();
        const auto same =
            std::find_if(own->begin(), own->end(), [&](const auto& p) { return p.first == name; });
        if (same != own->end())
            same->second = trim(value);
        else
            own->emplace_back(std::string(name), std::string(trim(value)));
    });
    if (own) style.custom = std::move(own);
}

// The values declared for one property on the element, in cascade order
// (the last wins), as declared, not checked: for the properties the caller
// resolves itself (a stop's stop-color and stop-opacity), which must pass an
// invalid one over for the one before it, as CSS drops an invalid declaration.
std::vector<std::string> Reader::declarations(const pugi::xml_node& n, std::string_view property) {
    // var()s take n's custom properties (style_of computes them), not the
    // element being drawn's, which are put back after.
    const std::shared_ptr<const CustomProperties> drawn = custom_;
    if (vars_) {
        ElementProps props;
        custom_ = style_of(n, props).custom;
    }
    std::vector<std::string> values;
    cascade(n, false, [&](std::string_view name, std::string_view v, const char*) {
        if (name == property) values.emplace_back(v);
    });
    custom_ = drawn;
    return values;
}

// Applies the element's declarations (see cascade). Without `props`, only
// font-size and the font shorthand (which sets it): the first of two
// passes, since every other length may be in em. An invalid value is a
// problem, and the property keeps what it had.
void Reader::apply_declarations(const pugi::xml_node& n, const StyleState& parent,
                                StyleState& style, ElementProps* props, const LengthContext& ctx) {
    if (!props)
        for (const pugi::xml_attribute& a : n.attributes()) check_length_limit(n, a);
    if (vars_) {
        if (!props) collect_custom(n, style);
        custom_ = style.custom;
    }
    ElementProps unused;
    const auto apply = [&](std::string_view name, std::string_view value, const char* from) {
        // The font shorthand goes in both: its size in the first, the
        // properties it resets in the second, in their cascade order.
        const bool shorthand = name == "font";
        if (!shorthand && (name == "font-size") == (props != nullptr)) return;
        if (name == "transform") {
            if (props) take_transform(n, value, from, *props, ctx);
            return;
        }
        const double size = style.font_size;
        const std::string e =
            apply_property(name, value, parent, style, props ? *props : unused, ctx);
        if (shorthand && props) style.font_size = size;
        if (!e.empty() && (props || !shorthand)) problem(n, from + e + "; ignored");
    };
    cascade(n, props != nullptr, std::ref(apply)); // by reference: no copy of the closure
}

// The style sheet declarations matching `n`, kept for the element's second
// pass (and for style_of's repeated ones).
const std::vector<const CssDeclaration*>& Reader::matched(const pugi::xml_node& n) {
    if (!matcher_ || n == matched_node_) return matched_;
    matched_node_ = n;
    if (!matcher_->match(PugiCssTree::node(n), matched_))
        fail(n, "style sheets: more than " + std::to_string(kCssDefaultMaxWork) +
                    " selector tests (the limit)");
    return matched_;
}

namespace {

// Whether a sheet's text has an @media rule (in any case), the only part of
// it whose reading depends on the document's size.
bool contains_media_rule(std::string_view css) {
    for (std::size_t at = css.find('@'); at != std::string_view::npos; at = css.find('@', at + 1))
        if (iequals(css.substr(at + 1, 5), "media")) return true;
    return false;
}

} // namespace

// Every <style> element's sheet (type text/css, empty or absent), in
// document order, before any element is styled: a sheet applies to the
// whole document. Its text is its character data, CDATA included. The
// sheets the prolog links (xml-stylesheet) come first, and each sheet's
// @import rules before its own (linked_style_sheets.cpp).
void Reader::read_style_sheets(const pugi::xml_node& root) {
    std::vector<pugi::xml_node> styles;
    struct Walker : pugi::xml_tree_walker {
        std::vector<pugi::xml_node>* out;
        bool external_use = false; // a <use> of another file's element
        bool for_each(pugi::xml_node& e) override {
            if (e.type() != pugi::node_element) return true;
            if (std::strcmp(e.name(), "style") == 0) out->push_back(e);
            if (std::strcmp(e.name(), "use") == 0) {
                const std::string_view href = use_href(e);
                external_use = external_use || (!href.empty() && href[0] != '#');
            }
            return true;
        }
    } walker;
    walker.out = &styles;
    pugi::xml_node(root).traverse(walker);
    // Another file's elements may read custom properties this one sets.
    vars_ = vars_ || walker.external_use;
    linked_style_sheets(root);
    for (const pugi::xml_node& st : styles) {
        const std::string_view type = st.attribute("type").value();
        if (!type.empty() && type != "text/css") continue;
        std::string css;
        for (const pugi::xml_node& c : st.children())
            if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) css += c.value();
        if (css.size() > options_.max_attribute_bytes)
            fail(st, "a style sheet of " + std::to_string(css.size()) +
                         " bytes, over the limit of " +
                         std::to_string(options_.max_attribute_bytes) + " bytes");
        const std::size_t font_faces = sheet_.font_faces().size();
        parse_sheet(css, located(st, ""), options_.base_dir, 0);
        load_font_faces(st, font_faces);
    }
    if (!sheet_.empty()) matcher_ = std::make_unique<CssMatcher>(sheet_, css_tree_);
}

// One sheet's text into the document's: the sheets its @import rules name
// first, then its own rules. `at` locates its first line; `dir` is where its
// relative URLs start.
void Reader::parse_sheet(std::string_view css, const SvgDiagnostic& at, const std::string& dir,
                         int depth) {
    // A var() in any sheet: custom properties are tracked (set_text looks
    // only at the document's own text).
    vars_ = vars_ || has_var(css);
    std::vector<CssProblem> problems;
    const std::vector<CssImport> imports = css_imports(css, problems);
    sheet_problems(problems, at);
    for (const CssImport& imp : imports) {
        SvgDiagnostic where = at;
        where.line += imp.line - 1;
        import_sheet(where, imp.url, imp.media, dir, depth + 1);
    }
    problems.clear();
    if (!media_ && contains_media_rule(css)) media_ = media_context(root_);
    sheet_.parse(css, problems, media_ ? *media_ : MediaContext{options_.dark});
    sheet_problems(problems, at);
}

// A sheet's problems, their lines within the sheet that starts at `at`'s.
void Reader::sheet_problems(const std::vector<CssProblem>& problems, const SvgDiagnostic& at) {
    for (const CssProblem& p : problems) {
        SvgDiagnostic d = at;
        d.line += p.line - 1;
        d.message = "style sheet: " + p.message;
        if (p.unsupported && !quiet_)
            warnings_.push_back(std::move(d));
        else
            problem_at(std::move(d));
    }
}

// Whether the element's conditional attributes let it be rendered.
bool Reader::conditions_hold(const pugi::xml_node& n) const {
    Conditions c;
    if (const pugi::xml_attribute a = n.attribute("systemLanguage")) c.system_language = a.value();
    if (const pugi::xml_attribute a = n.attribute("requiredExtensions"))
        c.required_extensions = a.value();
    return casteljau::conditions_hold(c, options_.languages);
}

// One element and what it holds, drawn into `out`. Every element visited
// counts against the element limit, instances of <use> included, so a
// nest of uses that would expand past it stops there (billion laughs).
void Reader::element(const pugi::xml_node& n, const StyleState& parent_style, const Affine& ctm,
                     Group& out, int depth) {
    count_element(n, depth);
    const std::string_view name = n.name();
    if (name.find(':') != name.npos || silently_skipped(name)) return; // foreign namespaces
    const bool group = name == "g" || name == "a";
    const bool structure = group || name == "switch" || name == "svg" || name == "use" ||
                           name == "image" || name == "text";
    if (!structure && !is_shape(name)) {
        if (unsupported(name)) warn(n, "not supported yet; skipped");
        return; // symbol too: drawn only through <use>
    }
    // A clip path holds shapes, text and uses of them; any other child is
    // invalid there and ignored (CSS Masking 1, 6.1).
    if (clip_mode_ && !is_shape(name) && name != "use" && name != "text") return;
    if (!conditions_hold(n)) return;
    StyleState style = parent_style;
    ElementProps props;
    apply_declarations(n, parent_style, style, nullptr, context(parent_style));
    apply_declarations(n, parent_style, style, &props, context(style));
    keep_own_values(style, props, name);
    read_language(n, style.text);
    if (props.display_none) return;
    if (clip_mode_) { // in a clip path, only the clip-path of its children counts
        props.opacity = 1;
        props.mask.clear();
        props.blend = BlendMode::Normal;
        props.isolate = false;
        props.filter.clear(); // a clip path is the shapes' geometry (CSS Masking 1, 6.1)
    }
    // fill_box() walks the element it measures untransformed.
    const Affine m = props.transform && n != measuring_
                         ? ctm * own_transform(n, name, parent_style, style, props, depth)
                         : ctm;
    Group g{props.opacity, {}};
    Group boxed; // a shape with markers and effects: the shape alone
    if (group) {
        walk(n, style, m, g, depth + 1);
    } else if (name == "switch") {
        // The first child whose conditions hold, passing over those this
        // reader cannot draw (foreignObject: draw.io's HTML labels, whose
        // next sibling is their text), as librsvg and resvg do, rather than
        // drawing nothing there; with no other, that one is skipped with
        // its warning.
        pugi::xml_node chosen, passed;
        for (const pugi::xml_node& c : n.children())
            if (c.type() == pugi::node_element && conditions_hold(c)) {
                if (!unsupported(c.name())) {
                    chosen = c;
                    break;
                }
                if (!passed) passed = c;
            }
        if (chosen || passed) element(chosen ? chosen : passed, style, m, g, depth + 1);
    } else if (name == "svg") {
        nested_viewport(n, nullptr, style, props, m, g, depth);
    } else if (name == "use") {
        use(n, parent_style, style, m, g, depth);
    } else if (name == "image") {
        image(n, style, m, g);
    } else if (name == "text") {
        text(n, style, props, m, g, depth);
    } else if (depth_ = depth; std::optional<Shape> sh = shape(n, name, style, m, props)) {
        const bool markable =
            name == "path" || name == "line" || name == "polyline" || name == "polygon";
        if (!markable || clip_mode_ ||
            (style.marker_start.empty() && style.marker_mid.empty() && style.marker_end.empty())) {
            if (!has_effects(props)) {
                out.children.push_back(Node{std::move(*sh)});
                return;
            }
            // Its effects on a group of its own, which carries its opacity too.
            sh->opacity = 1;
            g.children.push_back(Node{std::move(*sh)});
            apply_effects(n, props, m, g, depth);
            add_group(out, std::move(g));
            return;
        }
        // The element's opacity covers its markers too: the group carries it.
        sh->opacity = 1;
        // Its effects' bounding box is the shape's alone (SVG 2, 8.10).
        if (has_effects(props)) boxed.children.push_back(Node{*sh});
        Group marks{1, {}}; // not into g: its shape must stay where it is meanwhile
        markers(n, *sh, style, marks, depth);
        // paint-order with markers: before both paints, between them (the
        // shape split into its fill and its stroke), or after both.
        const std::array<int, 3>& po = style.paint_order;
        if (po[2] > po[0] && po[2] > po[1]) {
            g.children.push_back(Node{std::move(*sh)});
            add_group(g, std::move(marks));
        } else if (po[2] < po[0] && po[2] < po[1]) {
            add_group(g, std::move(marks));
            g.children.push_back(Node{std::move(*sh)});
        } else {
            Shape before = *sh;
            if (po[0] < po[1]) {
                before.stroke.reset(); // fill, markers, stroke
                sh->fill.reset();
            } else {
                before.fill.reset(); // stroke, markers, fill
                sh->stroke.reset();
            }
            g.children.push_back(Node{std::move(before)});
            add_group(g, std::move(marks));
            g.children.push_back(Node{std::move(*sh)});
        }
    }
    if (has_effects(props))
        apply_effects(n, props, m, g, depth, boxed.children.empty() ? nullptr : &boxed);
    add_group(out, std::move(g));
}

std::optional<Shape> Reader::shape(const pugi::xml_node& n, std::string_view name,
                                   const StyleState& style, const Affine& m,
                                   const ElementProps& props) {
    Path path = geometry(n, name, context(style));
    if (!style.visible || path.empty()) return std::nullopt;
    return painted(n, std::move(path), style, m, props);
}

// A required length that must not be negative: nullopt, and the element
// is not drawn, when it is (SVG 1.1, 9: "a negative value is an error").
std::optional<double> Reader::non_negative(const pugi::xml_node& n, const char* attr,
                                           std::optional<double> v) {
    if (v && *v < 0) {
        problem(n, std::string("attribute ") + attr +
                       ": a negative value is an error; the element is not drawn");
        return std::nullopt;
    }
    return v ? v : 0.0;
}

// A radius that may be auto (rx, ry): a negative value is invalid and
// ignored (SVG 2, 10.5: "must be ignored"), so the initial value, auto,
// is used (nullopt), as browsers do (WPT's ellipse-006 and rect-007).
std::optional<double> Reader::radius_or_auto(const pugi::xml_node& n, const char* attr,
                                             std::optional<double> v) {
    if (!v || *v >= 0) return v;
    problem(n, std::string("attribute ") + attr + ": a negative value is invalid; auto is used");
    return std::nullopt;
}

Path Reader::geometry(const pugi::xml_node& n, std::string_view name, const LengthContext& ctx) {
    if (name == "path") return path_data(n);
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
    if (name == "line") return line_path({at("x1", w), at("y1", h)}, {at("x2", w), at("y2", h)});
    if (name == "rect") {
        const auto rw = non_negative(n, "width", len("width", w));
        const auto rh = non_negative(n, "height", len("height", h));
        // rx, ry: absent or auto (-1) take the other's value (9.2).
        const auto rx = radius_or_auto(n, "rx", len("rx", w));
        const auto ry = radius_or_auto(n, "ry", len("ry", h));
        if (!rw || !rh || *rw == 0 || *rh == 0) return {};
        return rect_path(at("x", w), at("y", h), *rw, *rh, rx.value_or(-1), ry.value_or(-1));
    }
    if (name == "circle") {
        const auto r = non_negative(n, "r", len("r", d));
        if (!r || *r == 0) return {};
        return ellipse_path(at("cx", w), at("cy", h), *r, *r);
    }
    // ellipse: an absent or auto radius takes the other's (SVG 2, 10.4).
    auto rx = radius_or_auto(n, "rx", len("rx", w)), ry = radius_or_auto(n, "ry", len("ry", h));
    if (!rx) rx = ry;
    if (!ry) ry = rx;
    if (!rx || *rx == 0 || *ry == 0) return {};
    return ellipse_path(at("cx", w), at("cy", h), *rx, *ry);
}

} // namespace svg_detail

SvgResult parse_svg(std::string_view text, const std::string& name, const SvgOptions& options) {
    if (text.size() > options.max_file_bytes) {
        SvgResult r;
        r.error = name + ": " + std::to_string(text.size()) + " bytes exceed the limit of " +
                  std::to_string(options.max_file_bytes);
        return r;
    }
    // SVGZ (io/gunzip.h), inflated under the same limit.
    const std::span<const unsigned char> bytes(reinterpret_cast<const unsigned char*>(text.data()),
                                               text.size());
    if (is_gzip(bytes)) {
        const Gunzipped svg = gunzip(bytes, options.max_file_bytes);
        if (!svg.error.empty()) {
            SvgResult r;
            r.error = name + ": gzip data: " + svg.error;
            return r;
        }
        return svg_detail::Reader(svg.data, name, options).run();
    }
    return svg_detail::Reader(text, name, options).run();
}

SvgResult read_svg_file(const std::string& path, const SvgOptions& options) {
    const TextFile file = read_text_file(path, options.max_file_bytes);
    if (!file.error.empty()) {
        SvgResult r;
        r.error = file.error;
        r.io_error = file.io_error;
        return r;
    }
    SvgOptions o = options;
    if (o.base_dir.empty()) o.base_dir = std::filesystem::path(path).parent_path().string();
    if (o.base_dir.empty()) o.base_dir = ".";
    return parse_svg(file.text, path, o);
}

} // namespace casteljau
