#include "casteljau/render/drawing.h"

#include "casteljau/geom/pixel_index.h"
#include "casteljau/hit/rect_hit.h"
#include "casteljau/hit/stroke_hit.h"
#include "casteljau/hit/winding.h"

#include <algorithm>
#include <cstring>

namespace casteljau {

Paint Paint::linear(Point from, Point to, std::vector<GradientStop> stops) {
    auto g = std::make_shared<Gradient>();
    g->p1 = from;
    g->p2 = to;
    g->object_bounding_box = false;
    g->stops = std::move(stops);
    return {{}, std::move(g), 1};
}

Paint Paint::image(std::shared_ptr<const RasterImage> image, const Rect& where, bool smooth) {
    auto p = std::make_shared<Pattern>();
    p->width = where.width();
    p->height = where.height();
    p->transform = Affine::translate(where.min().to_vec());
    p->image = std::move(image);
    p->repeat = false;
    p->smooth = smooth;
    return {{}, nullptr, 1, std::move(p)};
}

Paint Paint::tiled(Pattern pattern) {
    return {{}, nullptr, 1, std::make_shared<const Pattern>(std::move(pattern))};
}

std::shared_ptr<const Mask> clip_of(const Path& path, const Affine& transform, FillRule rule) {
    auto m = std::make_shared<Mask>();
    Shape s{path, transform, Fill{{0, 0, 0, 1}, nullptr, 1, rule}, {}};
    m->content.children.push_back(Node{std::move(s)});
    return m;
}

namespace {

std::shared_ptr<const Filter> one_primitive(FilterOp op, const Rect& region, const Affine& m) {
    auto f = std::make_shared<Filter>();
    f->transform = m;
    f->graph.region = region;
    // sRGB, as the CSS functions are: what a drawing application shows.
    f->graph.primitives.push_back({std::move(op), {filter_input::kSourceGraphic}, region, false});
    return f;
}

} // namespace

std::shared_ptr<const Filter> blur_filter(double sigma, const Rect& region,
                                          const Affine& transform) {
    return one_primitive(GaussianBlur{sigma, sigma, EdgeMode::None}, region, transform);
}

std::shared_ptr<const Filter> drop_shadow_filter(Vec2 offset, double sigma, Rgba color,
                                                 const Rect& region, const Affine& transform) {
    return one_primitive(DropShadow{sigma, sigma, offset.x, offset.y, color}, region, transform);
}

Drawing::Drawing(int width, int height) : width_(width), height_(height) {
    scene_.width = width;
    scene_.height = height;
}

Drawing::ShapeId Drawing::fill(const Path& path, const Paint& paint, const Affine& transform,
                               FillRule rule) {
    Shape s{
        path, transform, Fill{paint.color, paint.gradient, paint.opacity, rule, paint.pattern}, {}};
    return add(std::move(s));
}

Drawing::ShapeId Drawing::text(FontDatabase& fonts, std::string_view utf8, const TextStyle& style,
                               Point origin, const Paint& paint, const Affine& transform) {
    return fill(text_to_path(fonts, utf8, style, origin), paint, transform, FillRule::NonZero);
}

Drawing::ShapeId Drawing::stroke(const Path& path, const Paint& paint,
                                 const StrokeGeometry& geometry, const Affine& transform) {
    Shape s{path,
            transform,
            {},
            Stroke{paint.color, paint.gradient, paint.opacity, geometry, paint.pattern}};
    return add(std::move(s));
}

Drawing::ShapeId Drawing::image(std::shared_ptr<const RasterImage> image, const Rect& where,
                                const Affine& transform, bool smooth) {
    Path rect;
    rect.move_to(where.min());
    rect.line_to({where.x1, where.y0});
    rect.line_to(where.max());
    rect.line_to({where.x0, where.y1});
    rect.close();
    return fill(rect, Paint::image(std::move(image), where, smooth), transform);
}

Drawing::ShapeId Drawing::add(Group group) {
    scene_.root.children.push_back(Node{std::move(group)});
    boxes_.push_back(Renderer::node_reach_box(scene_.root.children.back(), Affine::identity()));
    return boxes_.size() - 1;
}

Drawing::ShapeId Drawing::add(Shape shape) {
    boxes_.push_back(Renderer::reach_box(shape, Affine::identity()));
    scene_.root.children.push_back(Node{std::move(shape)});
    return boxes_.size() - 1;
}

const Shape& Drawing::shape(ShapeId id) const {
    return std::get<Shape>(scene_.root.children[id].item);
}

PixelRect Drawing::replace(ShapeId id, Node node) {
    const PixelRect before = damage(id);
    boxes_[id] = Renderer::node_reach_box(node, Affine::identity());
    scene_.root.children[id] = std::move(node);
    return united(before, damage(id));
}

PixelRect Drawing::damage(ShapeId id) const {
    const Rect& b = boxes_[id];
    if (b.is_empty()) return {};
    // Pixel [x, x + 1) can be touched when the box overlaps it.
    const PixelRect r{floor_in(b.x0, 0, width_), floor_in(b.y0, 0, height_),
                      ceil_in(b.x1, 0, width_), ceil_in(b.y1, 0, height_)};
    return r.width() > 0 && r.height() > 0 ? r : PixelRect{};
}

namespace {

// How closely hit tests follow a stroke's outline (caps, joins and dashes as
// drawn): a fiftieth of shape_at's default reach. (shape_at asked for 0.001
// user units, 10x finer than the selection's test: about 3x the outline's
// segments and time, for answers that differ only within 0.01 px of the reach.)
constexpr double kStrokeHitTolerancePx = 0.01;

// The outline's tolerance in the shape's own units, or nothing for a
// transform that draws nothing (a scale of 0, or one whose squares underflow:
// an infinite tolerance, on which the stroker would never end).
std::optional<double> stroke_hit_tolerance(const Shape& s) {
    const double tol = kStrokeHitTolerancePx / s.transform.max_scale();
    if (!(tol > 0) || !std::isfinite(tol)) return std::nullopt;
    return tol;
}

// Whether the stroke's outline meets the device rectangle `r`.
bool stroke_intersects_rect(const Shape& s, const Rect& r) {
    const std::optional<double> tol = stroke_hit_tolerance(s);
    if (!tol) return false;
    Path device = stroke_outline_path(s.path, s.stroke->geometry, *tol);
    device.transform(s.transform);
    return fill_intersects_rect(device, r, FillRule::NonZero);
}

} // namespace

std::optional<Drawing::ShapeId> Drawing::shape_at(Point p, double tolerance) const {
    for (std::size_t i = boxes_.size(); i-- > 0;) {
        if (!boxes_[i].inflated(tolerance).contains(p)) continue;
        const Shape* shape = std::get_if<Shape>(&node(i).item);
        if (!shape) continue;
        const Shape& s = *shape;
        // Hit-tests run in the shape's own coordinates, where its curves are
        // exact; the pixel tolerance becomes user units at the largest stretch.
        const Affine to_user = s.transform.inverse();
        const Point q = to_user * p;
        if (s.fill && fill_contains(s.path, q, s.fill->rule)) return i;
        if (s.stroke)
            if (const std::optional<double> tol = stroke_hit_tolerance(s);
                tol && stroke_distance(s.path, s.stroke->geometry, q, *tol) <=
                           tolerance * to_user.max_scale())
                return i;
    }
    return std::nullopt;
}

std::vector<Drawing::ShapeId> Drawing::shapes_in(const Rect& r) const {
    std::vector<ShapeId> hits;
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
        if (!boxes_[i].intersects(r)) continue;
        const Shape* shape = std::get_if<Shape>(&node(i).item);
        if (!shape) continue;
        const Shape& s = *shape;
        Path device = s.path; // affine maps are exact on the control points
        device.transform(s.transform);
        if ((s.fill && fill_intersects_rect(device, r, s.fill->rule)) ||
            (s.stroke && stroke_intersects_rect(s, r)))
            hits.push_back(i);
    }
    return hits;
}

template <class Pixel>
RenderStats Drawing::render(BasicCanvas<Pixel>& canvas, Premul background,
                            const RenderOptions& options, int threads) {
    return bands_.render(scene_, Affine::identity(), canvas, options, background, threads);
}

template <class Pixel>
RenderStats Drawing::render_region(BasicCanvas<Pixel>& canvas, const PixelRect& dirty,
                                   Premul background, const RenderOptions& options) {
    const PixelRect r{std::max(dirty.x0, 0), std::max(dirty.y0, 0), std::min(dirty.x1, width_),
                      std::min(dirty.y1, height_)};
    if (r.width() <= 0 || r.height() <= 0) return {};
    crossing_.clear();
    for (std::size_t i = 0; i < boxes_.size(); ++i) {
        const Rect& b = boxes_[i];
        if (b.x1 > r.x0 && b.x0 < r.x1 && b.y1 > r.y0 && b.y0 < r.y1)
            crossing_.push_back(&scene_.root.children[i]);
    }
    BasicCanvas<Pixel>& tile = std::get<BasicCanvas<Pixel>>(tiles_);
    tile.reset(r.width(), r.height(), r.x0, r.y0, background);
    const RenderStats stats = renderer_.render_nodes(crossing_, Affine::identity(), tile, options,
                                                     {0, 0, width_, height_});
    renderer_.release_reserved(); // a redraw is a frame: an idle drawing keeps no share
    for (int y = r.y0; y < r.y1; ++y)
        std::memcpy(static_cast<void*>(canvas.row(y) + r.x0), tile.row(y - r.y0),
                    std::size_t(r.width()) * sizeof(Pixel));
    return stats;
}

template RenderStats Drawing::render(Canvas&, Premul, const RenderOptions&, int);
template RenderStats Drawing::render(Canvas8&, Premul, const RenderOptions&, int);
template RenderStats Drawing::render_region(Canvas&, const PixelRect&, Premul,
                                            const RenderOptions&);
template RenderStats Drawing::render_region(Canvas8&, const PixelRect&, Premul,
                                            const RenderOptions&);

PixelRect united(const PixelRect& a, const PixelRect& b) {
    if (a.width() <= 0 || a.height() <= 0) return b;
    if (b.width() <= 0 || b.height() <= 0) return a;
    return {std::min(a.x0, b.x0), std::min(a.y0, b.y0), std::max(a.x1, b.x1), std::max(a.y1, b.y1)};
}

} // namespace casteljau
