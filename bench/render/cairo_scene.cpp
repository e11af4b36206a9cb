#include "cairo_scene.h"

#include "casteljau/edit/bezier_spline.h"

#include <variant>

namespace casteljau::bench {

namespace {

void add_path(cairo_t* cr, const Path& path) {
    cairo_new_path(cr);
    for (const Subpath& sp : path.subpaths()) {
        cairo_move_to(cr, sp.start.x, sp.start.y);
        for (const Segment& s : sp.segments) {
            if (const auto* l = std::get_if<Line>(&s)) {
                cairo_line_to(cr, l->p[1].x, l->p[1].y);
            } else if (const auto* q = std::get_if<QuadBez>(&s)) {
                const CubicBez c = q->elevate();
                cairo_curve_to(cr, c.p[1].x, c.p[1].y, c.p[2].x, c.p[2].y, c.p[3].x, c.p[3].y);
            } else if (const auto* c = std::get_if<CubicBez>(&s)) {
                cairo_curve_to(cr, c->p[1].x, c->p[1].y, c->p[2].x, c->p[2].y, c->p[3].x,
                               c->p[3].y);
            } else {
                Subpath one{segment_start(s), {s}, false};
                const BezierSpline spline = BezierSpline::from_subpath(one);
                for (std::size_t i = 0; i < spline.segment_count(); ++i) {
                    const CubicBez k = spline.segment(i);
                    cairo_curve_to(cr, k.p[1].x, k.p[1].y, k.p[2].x, k.p[2].y, k.p[3].x, k.p[3].y);
                }
            }
        }
        if (sp.closed) cairo_close_path(cr);
    }
}

void set_source(cairo_t* cr, Rgba color, const Gradient* gradient, float opacity) {
    if (gradient && !gradient->stops.empty()) color = gradient->stops.front().color;
    cairo_set_source_rgba(cr, color.r, color.g, color.b, color.a * opacity);
}

void draw_shape(cairo_t* cr, const Shape& s) {
    const Affine& m = s.transform;
    const cairo_matrix_t matrix{m.a, m.b, m.c, m.d, m.e, m.f};
    cairo_save(cr);
    cairo_transform(cr, &matrix); // after the caller's view scale
    add_path(cr, s.path);
    if (s.fill) {
        cairo_set_fill_rule(cr, s.fill->rule == FillRule::EvenOdd ? CAIRO_FILL_RULE_EVEN_ODD
                                                                  : CAIRO_FILL_RULE_WINDING);
        set_source(cr, s.fill->color, s.fill->gradient.get(), s.fill->opacity * s.opacity);
        if (s.stroke)
            cairo_fill_preserve(cr);
        else
            cairo_fill(cr);
    }
    if (s.stroke) {
        const StrokeGeometry& g = s.stroke->geometry;
        cairo_set_line_width(cr, g.width);
        cairo_set_line_join(cr, g.join == LineJoin::Round   ? CAIRO_LINE_JOIN_ROUND
                                : g.join == LineJoin::Bevel ? CAIRO_LINE_JOIN_BEVEL
                                                            : CAIRO_LINE_JOIN_MITER);
        cairo_set_line_cap(cr, g.cap == LineCap::Round    ? CAIRO_LINE_CAP_ROUND
                               : g.cap == LineCap::Square ? CAIRO_LINE_CAP_SQUARE
                                                          : CAIRO_LINE_CAP_BUTT);
        cairo_set_miter_limit(cr, g.miter_limit);
        cairo_set_dash(cr, g.dashes.data(), int(g.dashes.size()), g.dash_offset);
        set_source(cr, s.stroke->color, s.stroke->gradient.get(), s.stroke->opacity * s.opacity);
        cairo_stroke(cr);
    }
    cairo_restore(cr);
}

void draw_group(cairo_t* cr, const Group& g) {
    for (const Node& n : g.children) {
        if (const Shape* s = std::get_if<Shape>(&n.item)) {
            draw_shape(cr, *s);
            continue;
        }
        const Group& child = std::get<Group>(n.item);
        if (child.opacity >= 1.0f) {
            draw_group(cr, child);
        } else {
            cairo_push_group(cr);
            draw_group(cr, child);
            cairo_pop_group_to_source(cr);
            cairo_paint_with_alpha(cr, child.opacity);
        }
    }
}

} // namespace

void draw_with_cairo(cairo_t* cr, const Scene& scene) { draw_group(cr, scene.root); }

} // namespace casteljau::bench
