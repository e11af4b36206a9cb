// A shape's fill and stroke: paint references resolved to a color, a
// gradient or a pattern (SVG 2, 13.2: a reference to nothing, or a paint
// server that cannot apply, takes the fallback color or none), context-fill
// and context-stroke (13.3: the marked shape's or the use's paint, in that
// element's user space and box), objectBoundingBox units, and
// vector-effect: non-scaling-stroke (13.9).
#include "casteljau/svg/detail/reader_impl.h"

#include <algorithm>
#include <cstring>

namespace casteljau::svg_detail {

// A gradient mapped to user space units: objectBoundingBox units resolved
// against `box`, then the whole map composed with `m`.
std::shared_ptr<const Gradient> Reader::in_user_space(const Gradient& g, const Rect& box,
                                                      const Affine& m) {
    auto moved = std::make_shared<Gradient>(g);
    Affine to_user = Affine::identity();
    if (g.object_bounding_box)
        to_user = Affine::translate(box.min().to_vec()) * Affine::scale(box.width(), box.height());
    moved->transform = m * to_user * g.transform;
    moved->object_bounding_box = false;
    return moved;
}

Shape Reader::painted(const pugi::xml_node& n, Path path, const StyleState& style, const Affine& m,
                      const ElementProps& props, const Path* box) {
    Shape s;
    s.path = std::move(path);
    s.transform = m;
    s.opacity = props.opacity;
    s.source_line = line_of(offset_of(n));
    s.stroke_first = style.paint_order[1] < style.paint_order[0];
    s.antialias = style.antialias;
    if (clip_mode_) { // a clip path's shape: an opaque fill with its clip-rule
        s.fill = Fill{{0, 0, 0, 1}, nullptr, 1, style.clip_rule, nullptr};
        return s;
    }
    // objectBoundingBox units against `box` when given (in_box), else the
    // renderer takes the shape's own path.
    const Path& of = box ? *box : s.path;
    const auto resolved = [&](const PaintSpec& spec) {
        std::optional<ResolvedPaint> p = paint(n, spec, style, of, m);
        return box ? in_box(std::move(p), box->bounds()) : p;
    };
    if (const auto p = resolved(style.fill))
        s.fill = Fill{p->color, p->gradient, style.fill_opacity, style.fill_rule, p->pattern};
    if (const auto p = resolved(style.stroke); p && style.stroke_geometry.width > 0)
        s.stroke =
            Stroke{p->color, p->gradient, style.stroke_opacity, style.stroke_geometry, p->pattern};
    if (s.stroke && !s.stroke->geometry.dashes.empty()) dashes_in_path_length(n, s);
    if (props.non_scaling_stroke && s.stroke) to_host_space(s);
    return s;
}

// vector-effect: non-scaling-stroke (SVG 2, 13.9): the stroke is drawn in
// the host coordinate space, the scene's device space, so its width and
// dashes are in scene pixels whatever the transforms. The path is mapped
// into that space and the shape's transform becomes the identity; each
// gradient and pattern is remapped to stay where it was (to userSpaceOnUse,
// composing the old map and, for objectBoundingBox units, the user-space box).
void Reader::to_host_space(Shape& s) {
    const Affine m = s.transform;
    const Rect box = s.path.bounds();
    const auto remap = [&](std::shared_ptr<const Gradient>& g) {
        if (g) g = in_user_space(*g, box, m);
    };
    if (s.fill) remap(s.fill->gradient);
    remap(s.stroke->gradient);
    const auto remap_pattern = [&](std::shared_ptr<const Pattern>& p) {
        if (!p) return;
        auto moved = std::make_shared<Pattern>(*p); // already resolved to the user-space box
        moved->transform = m * p->transform;
        p = std::move(moved);
    };
    if (s.fill) remap_pattern(s.fill->pattern);
    remap_pattern(s.stroke->pattern);
    s.path.transform(m);
    s.transform = Affine::identity();
}

std::optional<Reader::ResolvedPaint> Reader::in_box(std::optional<ResolvedPaint> p,
                                                    const Rect& box) {
    if (p && p->gradient && p->gradient->object_bounding_box)
        p->gradient = in_user_space(*p->gradient, box, Affine::identity());
    return p;
}

std::optional<Reader::ResolvedPaint> Reader::paint(const pugi::xml_node& n, const PaintSpec& spec,
                                                   const StyleState& style, const Path& path,
                                                   const Affine& m) {
    if (spec.kind == PaintSpec::Kind::ContextFill || spec.kind == PaintSpec::Kind::ContextStroke) {
        // Outside a marker or a use there is no context element: none.
        if (context_.empty()) return std::nullopt;
        const ContextPaints& c = context_.back();
        std::optional<ResolvedPaint> p =
            spec.kind == PaintSpec::Kind::ContextFill ? c.fill : c.stroke;
        if (!p || (!p->gradient && !p->pattern)) return p;
        // The context element's space seen from this element's: a gradient
        // or pattern stays where the context element has it, whatever
        // transforms lie between (WPT's paint-context-004 and -008).
        if (m.determinant() == 0) return std::nullopt; // nothing is drawn
        const Affine to_here = m.inverse() * c.space;
        if (p->gradient) {
            auto g = std::make_shared<Gradient>(*p->gradient);
            g->transform = to_here * g->transform;
            p->gradient = std::move(g);
        }
        if (p->pattern) {
            auto q = std::make_shared<Pattern>(*p->pattern);
            q->transform = to_here * q->transform;
            p->pattern = std::move(q);
        }
        return p;
    }
    // objectBoundingBox units on a box without width or height (a
    // horizontal or vertical line) cannot be applied (SVG 2, 14.2): as for a
    // reference to nothing, the fallback is painted, or none, as browsers
    // and librsvg do (the renderer would draw nothing).
    if (spec.from_url) {
        if (const pugi::xml_node p = by_id(spec.url); p && std::strcmp(p.name(), "pattern") == 0) {
            if (std::find(instancing_.begin(), instancing_.end(), p) != instancing_.end()) {
                problem(n, "pattern #" + spec.url + " paints its own content; none is used");
                return std::nullopt;
            }
            bool boxless = false;
            if (auto pattern = this->pattern(p, path, depth_, &boxless))
                return ResolvedPaint{{}, nullptr, std::move(pattern)};
            if (!boxless) return std::nullopt; // disabled: it paints nothing, with no fallback
        } else {
            const svg_detail::GradientRef g = gradients_->resolve(spec.url);
            // A quiet walk (fill_box's measure) leaves the gradient's problems
            // and warning to the walk that draws, which tells them once.
            if (!quiet_) {
                for (const svg_detail::GradientProblem& gp : gradients_->take_problems())
                    problem(gp.where, gp.message);
                if (!g.warning.empty() && warned_.insert(g.warning).second)
                    warn(g.where ? g.where : n, g.warning);
            }
            const auto flat = [&] {
                const Rect b = path.bounds();
                return !(b.width() > 0 && b.height() > 0);
            };
            if (g.paints_none) return std::nullopt;
            if (g.gradient && !(g.gradient->object_bounding_box && flat()))
                return ResolvedPaint{{}, g.gradient, nullptr};
        }
    }
    if (const auto c = resolve_paint(spec, style)) return ResolvedPaint{*c, nullptr, nullptr};
    return std::nullopt;
}

} // namespace casteljau::svg_detail
