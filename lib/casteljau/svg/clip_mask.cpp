// clip-path, mask, mix-blend-mode and isolation, resolved at read time into
// the group's fields of the render tree (scene/scene.h).
//
// A clipPath (CSS Masking 1, 6.1; SVG 1.1, 14.3.5) becomes an alpha mask
// whose content is its children as opaque fills: shapes, and uses that
// reference shapes directly (other children are invalid and ignored), each
// filled with its clip-rule, never stroked, with no markers and no opacity;
// a child's own clip-path clips that child. clipPathUnits objectBoundingBox
// maps the unit square onto the referencing element's bounding box. A
// clip-path on the clipPath clips the clip path itself.
//
// A mask (CSS Masking 1, 7.2; SVG 1.1, 14.4) becomes a luminance mask (or an
// alpha mask, mask-type: alpha; in linear light with color-interpolation:
// linearRGB) of its children drawn normally, clipped to the mask region
// x, y, width, height (maskUnits, by default objectBoundingBox and
// -10%, -10%, 120%, 120%); maskContentUnits maps the children. A mask on
// the mask masks its content. An objectBoundingBox unit on an element
// whose box has no area makes the clip or mask empty: nothing is drawn.
//
// A basic shape (circle(), inset(), ...; svg/basic_shape.h) or a geometry
// box as clip-path becomes an alpha mask of that one outline, in the
// element's user space, its reference box taken from what the element draws.
//
// A reference to no such element, or to one of the wrong kind, is a problem
// and is ignored (the element is drawn unclipped, as librsvg and Chrome
// do); a reference back to a clip path or mask being resolved (a cycle) is
// a problem, and the element is not drawn.
#include "casteljau/svg/basic_shape.h"
#include "casteljau/svg/detail/reader_impl.h"
#include "casteljau/svg/shapes.h"
#include "casteljau/svg/transform_list.h"

#include <cmath>

namespace casteljau::svg_detail {

namespace {

// A shape's box in the coordinates `to_user` maps its device space to.
Rect shape_box(const Shape& s, const Affine& to_user) {
    Path p = s.path;
    p.transform(to_user * s.transform);
    return p.bounds();
}

} // namespace

Rect Reader::user_bbox(const Group& g, const Affine& to_user, bool strokes) {
    Rect r = Rect::empty();
    for (const Node& n : g.children) {
        if (const Shape* s = std::get_if<Shape>(&n.item)) {
            Rect b = shape_box(*s, to_user);
            // Half the width on every side: the stroke box without its
            // miters and caps (CSS Masking 1's stroke-box, approximated).
            if (strokes && s->stroke && !b.is_empty())
                b = b.inflated(0.5 * s->stroke->geometry.width *
                               (to_user * s->transform).max_scale());
            r = r.united(b);
        } else {
            r = r.united(user_bbox(std::get<Group>(n.item), to_user, strokes));
        }
    }
    return r;
}

// Whether everything `g` draws, strokes included (their widest miter),
// lies within r in the coordinates `to_r` maps device space to.
bool Reader::fits(const Group& g, const Rect& r, const Affine& to_r) {
    for (const Node& n : g.children) {
        if (const Group* child = std::get_if<Group>(&n.item)) {
            if (!fits(*child, r, to_r)) return false;
            continue;
        }
        const Shape& s = std::get<Shape>(n.item);
        Rect b = shape_box(s, to_r);
        if (s.stroke) {
            const StrokeGeometry& sg = s.stroke->geometry;
            b = b.inflated(0.5 * sg.width * std::max(sg.miter_limit, std::sqrt(2.0)) *
                           (to_r * s.transform).max_scale());
        }
        if (!(b.x0 >= r.x0 && b.y0 >= r.y0 && b.x1 <= r.x1 && b.y1 <= r.y1)) return false;
    }
    return true;
}

// The clip to a viewport, none when the content lies wholly inside: that
// is not only less work, it keeps the content's own antialiased edges where
// they meet the viewport's (a rectangle filling a marker's viewport would
// otherwise have its edge coverage squared by the clip's).
std::shared_ptr<const Mask> Reader::viewport_clip(const Group& content, const Rect& r,
                                                  const Affine& m) {
    const double det = m.determinant();
    if (det != 0 && std::isfinite(det) && fits(content, r, m.inverse())) return nullptr;
    return rect_clip(r, m);
}

std::shared_ptr<const Mask> Reader::rect_clip(const Rect& r, const Affine& m) {
    return path_clip(r.width() > 0 && r.height() > 0
                         ? rect_path(r.x0, r.y0, r.width(), r.height(), 0, 0)
                         : Path{},
                     m, FillRule::NonZero);
}

std::shared_ptr<const Mask> Reader::path_clip(Path p, const Affine& m, FillRule rule) {
    auto clip = std::make_shared<Mask>();
    if (!p.empty()) {
        Shape s;
        s.path = std::move(p);
        s.transform = m;
        s.fill = Fill{{0, 0, 0, 1}, nullptr, 1, rule, nullptr};
        clip->content.children.push_back(Node{std::move(s)});
    }
    return clip;
}

// A basic shape's clip (top of the file) for the element drawing g.
std::shared_ptr<const Mask> Reader::shape_clip(const BasicShape& s, const Affine& m, const Group& g,
                                               const BoxOf& bbox) {
    const Rect box = s.box == ShapeBox::View   ? Rect{0, 0, vw_, vh_}
                     : s.box == ShapeBox::Fill ? bbox()
                                               : user_bbox(g, m.inverse(), true);
    return path_clip(box.is_empty() ? Path{} : shape_path(s, box), m, s.fill_rule);
}

// The clip path or mask that `id` names ("" for none), for an element whose
// user space `m` maps to device space: null when the reference names no
// element of that kind (ignored), an empty mask (nothing is drawn) when it
// names one being resolved (a cycle).
std::shared_ptr<const Mask> Reader::effect(const pugi::xml_node& n, const std::string& id,
                                           bool is_clip, const Affine& m, const BoxOf& bbox,
                                           int depth) {
    if (id.empty()) return nullptr;
    const char* kind = is_clip ? "clipPath" : "mask";
    const pugi::xml_node t = by_id(id);
    if (!t || std::strcmp(t.name(), kind) != 0) {
        problem(n, "url(#" + id + ") names no <" + kind + ">; ignored");
        return nullptr;
    }
    if (std::find(instancing_.begin(), instancing_.end(), t) != instancing_.end()) {
        problem(n, std::string("<") + kind + "> #" + id +
                       " refers back to itself; the element is not drawn");
        return std::make_shared<const Mask>();
    }
    return is_clip ? clip_path(t, m, bbox, depth) : mask(t, m, bbox, depth);
}

void Reader::apply_effects(const pugi::xml_node& n, const ElementProps& props, const Affine& m,
                           Group& g, int depth, const Group* boxed) {
    g.blend = props.blend;
    g.isolate = props.isolate;
    const Affine to_user = m.inverse();
    std::optional<Rect> box; // computed once, if a unit needs it
    const auto bbox = [&]() -> const Rect& {
        if (!box) box = user_bbox(boxed ? *boxed : g, to_user);
        return *box;
    };
    g.clip = props.clip_shape ? shape_clip(*props.clip_shape, m, boxed ? *boxed : g, bbox)
                              : effect(n, props.clip_path, true, m, bbox, depth);
    g.mask = effect(n, props.mask, false, m, bbox, depth);
    if (!props.filter.empty() && !apply_filters(n, props, m, g, bbox, depth))
        g = Group{}; // not drawn: nothing left that needs a layer, dropped by add_group
}

std::shared_ptr<const Mask> Reader::clip_path(const pugi::xml_node& cp, const Affine& m,
                                              const BoxOf& bbox, int depth) {
    auto out = std::make_shared<Mask>();
    ElementProps props;
    const StyleState style = style_of(cp, props);
    Affine cm = m;
    if (const pugi::xml_attribute t = cp.attribute("transform")) {
        const TransformResult tr = parse_transform_list(t.value());
        if (tr.error.empty())
            cm = cm * tr.transform;
        else
            problem(cp, "transform: " + tr.error + "; ignored");
    }
    const std::string_view units = cp.attribute("clipPathUnits").value();
    if (units == "objectBoundingBox") {
        const Rect& b = bbox();
        if (!(b.width() > 0 && b.height() > 0)) return out;
        cm = cm * Affine::translate(b.min().to_vec()) * Affine::scale(b.width(), b.height());
    } else if (!units.empty() && units != "userSpaceOnUse") {
        problem(cp, "clipPathUnits: '" + std::string(units) + "' is invalid; userSpaceOnUse");
    }
    instancing_.push_back(cp);
    const bool was_clip = clip_mode_;
    clip_mode_ = true;
    walk(cp, style, cm, out->content, depth + 1);
    clip_mode_ = was_clip;
    // Its own clip-path, in the referencing element's user space.
    out->content.clip = effect(cp, props.clip_path, true, m, bbox, depth + 1);
    instancing_.pop_back();
    return out;
}

std::shared_ptr<const Mask> Reader::mask(const pugi::xml_node& mk, const Affine& m,
                                         const BoxOf& bbox, int depth) {
    auto out = std::make_shared<Mask>();
    ElementProps props;
    const StyleState style = style_of(mk, props);
    out->kind = props.mask_alpha   ? MaskKind::Alpha
                : style.linear_rgb ? MaskKind::LuminanceLinear
                                   : MaskKind::Luminance;
    const auto units = [&](const char* attr, const char* initial) {
        const std::string_view v = mk.attribute(attr).value();
        if (v.empty()) return std::string_view(initial) == "objectBoundingBox";
        if (v == "objectBoundingBox" || v == "userSpaceOnUse") return v == "objectBoundingBox";
        problem(mk, std::string(attr) + ": '" + std::string(v) + "' is invalid; " + initial);
        return std::string_view(initial) == "objectBoundingBox";
    };
    const bool region_obb = units("maskUnits", "objectBoundingBox");
    const bool content_obb = units("maskContentUnits", "userSpaceOnUse");
    Rect b{0, 0, 1, 1};
    if (region_obb || content_obb) {
        b = bbox();
        if (!(b.width() > 0 && b.height() > 0)) return out;
    }
    // The region: fractions of the box, or lengths of the viewport.
    const LengthContext ctx = context(style);
    const auto at = [&](const char* attr, double initial, double full) {
        return length(mk, attr, region_obb ? 1 : full, ctx)
            .value_or(region_obb ? initial : initial * full);
    };
    double x = at("x", -0.1, vw_), y = at("y", -0.1, vh_);
    double w = at("width", 1.2, vw_), h = at("height", 1.2, vh_);
    if (region_obb) {
        x = b.x0 + x * b.width(), y = b.y0 + y * b.height();
        w *= b.width(), h *= b.height();
    }
    if (!(w > 0 && h > 0)) return out;
    const Affine cm =
        content_obb ? m * Affine::translate(b.min().to_vec()) * Affine::scale(b.width(), b.height())
                    : m;
    instancing_.push_back(mk);
    walk(mk, style, cm, out->content, depth + 1);
    out->content.clip = rect_clip({x, y, x + w, y + h}, m);
    out->content.mask = effect(mk, props.mask, false, m, bbox, depth + 1);
    instancing_.pop_back();
    return out;
}

} // namespace casteljau::svg_detail
