// <pattern> paint servers (SVG 1.1, 13.3), resolved into scene Patterns.
//
// The tile is the rectangle x, y, width, height: in the painted element's
// user space (patternUnits userSpaceOnUse) or as fractions of its bounding
// box (objectBoundingBox, the initial value), then moved by
// patternTransform. Its content has its origin at the tile's top-left
// corner; with a viewBox, the viewBox is fitted into the tile
// (preserveAspectRatio) and patternContentUnits is ignored; otherwise
// patternContentUnits objectBoundingBox scales the content by the box's
// width and height. What the tile shows outside itself is clipped, and the
// tile repeats over the plane. Every attribute and the children are taken
// from the first pattern along the href chain that has them (13.3). A zero
// width or height, or an objectBoundingBox unit on an element whose box
// has no area, disables the paint: the element is painted as with none.
//
// The content is drawn by the renderer once per painted shape at the
// device resolution (render/renderer.h), so it is as exact as any shape.
// Patterns built without the painted element's box (userSpaceOnUse units
// throughout) are built once and shared.
#include "casteljau/svg/detail/href.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/transform_list.h"

namespace casteljau::svg_detail {

namespace {

bool has_element_children(const pugi::xml_node& n) {
    for (const pugi::xml_node& c : n.children())
        if (c.type() == pugi::node_element) return true;
    return false;
}

} // namespace

std::vector<pugi::xml_node> Reader::same_kind_chain(const pugi::xml_node& start) {
    const std::string kind = start.name();
    return href_chain(
        start, kind.c_str(), [&](const char* id) { return by_id(id); },
        [&](const pugi::xml_node& n) { return kind == n.name(); },
        [&](const pugi::xml_node& n, const std::string& what) { problem(n, what); });
}

bool Reader::units_of(const std::vector<pugi::xml_node>& chain, const char* name,
                      bool initial_obb) {
    const pugi::xml_attribute a = chain_attribute(chain, name);
    const std::string_view v = a.value();
    if (v == "objectBoundingBox") return true;
    if (v == "userSpaceOnUse") return false;
    if (!v.empty())
        problem(chain.front(), std::string(name) + ": '" + std::string(v) + "' is invalid");
    return initial_obb;
}

std::shared_ptr<const Pattern> Reader::pattern(const pugi::xml_node& pat, const Path& path,
                                               int depth, bool* boxless) {
    if (const auto it = patterns_.find(pat.internal_object()); it != patterns_.end())
        return it->second;
    const std::vector<pugi::xml_node> chain = same_kind_chain(pat);
    const bool tile_obb = units_of(chain, "patternUnits", true);
    const bool content_obb = units_of(chain, "patternContentUnits", false);
    std::optional<ViewBox> box;
    for (const pugi::xml_node& p : chain)
        if (p.attribute("viewBox")) {
            box = view_box(p);
            break;
        }
    const bool needs_bbox = tile_obb || (content_obb && !box);
    const Rect b = needs_bbox ? path.bounds() : Rect{0, 0, 1, 1};
    if (!(b.width() > 0 && b.height() > 0)) {
        if (boxless) *boxless = true;
        return nullptr;
    }
    ElementProps props;
    const StyleState style = style_of(pat, props);
    const LengthContext ctx = context(style);
    const auto at = [&](const char* name, double full) {
        for (const pugi::xml_node& p : chain)
            if (p.attribute(name)) return length(p, name, tile_obb ? 1 : full, ctx).value_or(0);
        return 0.0;
    };
    double x = at("x", vw_), y = at("y", vh_), w = at("width", vw_), h = at("height", vh_);
    if (tile_obb) {
        x = b.x0 + x * b.width(), y = b.y0 + y * b.height();
        w *= b.width(), h *= b.height();
    }
    if (!(w > 0 && h > 0) || (box && !(box->w > 0 && box->h > 0))) return nullptr;
    auto out = std::make_shared<Pattern>();
    out->width = w;
    out->height = h;
    Affine transform = Affine::identity();
    if (const pugi::xml_attribute t = chain_attribute(chain, "patternTransform")) {
        const TransformResult tr = parse_transform_list(t.value());
        if (tr.error.empty())
            transform = tr.transform;
        else
            problem(pat, "patternTransform: " + tr.error + "; ignored");
    }
    out->transform = transform * Affine::translate({x, y});
    pugi::xml_node content = pat;
    for (const pugi::xml_node& p : chain)
        if (has_element_children(p)) {
            content = p;
            break;
        }
    Affine content_map = Affine::identity();
    if (box) {
        pugi::xml_node par = content;
        for (const pugi::xml_node& p : chain)
            if (p.attribute("preserveAspectRatio")) {
                par = p;
                break;
            }
        content_map = view_map(par, *box, w, h);
    } else if (content_obb) {
        content_map = Affine::scale(b.width(), b.height());
    }
    ElementProps content_props;
    const StyleState content_style = style_of(content, content_props);
    const double saved_w = vw_, saved_h = vh_;
    if (box) vw_ = box->w, vh_ = box->h;
    instancing_.push_back(pat);
    walk(content, content_style, content_map, out->content, depth + 1);
    instancing_.pop_back();
    vw_ = saved_w, vh_ = saved_h;
    // Kept unless built quietly (fill_box's measure), whose problems were
    // not told: the walk that draws builds it again and tells them.
    if (!needs_bbox && !quiet_) patterns_.emplace(pat.internal_object(), out);
    return out;
}

} // namespace casteljau::svg_detail
