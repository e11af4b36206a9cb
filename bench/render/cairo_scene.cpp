#include "cairo_scene.h"

#include "casteljau/edit/bezier_spline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
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

/// An application's own copy of an image, made once: ARGB32 (premultiplied,
/// 8-bit) from the scene's float pixels, kept for the program's life. Keyed
/// by address: the benchmarks keep every scene, and so every image, alive
/// to the end, so no two images share one.
cairo_surface_t* image_surface(const RasterImage& im) {
    static std::map<const RasterImage*, cairo_surface_t*> made;
    if (cairo_surface_t* s = made[&im]) return s;
    cairo_surface_t* s = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, im.width, im.height);
    unsigned char* data = cairo_image_surface_get_data(s);
    const int stride = cairo_image_surface_get_stride(s);
    const auto byte = [](float v) {
        return std::uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
    };
    for (int y = 0; y < im.height; ++y)
        for (int x = 0; x < im.width; ++x) {
            const Premul& c = im.at(x, y);
            const std::uint32_t argb =
                byte(c.a) << 24 | byte(c.r) << 16 | byte(c.g) << 8 | byte(c.b);
            std::memcpy(data + std::ptrdiff_t(y) * stride + 4 * x, &argb, 4);
        }
    cairo_surface_mark_dirty(s);
    return made[&im] = s;
}

void draw_group(cairo_t* cr, const Group& g);

/// `to_user` maps the pattern's space to the current user space; Cairo's
/// pattern matrix maps the other way.
void set_pattern_matrix(cairo_pattern_t* pattern, const Affine& to_user) {
    const Affine m = to_user.inverse();
    const cairo_matrix_t matrix{m.a, m.b, m.c, m.d, m.e, m.f};
    cairo_pattern_set_matrix(pattern, &matrix);
}

/// A pattern's tile drawn by Cairo at the device resolution, as Casteljau
/// draws it, then repeated; an image stretched onto the tile.
cairo_pattern_t* make_tile(cairo_t* cr, const Pattern& p) {
    if (p.image) {
        cairo_pattern_t* pattern = cairo_pattern_create_for_surface(image_surface(*p.image));
        set_pattern_matrix(pattern, p.transform * Affine::scale(p.width / p.image->width,
                                                                p.height / p.image->height));
        // GOOD, as librsvg asks for images: bilinear where the image is
        // shrunk by less than 4/3, else a box over each pixel's footprint.
        cairo_pattern_set_filter(pattern, p.smooth ? CAIRO_FILTER_GOOD : CAIRO_FILTER_NEAREST);
        cairo_pattern_set_extend(pattern, p.repeat ? CAIRO_EXTEND_REPEAT : CAIRO_EXTEND_PAD);
        return pattern;
    }
    cairo_matrix_t user;
    cairo_get_matrix(cr, &user);
    const Affine to_device =
        Affine{user.xx, user.yx, user.xy, user.yy, user.x0, user.y0} * p.transform;
    const int w = std::max(1, int(std::ceil(std::hypot(to_device.a, to_device.b) * p.width)));
    const int h = std::max(1, int(std::ceil(std::hypot(to_device.c, to_device.d) * p.height)));
    cairo_surface_t* tile = cairo_image_surface_create(CAIRO_FORMAT_ARGB32, w, h);
    cairo_t* tc = cairo_create(tile);
    cairo_scale(tc, w / p.width, h / p.height);
    draw_group(tc, p.content);
    cairo_destroy(tc);
    cairo_pattern_t* pattern = cairo_pattern_create_for_surface(tile);
    cairo_surface_destroy(tile);
    set_pattern_matrix(pattern, p.transform * Affine::scale(p.width / w, p.height / h));
    cairo_pattern_set_filter(pattern, CAIRO_FILTER_BILINEAR);
    cairo_pattern_set_extend(pattern, CAIRO_EXTEND_REPEAT);
    return pattern;
}

cairo_pattern_t* make_gradient(const Gradient& g, const Path& path, float opacity) {
    cairo_pattern_t* pattern = g.kind == Gradient::Kind::Linear
                                   ? cairo_pattern_create_linear(g.p1.x, g.p1.y, g.p2.x, g.p2.y)
                                   : cairo_pattern_create_radial(g.focal.x, g.focal.y, 0,
                                                                 g.center.x, g.center.y, g.radius);
    for (const GradientStop& stop : g.stops)
        cairo_pattern_add_color_stop_rgba(pattern, stop.offset, stop.color.r, stop.color.g,
                                          stop.color.b, stop.color.a * opacity);
    cairo_pattern_set_extend(pattern, g.spread == Spread::Repeat    ? CAIRO_EXTEND_REPEAT
                                      : g.spread == Spread::Reflect ? CAIRO_EXTEND_REFLECT
                                                                    : CAIRO_EXTEND_PAD);
    Affine to_user = g.transform;
    if (g.object_bounding_box) {
        const Rect b = path.bounds();
        to_user = Affine::translate(b.min().to_vec()) * Affine::scale(b.width(), b.height()) *
                  g.transform;
    }
    set_pattern_matrix(pattern, to_user);
    return pattern;
}

/// The paint of a fill or a stroke as Cairo's source; returns the opacity
/// still to apply (a pattern's: Cairo's surface patterns carry none).
template <class Paint>
float set_source(cairo_t* cr, const Paint& paint, const Path& path, float opacity) {
    cairo_pattern_t* pattern = nullptr;
    if (paint.pattern && paint.pattern->width > 0 && paint.pattern->height > 0)
        pattern = make_tile(cr, *paint.pattern);
    else if (paint.gradient && !paint.gradient->stops.empty())
        pattern = make_gradient(*paint.gradient, path, opacity);
    if (!pattern) {
        const Rgba c = paint.color;
        cairo_set_source_rgba(cr, c.r, c.g, c.b, c.a * opacity);
        return 1;
    }
    cairo_set_source(cr, pattern);
    cairo_pattern_destroy(pattern);
    return paint.pattern ? opacity : 1;
}

/// cairo_fill_preserve or cairo_stroke_preserve with `alpha`: through a
/// group where it is below 1.
void draw_with_alpha(cairo_t* cr, void (*draw)(cairo_t*), float alpha) {
    if (alpha >= 1) return draw(cr);
    cairo_push_group(cr);
    draw(cr);
    cairo_pop_group_to_source(cr);
    cairo_paint_with_alpha(cr, alpha);
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
        draw_with_alpha(cr, cairo_fill_preserve,
                        set_source(cr, *s.fill, s.path, s.fill->opacity * s.opacity));
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
        draw_with_alpha(cr, cairo_stroke_preserve,
                        set_source(cr, *s.stroke, s.path, s.stroke->opacity * s.opacity));
    }
    cairo_new_path(cr);
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
