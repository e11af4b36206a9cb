// An element's own transform (CSS Transforms 1; SVG 2, 8.5):
//
//   M = T(origin) * transform(box) * T(-origin)
//
// in the parent's user space, where transform is the transform attribute or
// the CSS transform property, whichever the cascade takes (the attribute is
// the property's presentation attribute: a style sheet or a style attribute
// overrides it), origin is transform-origin in the reference box and box is
// that box, set by transform-box:
// - view-box (SVG's initial value): the nearest viewport, its corner at the
//   user space's origin; transform-origin's initial 0 0 is that origin;
// - fill-box (content-box on SVG elements): the element's object bounding
//   box in its own user space (before its transform);
// - stroke-box (border-box): the fill box with the stroke; taken as the fill
//   box outset by half the stroke's width (miters and caps aside).
// A translation's percentages are of the box too (translate(50%)).
//
// The fill box of a shape is its geometry's bounds. For a group, a use, an
// image, a nested svg or a text it is what the element draws: the element
// is walked once, quietly, untransformed, into a group that is measured
// and dropped. That box is kept per element (an element drawn in several
// places through <use> takes the first's), so nested fill-box groups cost
// a walk each, not one per ancestor; the walk's elements count against the
// element limit.
#include "casteljau/svg/detail/ascii.h"
#include "casteljau/svg/detail/reader_impl.h"

namespace casteljau::svg_detail {

// A transform declaration: the attribute's syntax from the attribute, CSS's
// from a style sheet or a style attribute (`from` is "" for the attribute).
void Reader::take_transform(const pugi::xml_node& n, std::string_view value, const char* from,
                            ElementProps& props, const LengthContext& ctx) {
    const bool css = *from != 0;
    TransformParse t =
        parse_transform(trim(value), css ? TransformSyntax::Css : TransformSyntax::Attribute, ctx);
    if (!t.error.empty())
        return problem(n, std::string(css ? from : "") + "transform: " + t.error + "; ignored");
    if (t.value.steps.empty())
        props.transform.reset();
    else
        props.transform = std::move(t.value);
}

// M (top of the file) for an element with a transform.
Affine Reader::own_transform(const pugi::xml_node& n, std::string_view name,
                             const StyleState& parent_style, const StyleState& style,
                             const ElementProps& props, int depth) {
    const LengthContext ctx = context(style);
    Rect box{0, 0, ctx.viewport_w, ctx.viewport_h};
    if (props.transform_box != TransformBox::ViewBox) {
        box = fill_box(n, name, parent_style, style, props.transform_box == TransformBox::StrokeBox,
                       depth);
        if (box.is_empty()) box = {};
    }
    const Point o =
        props.transform_origin.value_or(BoxPoint{}).at(box.x0, box.y0, box.width(), box.height());
    return Affine::translate(o.to_vec()) * props.transform->at(box.width(), box.height()) *
           Affine::translate(-o.to_vec());
}

// The fill box, or the stroke box (top of the file), in the element's own
// user space.
Rect Reader::fill_box(const pugi::xml_node& n, std::string_view name,
                      const StyleState& parent_style, const StyleState& style, bool stroke,
                      int depth) {
    Rect box;
    const ScopedValue quiet(quiet_, true); // its problems are told where it is drawn
    if (is_shape(name)) {
        box = geometry(n, name, context(style)).bounds();
    } else if (const auto kept = fill_boxes_.find(n.internal_object()); kept != fill_boxes_.end()) {
        box = kept->second;
    } else {
        Group drawn{1, {}};
        const ScopedValue measuring(measuring_, n);
        element(n, parent_style, Affine::identity(), drawn, depth);
        box = fill_boxes_[n.internal_object()] = user_bbox(drawn, Affine::identity());
    }
    if (stroke && style.stroke.kind != PaintSpec::Kind::None && !box.is_empty())
        box = box.inflated(0.5 * style.stroke_geometry.width);
    return box;
}

// The root svg's transform (SVG 2 allows one there), in the viewport's
// pixels, about its transform-origin, which there is 50% 50% of the
// viewport (browsers' UA style sheet makes it 0 0 only for an svg inside
// another element); transform-box is the viewport whatever it says.
Affine Reader::root_transform(const ElementProps& props, double width, double height) const {
    if (!props.transform) return Affine::identity();
    const Point o =
        props.transform_origin.value_or(BoxPoint{{}, {0.5, 0.5}}).at(0, 0, width, height);
    return Affine::translate(o.to_vec()) * props.transform->at(width, height) *
           Affine::translate(-o.to_vec());
}

} // namespace casteljau::svg_detail
