// Internal to the SVG reader (not installed): the Reader class, whose work
// is split by concern over svg/reader.cpp (the document, properties,
// elements, shapes and paints) and svg/instancing.cpp (what one element
// draws in another's place: use, symbol and nested svg viewports, markers,
// and the count of what instancing expands to).
#pragma once

#include "casteljau/svg/css.h"
#include "casteljau/svg/detail/css_pugi.h"
#include "casteljau/svg/detail/gradients.h"
#include "casteljau/svg/detail/href.h"
#include "casteljau/svg/detail/xml_namespaces.h"
#include "casteljau/svg/font_face.h"
#include "casteljau/svg/marker_vertices.h"
#include "casteljau/svg/reader.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/svg/style.h"
#include "casteljau/svg/viewport.h"

#include <algorithm>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace casteljau::svg_detail {

struct Failure {
    std::string message;
};

// Elements that are never rendered by themselves: skipped without a warning
// (a marker is drawn only through the marker properties).
inline bool silently_skipped(std::string_view n) {
    return n == "title" || n == "desc" || n == "metadata" || n == "defs" || n == "linearGradient" ||
           n == "radialGradient" || n == "stop" || n == "script" || n == "marker" || n == "style" ||
           n == "clipPath" || n == "mask" || n == "pattern";
}

// SVG elements that change what a file shows and that this reader does not
// draw yet: skipped with a warning. Any other element (but symbol, drawn only
// through use) is unknown to SVG, and an unknown element is not rendered
// (SVG 2, 5.9 "unknown elements"): no warning.
inline bool unsupported(std::string_view n) {
    static const std::set<std::string_view> names = {"foreignObject"};
    return names.count(n) != 0;
}

// An element's language, xml:lang or lang (SVG 2, 2.4.2), into the text
// state its descendants inherit.
inline void read_language(const pugi::xml_node& n, TextState& text) {
    if (const pugi::xml_attribute a = n.attribute("xml:lang"))
        text.language = a.value();
    else if (const pugi::xml_attribute b = n.attribute("lang"))
        text.language = b.value();
}

inline bool is_shape(std::string_view n) {
    return n == "path" || n == "rect" || n == "circle" || n == "ellipse" || n == "line" ||
           n == "polyline" || n == "polygon";
}

// Gives `slot` a value for a scope and puts the old one back after: the
// reader's quiet walks (re-reading an element whose problems are told where
// it is drawn), nested and left early alike.
template <class T>
class ScopedValue {
  public:
    ScopedValue(T& slot, T value) : slot_(slot), saved_(std::exchange(slot, std::move(value))) {}
    ~ScopedValue() { slot_ = std::move(saved_); }
    ScopedValue(const ScopedValue&) = delete;
    ScopedValue& operator=(const ScopedValue&) = delete;

  private:
    T& slot_;
    T saved_;
};

struct TextReading;
struct TextContent;
struct TextLayout;

// A filter's primitiveUnits, and the box objectBoundingBox refers to.
struct PrimitiveUnits {
    bool obb = false;
    Rect bbox;
};

class Reader {
  public:
    Reader(std::string_view text, std::string name, const SvgOptions& options)
        : name_(std::move(name)), options_(options) {
        if (!options_.image_budget) options_.image_budget = std::make_shared<ImageBudget>();
        set_text(text);
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
    // Where n starts in the text, and its name as written: a renamed
    // element's (xml_namespaces.h) are those before the renaming.
    std::ptrdiff_t offset_of(const pugi::xml_node& n) const {
        const auto it = renamed_.find(n.internal_object());
        return it == renamed_.end() ? n.offset_debug() : it->second.offset;
    }
    const char* written_name(const pugi::xml_node& n) const {
        const auto it = renamed_.find(n.internal_object());
        return it == renamed_.end() ? n.name() : it->second.written.c_str();
    }
    SvgDiagnostic located(const pugi::xml_node& n, const std::string& what) const {
        return {name_, line_of(offset_of(n)), written_name(n), what};
    }
    [[noreturn]] void fail(const pugi::xml_node& n, const std::string& what) const {
        throw Failure{located(n, what).text()};
    }
    [[noreturn]] void fail_at(std::ptrdiff_t offset, const std::string& what) const {
        throw Failure{name_ + ":" + std::to_string(line_of(offset)) + ": " + what};
    }
    void warn(const pugi::xml_node& n, const std::string& what) {
        if (!quiet_) warnings_.push_back(located(n, what));
    }
    // A problem the spec says how to recover from: a warning, and the caller
    // recovers; with `strict`, the error that ends the read.
    void problem(const pugi::xml_node& n, const std::string& what) {
        if (quiet_) return;
        if (options_.strict) fail(n, what);
        warn(n, what);
    }
    // The same, located by `d` (in a file other than this one, or in a
    // style sheet's text).
    void problem_at(SvgDiagnostic d) {
        if (quiet_) return;
        if (options_.strict) throw Failure{d.text()};
        warnings_.push_back(std::move(d));
    }
    LengthContext context(const StyleState& s) const {
        return {s.font_size, root_font_size_, vw_, vh_};
    }
    bool in_css(const pugi::xml_node& n, std::string_view property);
    std::optional<double> length(const pugi::xml_node& n, const char* attr, double percent_of,
                                 const LengthContext& ctx);
    // A path's d: the attribute, or the CSS d property (svg/d_property.cpp).
    Path path_data(const pugi::xml_node& n);
    pugi::xml_node load();
    void index_gradients(const pugi::xml_node& root);
    Scene read();
    MediaContext media_context(const pugi::xml_node& root);
    std::pair<double, double> document_size(const pugi::xml_node& root,
                                            const std::optional<ViewBox>& box,
                                            const LengthContext& ctx);
    std::optional<MediaContext> media_; // what @media is answered for, once a sheet has one
    std::optional<Affine> viewport(const pugi::xml_node& root, Scene& scene,
                                   const LengthContext& ctx);
    std::optional<ViewBox> view_box(const pugi::xml_node& n);
    Affine view_map(const pugi::xml_node& n, const ViewBox& box, double w, double h);
    // Counts an element against the element limit and checks how deep it
    // is; over either limit, the read ends.
    void count_element(const pugi::xml_node& n, int depth) {
        if (++elements_ > options_.max_elements)
            fail(n, "more than " + std::to_string(options_.max_elements) +
                        " elements, <use> instances included (the limit)");
        if (depth > options_.max_depth)
            fail(n, "elements nested deeper than " + std::to_string(options_.max_depth) +
                        ", <use> instances included (the limit)");
    }
    void check_length_limit(const pugi::xml_node& n, const pugi::xml_attribute& a) const {
        if (const std::size_t len = std::strlen(a.value()); len > options_.max_attribute_bytes)
            fail(n, std::string("attribute ") + a.name() + " is " + std::to_string(len) +
                        " bytes, over the limit of " +
                        std::to_string(options_.max_attribute_bytes) + " bytes");
    }
    using DeclarationVisitor =
        std::function<void(std::string_view name, std::string_view value, const char* from)>;
    void cascade(const pugi::xml_node& n, bool tell, const DeclarationVisitor& visit);
    std::vector<std::string> declarations(const pugi::xml_node& n, std::string_view property);
    void apply_declarations(const pugi::xml_node& n, const StyleState& parent, StyleState& style,
                            ElementProps* props, const LengthContext& ctx);
    void collect_custom(const pugi::xml_node& n, StyleState& style);
    void walk(const pugi::xml_node& parent, const StyleState& parent_style, const Affine& ctm,
              Group& out, int depth) {
        for (const pugi::xml_node& n : parent.children())
            if (n.type() == pugi::node_element) element(n, parent_style, ctm, out, depth);
    }
    bool conditions_hold(const pugi::xml_node& n) const;
    void read_style_sheets(const pugi::xml_node& root);
    void parse_sheet(std::string_view css, const SvgDiagnostic& at, const std::string& dir,
                     int depth);
    void sheet_problems(const std::vector<CssProblem>& problems, const SvgDiagnostic& at);
    // Style sheets in files: xml-stylesheet, @import (svg/linked_style_sheets.cpp).
    void linked_style_sheets(const pugi::xml_node& root);
    void import_sheet(const SvgDiagnostic& where, const std::string& href, const std::string& media,
                      const std::string& dir, int depth);
    const std::vector<const CssDeclaration*>& matched(const pugi::xml_node& n);
    // Adds a group's children to `out`, or the group itself when it needs a
    // layer (opacity, a clip, a mask, a blend mode, isolation).
    static void add_group(Group& out, Group g) {
        if (!g.needs_layer())
            std::move(g.children.begin(), g.children.end(), std::back_inserter(out.children));
        else if (!g.children.empty() || !g.filters.empty()) // a filter draws on empty too
            out.children.push_back(Node{std::move(g)});
    }
    void element(const pugi::xml_node& n, const StyleState& parent_style, const Affine& ctm,
                 Group& out, int depth);
    // transform, transform-origin and transform-box (svg/element_transform.cpp).
    void take_transform(const pugi::xml_node& n, std::string_view value, const char* from,
                        ElementProps& props, const LengthContext& ctx);
    Affine own_transform(const pugi::xml_node& n, std::string_view name,
                         const StyleState& parent_style, const StyleState& style,
                         const ElementProps& props, int depth);
    Rect fill_box(const pugi::xml_node& n, std::string_view name, const StyleState& parent_style,
                  const StyleState& style, bool stroke, int depth);
    Affine root_transform(const ElementProps& props, double width, double height) const;
    void use(const pugi::xml_node& n, const StyleState& parent_style, const StyleState& style,
             const Affine& m, Group& out, int depth);
    void local_use(const pugi::xml_node& n, const pugi::xml_node& target, const std::string& quoted,
                   const StyleState& parent_style, const StyleState& style, const Affine& m,
                   Group& out, int depth);
    // A use's width and height, where given: they win over its symbol's or svg's.
    struct UseSize {
        std::optional<double> width, height;
    };
    struct ContextPaints;
    void draw_use(const pugi::xml_node& n, Reader& doc, const pugi::xml_node& target,
                  const StyleState& parent_style, const StyleState& style, const Affine& m,
                  Group& out, int depth, const std::string& key = {});
    void instance(const pugi::xml_node& target, const StyleState& style, const Affine& m,
                  ContextPaints paints, const UseSize& size, Group& out, int depth);
    // An element of another file (svg/external_use.cpp).
    void external_instance(Reader& doc, const std::string& key, const pugi::xml_node& target,
                           const StyleState& style, const Affine& m, ContextPaints paints,
                           const UseSize& size, Group& out, int depth);
    void external_use(const pugi::xml_node& n, std::string_view href,
                      const StyleState& parent_style, const StyleState& style, const Affine& m,
                      Group& out, int depth);
    Reader* external_document(const pugi::xml_node& n, const std::string& path);
    struct ExternalDocument;
    void load_external(ExternalDocument& d, const std::string& path);
    void nested_viewport(const pugi::xml_node& n, const UseSize* use, const StyleState& style,
                         const ElementProps& props, const Affine& m, Group& out, int depth);
    // clip-path, mask, mix-blend-mode, isolation (svg/clip_mask.cpp).
    static bool has_effects(const ElementProps& p) {
        return !p.clip_path.empty() || p.clip_shape || !p.mask.empty() ||
               p.blend != BlendMode::Normal || p.isolate || !p.filter.empty();
    }
    // `boxed`, when given, is what the element's boxes are taken from (its
    // shape without its markers: markers do not count, SVG 2, 8.10).
    void apply_effects(const pugi::xml_node& n, const ElementProps& props, const Affine& m,
                       Group& g, int depth, const Group* boxed = nullptr);
    // The user-space box of the element an effect applies to, computed on demand.
    using BoxOf = std::function<const Rect&()>;
    std::shared_ptr<const Mask> effect(const pugi::xml_node& n, const std::string& id, bool is_clip,
                                       const Affine& m, const BoxOf& bbox, int depth);
    std::shared_ptr<const Mask> clip_path(const pugi::xml_node& cp, const Affine& m,
                                          const BoxOf& bbox, int depth);
    std::shared_ptr<const Mask> mask(const pugi::xml_node& mk, const Affine& m, const BoxOf& bbox,
                                     int depth);
    // filter (svg/filters.cpp): the group's filters; false when the element
    // is not to be drawn (a reference to no filter, a filter in error).
    bool apply_filters(const pugi::xml_node& n, const ElementProps& props, const Affine& m,
                       Group& g, const BoxOf& bbox, int depth);
    std::shared_ptr<Filter> filter_element(const pugi::xml_node& n, const pugi::xml_node& f,
                                           const Affine& m, const BoxOf& bbox, int depth);
    // One primitive's operation (svg/filter_primitives.cpp); nullopt when
    // the element is not a primitive. `f` gets the drawings it needs.
    void filter_paints(const pugi::xml_node& n, const Affine& m, Filter& f);
    // False when a primitive is in error so that the element is not drawn.
    bool read_primitives(const pugi::xml_node& filter, const PrimitiveUnits& u, const Affine& m,
                         Filter& f, int depth);
    FilterOp image_input(const pugi::xml_node& e, const PrimitiveUnits& u, const StyleState& style,
                         const Affine& m, Filter& f, int depth);
    Rect subregion(const pugi::xml_node& e, const PrimitiveUnits& u, const FilterPrimitive& p,
                   const FilterGraph& g, const StyleState& style);
    std::optional<FilterOp> filter_op(const pugi::xml_node& p, const PrimitiveUnits& u,
                                      const StyleState& style, const ElementProps& props,
                                      const Affine& m, Filter& f, int depth);
    // The box of what a group draws (its shapes' paths, strokes apart), in
    // the coordinates `to_user` maps device space to.
    // With `strokes`, each stroked shape's box outset by half its width.
    static Rect user_bbox(const Group& g, const Affine& to_user, bool strokes = false);
    // A clip to the rectangle r of the coordinates m maps to device space.
    static std::shared_ptr<const Mask> rect_clip(const Rect& r, const Affine& m);
    // A clip to the outline p of those coordinates, filled by `rule`.
    static std::shared_ptr<const Mask> path_clip(Path p, const Affine& m, FillRule rule);
    std::shared_ptr<const Mask> shape_clip(const BasicShape& s, const Affine& m, const Group& g,
                                           const BoxOf& bbox);
    static bool fits(const Group& g, const Rect& r, const Affine& to_r);
    // The clip of a viewport r (in the coordinates m maps to device space)
    // around `content`; null when the content lies wholly inside.
    static std::shared_ptr<const Mask> viewport_clip(const Group& content, const Rect& r,
                                                     const Affine& m);
    std::size_t expanded_size(const pugi::xml_node& n, int depth);
    static Rect clip_box(const ElementProps& props, double w, double h);
    StyleState style_of(const pugi::xml_node& n, ElementProps& props);
    void to_host_space(Shape& s);
    void markers(const pugi::xml_node& n, const Shape& s, const StyleState& style, Group& out,
                 int depth);
    void marker(const pugi::xml_node& mk, const MarkerVertex& v, const Shape& s,
                double stroke_width, Group& out, int depth);
    pugi::xml_node by_id(const std::string& id);
    std::optional<Shape> shape(const pugi::xml_node& n, std::string_view name,
                               const StyleState& style, const Affine& m, const ElementProps& props);
    static std::shared_ptr<const Gradient> in_user_space(const Gradient& g, const Rect& box,
                                                         const Affine& m);
    // A path painted as `n`'s style says; `box` is what objectBoundingBox
    // paints refer to (the path itself when null).
    Shape painted(const pugi::xml_node& n, Path path, const StyleState& style, const Affine& m,
                  const ElementProps& props, const Path* box = nullptr);
    // <text> (svg/text.cpp): reading its content, then drawing its layout.
    FontDatabase& fonts() const {
        if (document_fonts_) return *document_fonts_;
        return options_.fonts ? *options_.fonts : FontDatabase::system();
    }
    // @font-face (svg/font_face.cpp).
    void load_font_faces(const pugi::xml_node& st, std::size_t first);
    std::optional<std::vector<unsigned char>> font_source_bytes(const FontFaceSource& s,
                                                                std::string& error);
    std::unique_ptr<FontDatabase> document_fonts_; // the @font-face fonts, over the others
    int font_faces_ = 0;                           // fonts parsed for @font-face
    void text(const pugi::xml_node& n, const StyleState& style, const ElementProps& props,
              const Affine& m, Group& out, int depth);
    void text_characters(const pugi::xml_node& at, std::string_view utf8, std::uint32_t span,
                         TextReading& r);
    bool text_span(const pugi::xml_node& e, TextReading& r, std::uint32_t parent);
    void text_positions(const pugi::xml_node& e, TextReading& r);
    void text_children(const pugi::xml_node& e, TextReading& r, int depth);
    void text_length(const pugi::xml_node& e, std::size_t begin, TextReading& r);
    bool text_path(const pugi::xml_node& e, TextReading& r);
    void draw_text(const TextContent& content, const TextLayout& layout, const Affine& m,
                   const ElementProps& props, Group& out);
    // A paint: a color, or a gradient by url(#id) with its fallback color
    // when the reference names no usable gradient (SVG 1.1, 11.2).
    struct ResolvedPaint {
        Rgba color;
        std::shared_ptr<const Gradient> gradient;
        std::shared_ptr<const Pattern> pattern;
    };
    // `path` is the painted shape's, for objectBoundingBox units, and `m`
    // its transform, into which a context paint's space is mapped.
    std::optional<ResolvedPaint> paint(const pugi::xml_node& n, const PaintSpec& spec,
                                       const StyleState& style, const Path& path, const Affine& m);
    // A context element's paint (ContextPaints): a gradient in objectBoundingBox
    // units mapped onto `box`, the element's box in its user space.
    static std::optional<ResolvedPaint> in_box(std::optional<ResolvedPaint> p, const Rect& box);
    // <image> (svg/images.cpp): a raster image's pixels or an SVG image's
    // tree, with its own size; neither when it cannot be used.
    struct ImageSource {
        std::shared_ptr<const RasterImage> raster;
        std::shared_ptr<const Group> svg;
        double width = 0, height = 0;
    };
    const ImageSource& image_source(const pugi::xml_node& n, const std::string& href);
    void read_image_source(const pugi::xml_node& n, const std::string& href, ImageSource& src);
    // `given`, when given, is the viewport instead of x, y, width, height
    // (feImage's subregion).
    void image(const pugi::xml_node& n, const StyleState& style, const Affine& m, Group& out,
               const Rect* given = nullptr);
    // The href chain of `start` through elements named like it (patterns,
    // filters), problems told (svg/patterns.cpp).
    std::vector<pugi::xml_node> same_kind_chain(const pugi::xml_node& start);
    // Units attribute `name` along `chain`: objectBoundingBox (true) or
    // userSpaceOnUse; `initial_obb` when absent, or invalid (a problem).
    bool units_of(const std::vector<pugi::xml_node>& chain, const char* name, bool initial_obb);
    // Patterns (svg/patterns.cpp): null when disabled (paints nothing), or
    // when its objectBoundingBox units find `path` without width or height
    // (then `*boxless` is set, if given).
    std::shared_ptr<const Pattern> pattern(const pugi::xml_node& pat, const Path& path, int depth,
                                           bool* boxless = nullptr);
    std::optional<double> non_negative(const pugi::xml_node& n, const char* attr,
                                       std::optional<double> v);
    std::optional<double> radius_or_auto(const pugi::xml_node& n, const char* attr,
                                         std::optional<double> v);
    Path geometry(const pugi::xml_node& n, std::string_view name, const LengthContext& ctx);
    // pathLength (svg/path_length.cpp).
    std::optional<double> path_length(const pugi::xml_node& n);
    static double measured_length(const Path& p);
    void dashes_in_path_length(const pugi::xml_node& n, Shape& s);

    // The document's text (its entities expanded, read()), its line breaks.
    void set_text(std::string_view text) {
        text_ = text;
        newlines_.clear();
        for (std::size_t i = 0; i < text.size(); ++i)
            if (text[i] == '\n') newlines_.push_back(i);
        // Any "var(" at all (in a string or a comment too: a false yes only
        // costs tracking custom properties).
        vars_ = false;
        for (std::size_t i = 0; i + 4 <= text.size() && !vars_; ++i)
            vars_ = (text[i] | 0x20) == 'v' && (text[i + 1] | 0x20) == 'a' &&
                    (text[i + 2] | 0x20) == 'r' && text[i + 3] == '(';
    }
    std::string_view text_;
    std::string decoded_;  // the text in UTF-8, when it was in another encoding
    std::string expanded_; // the text, when entities were expanded
    std::string name_;
    SvgOptions options_;
    std::vector<std::size_t> newlines_;
    std::vector<SvgDiagnostic> warnings_;
    std::set<std::string> warned_;
    std::size_t elements_ = 0;
    std::size_t text_characters_ = 0; // read so far, against max_text_characters
    double root_font_size_ = 16;
    double vw_ = 0, vh_ = 0; // viewport size in user units, for percentages
    std::optional<svg_detail::GradientIndex> gradients_;
    pugi::xml_document doc_;  // load()'s
    RenamedElements renamed_; // by normalize_namespaces
    pugi::xml_node root_;
    std::map<std::string, pugi::xml_node> ids_; // built at the first <use>
    std::vector<pugi::xml_node> instancing_;    // the <use> targets being drawn
    std::map<const void*, std::size_t> sizes_;
    std::map<const void*, Rect> fill_boxes_; // transform-box: fill-box, measured once an element
    bool vars_ = false; // the document has a var(): custom properties are tracked
    std::shared_ptr<const CustomProperties> custom_; // the element being styled's
    pugi::xml_node measuring_; // the element fill_box is walking, drawn untransformed
    StyleSheet sheet_;
    PugiCssTree css_tree_;
    std::unique_ptr<CssMatcher> matcher_; // none without style sheets
    pugi::xml_node matched_node_;         // the element matched_ is for
    std::vector<const CssDeclaration*> matched_;
    std::map<const void*, std::shared_ptr<const Pattern>> patterns_; // built without a box
    std::map<std::string, ImageSource> images_;                      // by href
    // The paints context-fill and context-stroke take: the shape's whose
    // markers, or the use's whose target, is being drawn (innermost last).
    // Their gradients and patterns are in that context element's user space,
    // `space`, their objectBoundingBox units taken from its box (SVG 2, 13.3).
    struct ContextPaints {
        std::optional<ResolvedPaint> fill, stroke;
        Affine space;
    };
    std::vector<ContextPaints> context_;
    // A file a <use> draws from; its reader keeps its text and tree.
    struct ExternalDocument {
        std::string text;                    ///< the file's (inflated) text
        std::unique_ptr<Reader> reader;      ///< null when the file cannot be used
        std::string error;                   ///< why not
        std::vector<SvgDiagnostic> warnings; ///< its reading's, until a use tells them
    };
    // What every reader of one document shares (the document read's and
    // those of the files its <use>s draw from, external_use.cpp): the files,
    // each read once, by canonical path; the other files' elements being
    // instanced ("path#id", outermost first), so that a cycle through several
    // files is found where it closes; the folder every file stays within.
    struct SharedFiles {
        std::map<std::string, ExternalDocument> documents;
        std::vector<std::string> chain;
        std::string root_dir;
    };
    std::unique_ptr<SharedFiles> own_files_ = std::make_unique<SharedFiles>(); // the first reader's
    SharedFiles* files_ = own_files_.get();
    const std::string& root_dir();
    std::vector<std::string> sheet_chain_; // the style sheet files being read, outermost first
    int depth_ = 0;          // the nesting depth of the shape being painted, for its patterns
    bool clip_mode_ = false; // drawing a clipPath's content: opaque fills of shapes only
    bool quiet_ = false;     // style_of re-reads ancestors: their problems were told  //
                             // expanded_size's, per element
};

} // namespace casteljau::svg_detail
