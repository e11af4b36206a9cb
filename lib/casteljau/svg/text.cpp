// <text>: its content read into characters and spans, laid out
// (svg/text_layout.cpp), and drawn as paths (SVG 2, chapter 11).
//
// Reading follows SVG 2, 11.8.3 and CSS Text 3, 4.1: white space is
// processed over the whole text element, across its tspans: with
// xml:space="default" (or white-space: normal) tabs and line breaks become
// spaces, a space after a space (or at the very start) is dropped, and the
// spaces at the very end are dropped; with xml:space="preserve" each is kept
// as a space (SVG 1.1, 10.15). The characters left are the addressable ones:
// the n-th value of an element's x, y, dx, dy and rotate lists applies to
// the n-th of its characters, the nearest element with a value winning; a
// rotate list shorter than the characters repeats its last value.
//
// Each span is drawn as one Shape of its glyphs' outlines with its own
// fill, stroke and paint-order; objectBoundingBox paints use the whole text
// element's box, as browsers do. Decorations are drawn in the paint of the
// element that set them: underlines and overlines under the text, line-through
// over it (CSS Text Decoration 3, 2.3).
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/detail/text_content.h"
#include "casteljau/svg/transform_list.h"
#include "casteljau/text/utf8.h"

#include <cmath>

namespace casteljau::svg_detail {

namespace {

// The position lists an element gives its characters, from its first.
struct PositionLists {
    std::size_t start = 0;
    std::vector<double> x, y, dx, dy, rotate;
};

// A list of numbers or lengths (commas or spaces between); nullopt when a
// value is malformed.
std::optional<std::vector<double>> parse_list(std::string_view v, double percent_of,
                                              const LengthContext& ctx, bool lengths) {
    std::vector<double> out;
    for (std::size_t i = 0; i < v.size();) {
        while (i < v.size() && (std::isspace(static_cast<unsigned char>(v[i])) || v[i] == ',')) ++i;
        const std::size_t b = i;
        while (i < v.size() && !std::isspace(static_cast<unsigned char>(v[i])) && v[i] != ',') ++i;
        if (i == b) break;
        const std::string_view word = v.substr(b, i - b);
        const auto value = lengths ? parse_length(word, percent_of, ctx) : parse_number(word);
        if (!value) return std::nullopt;
        out.push_back(*value);
    }
    return out;
}

std::optional<double> value_at(const std::vector<PositionLists>& stack, std::size_t index,
                               std::vector<double> PositionLists::*list) {
    for (auto it = stack.rbegin(); it != stack.rend(); ++it)
        if (index - it->start < ((*it).*list).size()) return ((*it).*list)[index - it->start];
    return std::nullopt;
}

// The rotate value of a character: that of the nearest element with a
// rotate list, its value for the index or, past its end, its last value
// (SVG 1.1, 10.5; SVG 2, 11.8.3).
std::optional<double> rotate_at(const std::vector<PositionLists>& stack, std::size_t index) {
    for (auto it = stack.rbegin(); it != stack.rend(); ++it)
        if (!it->rotate.empty())
            return index - it->start < it->rotate.size() ? it->rotate[index - it->start]
                                                         : it->rotate.back();
    return std::nullopt;
}

// All the character data under `n`, in document order (tref, SVG 1.1,
// 10.6); pugixml's walk is iterative, so any depth is safe.
std::string text_content(const pugi::xml_node& n) {
    struct Walker : pugi::xml_tree_walker {
        std::string out;
        bool for_each(pugi::xml_node& c) override {
            if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) out += c.value();
            return true;
        }
    } walker;
    pugi::xml_node(n).traverse(walker);
    return std::move(walker.out);
}

// A baseline-shift in px, up: sub and super as 0.2 and 0.4 em, as librsvg
// and resvg take them (fonts' own subscript offsets vary too much to agree).
double shift_px(const BaselineShift& bs, double font_size) {
    switch (bs.kind) {
    case BaselineShift::Kind::Sub:
        return -0.2 * font_size;
    case BaselineShift::Kind::Super:
        return 0.4 * font_size;
    case BaselineShift::Kind::Length:
        return bs.px;
    case BaselineShift::Kind::Baseline:
        break;
    }
    return 0;
}

// xml:space (SVG 1.1, 10.15): preserve or default, as white-space does;
// and the element's language, xml:lang or lang (SVG 2, 2.4.2).
void xml_space(const pugi::xml_node& e, StyleState& style) {
    const std::string_view space = e.attribute("xml:space").value();
    if (space == "preserve") style.text.preserve_spaces = true;
    if (space == "default") style.text.preserve_spaces = false;
    read_language(e, style.text);
}

bool is_collapsible(char32_t c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }

} // namespace

// What reading a text element carries from one element to the next.
struct TextReading {
    TextContent content;
    std::vector<PositionLists> stack;
    bool after_space = true; // a collapsible space here would be dropped
    std::size_t limit = 0;   // characters the document may still take
    bool over = false;
};

void Reader::text_characters(const pugi::xml_node& at, std::string_view utf8, std::uint32_t span,
                             TextReading& r) {
    const bool preserve = r.content.spans[span].style.text.preserve_spaces;
    for (char32_t c : decode_utf8(utf8)) {
        if (is_collapsible(c)) {
            c = ' ';
            if (!preserve && r.after_space) continue;
        }
        r.after_space = c == ' ' && !preserve;
        if (r.content.chars.size() >= r.limit) {
            if (!r.over)
                problem(at, "text past the limit of " +
                                std::to_string(options_.max_text_characters) +
                                " characters; not drawn");
            r.over = true;
            return;
        }
        const std::size_t i = r.content.chars.size();
        TextChar tc{c,
                    span,
                    value_at(r.stack, i, &PositionLists::x),
                    value_at(r.stack, i, &PositionLists::y),
                    value_at(r.stack, i, &PositionLists::dx).value_or(0),
                    value_at(r.stack, i, &PositionLists::dy).value_or(0),
                    rotate_at(r.stack, i)};
        r.content.chars.push_back(tc);
    }
}

// A span for element `e`, styled from its parent span; false when it is not
// displayed.
bool Reader::text_span(const pugi::xml_node& e, TextReading& r, std::uint32_t parent) {
    TextSpan span;
    span.node = e;
    const StyleState& up = r.content.spans[parent].style;
    span.style = up;
    ElementProps props;
    apply_declarations(e, up, span.style, nullptr, context(up));
    apply_declarations(e, up, span.style, &props, context(span.style));
    keep_own_values(span.style, props, e.name());
    if (props.display_none || !conditions_hold(e)) return false;
    xml_space(e, span.style);
    span.props = props.text;
    const TextSpan& p = r.content.spans[parent];
    span.baseline_shift =
        p.baseline_shift + shift_px(props.text.baseline_shift, span.style.font_size);
    span.decorations = p.decorations;
    if (props.text.decoration.any())
        span.decorations.push_back(std::uint32_t(r.content.spans.size()));
    span.text_path = p.text_path;
    span.parent = parent;
    r.content.spans.push_back(std::move(span));
    return true;
}

// The position lists and textLength of a text or tspan element.
void Reader::text_positions(const pugi::xml_node& e, TextReading& r) {
    const LengthContext ctx = context(r.content.spans.back().style);
    PositionLists lists;
    lists.start = r.content.chars.size();
    const auto list = [&](const char* attr, double percent_of, bool lengths) {
        const pugi::xml_attribute a = e.attribute(attr);
        if (!a) return std::vector<double>{};
        auto v = parse_list(a.value(), percent_of, ctx, lengths);
        if (!v)
            problem(e, std::string("attribute ") + attr + ": not a list of " +
                           (lengths ? "lengths" : "numbers") + "; ignored");
        return v.value_or(std::vector<double>{});
    };
    lists.x = list("x", vw_, true);
    lists.y = list("y", vh_, true);
    lists.dx = list("dx", vw_, true);
    lists.dy = list("dy", vh_, true);
    lists.rotate = list("rotate", 0, false);
    r.stack.push_back(std::move(lists));
}

void Reader::text_children(const pugi::xml_node& e, TextReading& r, int depth) {
    const std::uint32_t self = std::uint32_t(r.content.spans.size() - 1);
    for (const pugi::xml_node& c : e.children()) {
        if (r.over) return;
        if (c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) {
            text_characters(e, c.value(), self, r);
            continue;
        }
        if (c.type() != pugi::node_element) continue;
        count_element(c, depth);
        const std::string_view name = c.name();
        if (name == "tspan" || name == "a") {
            if (!text_span(c, r, self)) continue;
            if (name == "tspan") text_positions(c, r);
            const std::size_t begin = r.content.chars.size();
            text_children(c, r, depth + 1);
            if (name == "tspan") r.stack.pop_back();
            text_length(c, begin, r);
        } else if (name == "textPath" && r.content.spans[self].text_path < 0) {
            if (!text_span(c, r, self) || !text_path(c, r)) continue;
            text_children(c, r, depth + 1);
        } else if (name == "tref") {
            const char* href = href_of(c);
            const pugi::xml_node target = href[0] == '#' ? by_id(href + 1) : pugi::xml_node();
            if (!target) {
                problem(c, std::string("href '") + href + "' names no element; skipped");
                continue;
            }
            if (!text_span(c, r, self)) continue;
            text_characters(c, text_content(target), std::uint32_t(r.content.spans.size() - 1), r);
        }
    }
}

// textLength and lengthAdjust of `e`, whose characters start at `begin`.
void Reader::text_length(const pugi::xml_node& e, std::size_t begin, TextReading& r) {
    const pugi::xml_attribute a = e.attribute("textLength");
    if (!a) return;
    const auto len = parse_length(a.value(), vw_, context(r.content.spans.back().style));
    if (!len || *len < 0) return problem(e, "textLength: not a non-negative length; ignored");
    const bool glyphs = std::string_view(e.attribute("lengthAdjust").value()) == "spacingAndGlyphs";
    r.content.lengths.push_back({begin, r.content.chars.size(), *len, glyphs});
}

// A textPath's path; false (nothing drawn) when it names none.
bool Reader::text_path(const pugi::xml_node& e, TextReading& r) {
    TextSpan& span = r.content.spans.back();
    TextPathRef ref;
    const pugi::xml_node target = [&] {
        const char* href = href_of(e);
        return href[0] == '#' ? by_id(href + 1) : pugi::xml_node();
    }();
    const std::string_view kind = target.name();
    if (!target || !is_shape(kind)) {
        problem(e, "href names no path or shape; its text is not drawn");
        r.content.spans.pop_back();
        return false;
    }
    {
        const ScopedValue quiet(quiet_, true); // the shape's problems are told where it is drawn
        ref.path = geometry(target, kind, context(span.style));
        ref.path_length = path_length(target);
    }
    if (const pugi::xml_attribute t = target.attribute("transform")) {
        const TransformResult tr = parse_transform_list(t.value());
        if (tr.error.empty()) ref.path.transform(tr.transform);
    }
    const std::string_view offset = e.attribute("startOffset").value();
    if (!offset.empty() && offset.back() == '%') {
        if (const auto f = parse_number(offset.substr(0, offset.size() - 1)))
            ref.start_offset = *f / 100, ref.start_percent = true;
    } else if (!offset.empty()) {
        ref.start_offset = parse_length(offset, 0, context(span.style)).value_or(0);
    }
    ref.right_side = std::string_view(e.attribute("side").value()) == "right";
    span.text_path = int(r.content.paths.size());
    r.content.paths.push_back(std::move(ref));
    return true;
}

void Reader::text(const pugi::xml_node& n, const StyleState& style, const ElementProps& props,
                  const Affine& m, Group& out, int depth) {
    TextReading r;
    r.limit =
        options_.max_text_characters - std::min(text_characters_, options_.max_text_characters);
    TextSpan root;
    root.node = n;
    root.style = style;
    xml_space(n, root.style);
    root.props = props.text;
    root.baseline_shift = shift_px(props.text.baseline_shift, style.font_size);
    if (props.text.decoration.any()) root.decorations.push_back(0);
    r.content.spans.push_back(std::move(root));
    text_positions(n, r);
    text_children(n, r, depth + 1);
    text_length(n, 0, r);
    std::vector<TextChar>& chars = r.content.chars;
    while (!chars.empty() && chars.back().c == ' ' &&
           !r.content.spans[chars.back().span].style.text.preserve_spaces)
        chars.pop_back();
    text_characters_ += chars.size();
    if (chars.empty()) return;
    const TextLayout layout = layout_text(fonts(), r.content);
    if (std::any_of(layout.glyphs.begin(), layout.glyphs.end(),
                    [](const PlacedGlyph& g) { return !g.glyph.font; }))
        warn(n, "no font draws some of this text (" +
                    (text_libraries_error().empty()
                         ? std::string("none installed, or none that reads")
                         : "the text libraries did not load: " + text_libraries_error()) +
                    "); those characters are not drawn");
    draw_text(r.content, layout, m, props, out);
}

namespace {

// A decoration piece as a closed quadrilateral.
void add_piece(Path& path, const DecorationPiece& d) {
    const double y0 = d.y - d.thickness / 2, y1 = d.y + d.thickness / 2;
    path.move_to(d.transform * Point{0, y0});
    path.line_to(d.transform * Point{d.width, y0});
    path.line_to(d.transform * Point{d.width, y1});
    path.line_to(d.transform * Point{0, y1});
    path.close();
}

} // namespace

void Reader::draw_text(const TextContent& content, const TextLayout& layout, const Affine& m,
                       const ElementProps& props, Group& out) {
    std::vector<Path> glyphs(content.spans.size());
    for (const PlacedGlyph& g : layout.glyphs)
        append_glyph(glyphs[g.glyph.style], g.glyph, g.transform);
    // Decorations by owner and line: 0 underline, 1 overline, 2 line-through.
    std::vector<std::array<Path, 3>> lines(content.spans.size());
    for (const DecorationPiece& d : layout.decorations) add_piece(lines[d.owner][d.line], d);
    Rect box = Rect::empty();
    for (const Path& p : glyphs) box = box.united(p.bounds());
    for (const auto& l : lines)
        for (const Path& p : l) box = box.united(p.bounds());
    if (box.is_empty()) return;
    const Path box_path = rect_path(box.min().x, box.min().y, box.width(), box.height(), 0, 0);
    ElementProps own = props;
    own.opacity = 1; // the group around the text carries it
    const auto draw = [&](std::uint32_t span, Path path) {
        const TextSpan& s = content.spans[span];
        if (path.empty() || !s.style.visible) return;
        Shape shape = painted(s.node, std::move(path), s.style, m, own, &box_path);
        if (shape.fill) shape.fill->rule = FillRule::NonZero; // glyph contours may overlap
        out.children.push_back(Node{std::move(shape)});
    };
    for (int line : {0, 1})
        for (std::uint32_t s = 0; s < lines.size(); ++s) draw(s, std::move(lines[s][line]));
    for (std::uint32_t s = 0; s < glyphs.size(); ++s) draw(s, std::move(glyphs[s]));
    for (std::uint32_t s = 0; s < lines.size(); ++s) draw(s, std::move(lines[s][2]));
}

} // namespace casteljau::svg_detail
