#include "casteljau/render/renderer.h"

#include "casteljau/filter/run.h"
#include "casteljau/geom/pixel_index.h"
#include "casteljau/paint/blend.h"
#include "casteljau/paint/mask.h"
#include "casteljau/raster/path_edges.h"
#include "casteljau/stroke/stroker.h"

#include <algorithm>
#include <chrono>
#include <cmath>

namespace casteljau {

namespace {

// Ends a scope that may have entered the memory gate (memory_gate.h: a
// reservation the budget refused enters it): if it did, frees what was
// grown through the gate and leaves, so that what threads hold outside the
// gate stays within the budget and none stays in it past a stroke strip or
// a filter chain. Nested scopes (a pattern tile's stroke inside a stroke's
// paint) each leave only the level they entered.
template <class Release>
class LeaveGate {
  public:
    explicit LeaveGate(Release release) : release_(release), depth_(memory_gate::depth()) {}
    ~LeaveGate() {
        if (memory_gate::depth() == depth_) return;
        release_();
        memory_gate::leave();
    }
    LeaveGate(const LeaveGate&) = delete;
    LeaveGate& operator=(const LeaveGate&) = delete;

  private:
    Release release_;
    int depth_;
};

using Clock = std::chrono::steady_clock;

// Stage times, read only when the options ask for them: the two clock reads
// per shape and stage took 1.6% of the frame of 10k one-pixel strokes (perf,
// in clock_gettime), which a render that reports no times should not pay.
Clock::time_point stage_start(const RenderOptions& o) {
    return o.time_stages ? Clock::now() : Clock::time_point{};
}
void add_stage_ms(double& ms, const RenderOptions& o, Clock::time_point start) {
    if (o.time_stages)
        ms += std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

} // namespace

RenderStats& RenderStats::operator+=(const RenderStats& o) {
    flatten.curves_in += o.flatten.curves_in;
    flatten.segments_out += o.flatten.segments_out;
    flatten.max_depth = std::max(flatten.max_depth, o.flatten.max_depth);
    flatten.max_error = std::max(flatten.max_error, o.flatten.max_error);
    flatten_ms += o.flatten_ms;
    raster_ms += o.raster_ms;
    return *this;
}

template <class Pixel>
RenderStats Renderer::render(const Scene& scene, const Affine& view, BasicCanvas<Pixel>& canvas,
                             const RenderOptions& options) {
    const int x0 = canvas.origin_x(), y0 = canvas.origin_y();
    return render(scene, view, canvas, options,
                  {x0, y0, x0 + canvas.width(), y0 + canvas.height()});
}

template <class Pixel>
RenderStats Renderer::render(const Scene& scene, const Affine& view, BasicCanvas<Pixel>& canvas,
                             const RenderOptions& options, const PixelRect& frame) {
    begin(view, options, frame);
    draw_group(scene.root, canvas);
    release_reserved();
    return stats_;
}

void Renderer::release_reserved() {
    if (stroker_.reserved() > 0) release_stroke_buffers();
    for (const auto& b : filter_buffers_)
        if (b->reserved.bytes() > 0) *b = FilterBuffers();
    if (tile_renderer_) tile_renderer_->release_reserved();
}

void Renderer::release_stroke_buffers() {
    stroker_.release();
    edges_.release();
    raster_.release();
}

template <class Pixel>
RenderStats Renderer::render_nodes(std::span<const Node* const> nodes, const Affine& view,
                                   BasicCanvas<Pixel>& canvas, const RenderOptions& options,
                                   const PixelRect& frame) {
    begin(view, options, frame);
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        // A band's nodes are a sparse subset of the scene's, some 300 bytes
        // each, which no hardware prefetcher follows: the miss on each node
        // was 3.6% of the frame of 10k one-pixel strokes (perf). Asks for the
        // next node's lines while this one is drawn (some microseconds).
        // (Prefetching its path's segments too, two loads deeper, measured
        // slower.)
        if (i + 1 < nodes.size()) {
            constexpr std::size_t kLine = 64; // x86-64's cache line, and most ARM cores'
            const char* next = reinterpret_cast<const char*>(nodes[i + 1]);
            for (std::size_t b = 0; b < sizeof(Node); b += kLine) __builtin_prefetch(next + b);
        }
        draw_node(*nodes[i], canvas);
    }
    return stats_;
}

void Renderer::begin(const Affine& view, const RenderOptions& options, const PixelRect& frame) {
    view_ = view;
    frame_ = frame;
    options_ = &options;
    stats_ = {};
    tiles_.clear(); // a new scene may hold other patterns at the same addresses
    layers_used_ = {};
    layer_bytes_ = 0;
    layer_sizes_.clear();
    filter_depth_ = 0;
    stroker_.set_memory_budget(&memory_gate::reserve, &memory_gate::unreserve);
}

Rect Renderer::reach_box(const Shape& s, const Affine& view) {
    const Affine m = view * s.transform;
    return mapped_box(s.path.control_bounds(), m).inflated(stroke_reach(s, m));
}

Rect Renderer::node_reach_box(const Node& n, const Affine& view) {
    if (const Shape* s = std::get_if<Shape>(&n.item)) return reach_box(*s, view);
    return group_reach_box(std::get<Group>(n.item), view);
}

Rect Renderer::group_reach_box(const Group& g, const Affine& view) {
    Rect r = Rect::empty();
    if (!g.filters.empty()) { // a filter draws over its region, whatever the content's box
        const Filter& f = *g.filters.back();
        const PixelRect p = filter_pixel_region(f.graph, view * f.transform);
        if (p.x1 > p.x0 && p.y1 > p.y0)
            r = {double(p.x0), double(p.y0), double(p.x1), double(p.y1)};
    } else {
        for (const Node& c : g.children) r = r.united(node_reach_box(c, view));
    }
    // Outside its content, a clip or a mask is 0: nothing shows there.
    if (g.clip) r = r.intersected(group_reach_box(g.clip->content, view));
    if (g.mask) r = r.intersected(group_reach_box(g.mask->content, view));
    return r;
}

template <class Target>
Target* Renderer::acquire_layer(int w, int h, int x0, int y0) {
    const std::size_t bytes = std::size_t(w) * std::size_t(h) * sizeof(typename Target::pixel_type);
    if (layer_bytes_ + bytes > layer_budget_) return nullptr;
    auto& layers = std::get<std::vector<std::unique_ptr<Target>>>(layers_);
    int& used = layers_used_[std::is_same_v<Target, Canvas8>];
    if (int(layers.size()) <= used) layers.push_back(std::make_unique<Target>());
    Target& l = *layers[std::size_t(used++)];
    l.reset(w, h, x0, y0);
    layer_bytes_ += bytes;
    layer_sizes_.push_back(bytes);
    return &l;
}

template <class Target>
void Renderer::release_layer() {
    --layers_used_[std::is_same_v<Target, Canvas8>];
    layer_bytes_ -= layer_sizes_.back();
    layer_sizes_.pop_back();
}

template <class Target>
void Renderer::draw_children(const Group& g, Target& target) {
    for (const Node& n : g.children) draw_node(n, target);
}

template <class Target>
void Renderer::draw_node(const Node& n, Target& target) {
    if (const Shape* s = std::get_if<Shape>(&n.item)) {
        // Opacity on a shape with both fill and stroke applies to the two
        // together (SVG 1.1, 14.5): a layer, or the stroke would show the
        // fill through it. With one paint, scaling its alpha is the same.
        if (s->opacity < 1.0f && s->fill && s->stroke)
            in_layer(reach_box(*s, view_), target, s->opacity, BlendMode::Normal,
                     [&](Target& l) { draw_shape(*s, l, 1.0f); });
        else
            draw_shape(*s, target, s->opacity);
        return;
    }
    draw_group(std::get<Group>(n.item), target);
}

template <class Target>
void Renderer::draw_group(const Group& g, Target& target) {
    if (!g.needs_layer()) {
        draw_children(g, target);
        return;
    }
    in_layer(group_reach_box(g, view_), target, g.opacity, g.blend, [&](Target& l) {
        // Over the layer budget, l is the target: drawn straight, with its
        // opacity and blend mode left out, or, clipped or masked, not at
        // all (what a clip hides must not show).
        if (&l == &target && (g.clip || g.mask || !g.filters.empty())) return;
        if (g.filters.empty())
            draw_children(g, l);
        else if (!filter_layer(g, l))
            return;
        if (&l == &target) return;
        if (g.clip) mask_layer(*g.clip, l);
        if (g.mask) mask_layer(*g.mask, l);
    });
}

template <class Target>
void Renderer::mask_layer(const Mask& mask, Target& layer) {
    Target* m =
        acquire_layer<Target>(layer.width(), layer.height(), layer.origin_x(), layer.origin_y());
    if (!m) { // over the layer budget: masked away wholly, not left unmasked
        layer.reset(layer.width(), layer.height(), layer.origin_x(), layer.origin_y());
        return;
    }
    draw_group(mask.content, *m);
    const auto t = stage_start(*options_);
    apply_mask(layer, *m, mask.kind);
    add_stage_ms(stats_.raster_ms, *options_, t);
    release_layer<Target>();
}

template <class Target, class Draw>
void Renderer::in_layer(const Rect& b, Target& target, float opacity, BlendMode blend, Draw draw) {
    if (opacity <= 0.0f) return;
    // The layer covers all that the node can draw (node_reach_box: its
    // shapes' control boxes grown by their strokes' reach, a wide stroke, a
    // miter, a square cap), with one pixel of margin for antialiasing,
    // clipped to the target. (It once took the paths' tight bounds: a
    // stroke's outer half was cut away.)
    if (b.is_empty()) return;
    const int tx0 = target.origin_x(), tx1 = tx0 + target.width();
    const int ty0 = target.origin_y(), ty1 = ty0 + target.height();
    const int x0 = floor_in(b.x0 - 1, tx0, tx1), y0 = floor_in(b.y0 - 1, ty0, ty1);
    const int x1 = ceil_in(b.x1 + 1, tx0, tx1), y1 = ceil_in(b.y1 + 1, ty0, ty1);
    if (x1 <= x0 || y1 <= y0) return;
    Target* l = acquire_layer<Target>(x1 - x0, y1 - y0, x0, y0);
    if (!l) { // over the layer budget: drawn straight onto the target
        draw(target);
        return;
    }
    draw(*l);
    const auto t = stage_start(*options_);
    composite_layer(target, *l, opacity, blend);
    add_stage_ms(stats_.raster_ms, *options_, t);
    release_layer<Target>();
}

template <class Target>
void Renderer::draw_shape(const Shape& s, Target& target, float opacity) {
    if (opacity <= 0.0f || (!s.fill && !s.stroke)) return;
    const Affine m = view_ * s.transform;
    // A shape wholly outside the target draws nothing there. Left of it too:
    // fills and stroke outlines are closed, so their winding is 0 right of
    // them, and the sweep rounds the winding past an outline's last column.
    const Rect box = reach_box(s, view_);
    if (box.is_empty() || box.y1 <= target.origin_y() ||
        box.y0 >= target.origin_y() + target.height() || box.x1 <= target.origin_x() ||
        box.x0 >= target.origin_x() + target.width())
        return;
    // Edges are clipped to the frame, columns and rows alike, and built for
    // the target's rows only (see EdgeList); spans are cut to the target's
    // columns when composited (paint). So a band, a layer or a dirty tile
    // gets the same edges and coverage as the whole frame, bit for bit.
    // paint-order: the fill under the stroke (SVG's normal), or over it.
    if (s.stroke && s.stroke_first) draw_stroke(s, m, target, opacity);
    if (s.fill) {
        const auto t = stage_start(*options_);
        edges_.reset(frame_, target.origin_y(), target.origin_y() + target.height());
        RenderStats shape;
        shape.flatten =
            add_path_edges(s.path, m, options_->flatten, edges_, options_->measure_error);
        stats_ += shape;
        add_stage_ms(stats_.flatten_ms, *options_, t);
        paint(s, s.fill->color, s.fill->gradient.get(), s.fill->pattern.get(),
              s.fill->opacity * opacity, s.fill->rule, target);
    }
    if (s.stroke && !s.stroke_first) draw_stroke(s, m, target, opacity);
}

template <class Target>
void Renderer::draw_stroke(const Shape& s, const Affine& m, Target& target, float opacity) {
    const Stroke& st = *s.stroke;
    // Hairlines: a stroke narrower than one device pixel is drawn one pixel
    // wide with its opacity scaled by its width, so it keeps its total
    // coverage without breaking up. The device width is taken as the width
    // times the map's geometric-mean scale.
    const double scale = std::sqrt(std::fabs(m.determinant()));
    const double device_width = st.geometry.width * scale;
    if (!(device_width > 0) || !(scale > 0)) return;
    const StrokeGeometry* geometry = &st.geometry;
    float hairline = 1.0f;
    if (device_width < 1.0) {
        hairline_geometry_ = st.geometry; // into the member: its dash storage is reused
        hairline_geometry_.width = st.geometry.width / device_width;
        geometry = &hairline_geometry_;
        hairline = float(device_width);
    }
    // The outline is built only near the pixels it is drawn on, and its
    // samples and dash ends depend on that box (clipped chords, halved
    // curves). So that every band or tile gets the same outline for a row,
    // the box is a fixed strip of kStrokeStripRows frame rows (one pixel
    // wider for the antialiased edge), and a target crossing several strips
    // draws each strip's rows from that strip's outline.
    const int top = std::max(frame_.y0, target.origin_y());
    const int bottom = std::min(frame_.y1, target.origin_y() + target.height());
    // The device tolerance in user units: divided by the largest stretch.
    const double tolerance = options_->flatten.tolerance / m.max_scale();
    const Affine to_user = m.inverse();
    for (int y0 = top; y0 < bottom;) {
        // Refused by the memory budget, the strip's outline went on through
        // the gate: its buffers are freed once it is painted.
        const LeaveGate leave([this] { release_stroke_buffers(); });
        const int strip = frame_.y0 + (y0 - frame_.y0) / kStrokeStripRows * kStrokeStripRows;
        const int y1 = std::min(bottom, strip + kStrokeStripRows);
        const auto t = stage_start(*options_);
        const Rect pixels{double(frame_.x0 - 1), double(strip - 1), double(frame_.x1 + 1),
                          double(std::min(frame_.y1, strip + kStrokeStripRows) + 1)};
        const std::span<const Polygon> outline =
            stroker_.outline(s.path, *geometry, tolerance, mapped_box(pixels, to_user));
        edges_.reset(frame_, y0, y1);
        for (const Polygon& poly : outline) {
            for (std::size_t i = 0; i < poly.size(); ++i)
                edges_.add_line(m * poly[i], m * poly[(i + 1) % poly.size()]);
            stats_.flatten.segments_out += poly.size();
        }
        add_stage_ms(stats_.flatten_ms, *options_, t);
        paint(s, st.color, st.gradient.get(), st.pattern.get(), st.opacity * opacity * hairline,
              FillRule::NonZero, target);
        y0 = y1;
    }
}

double Renderer::stroke_reach(const Shape& s, const Affine& m) {
    if (!s.stroke) return 0;
    // A miter reaches at most limit * width / 2 from the path; caps and round
    // joins width / 2 (sqrt(2) of it for square caps). At least one pixel for
    // hairlines.
    const Stroke& st = *s.stroke;
    return std::max(1.0, 0.5 * st.geometry.width *
                             std::max(st.geometry.miter_limit, std::sqrt(2.0)) * m.max_scale());
}

template <class Target>
void Renderer::paint(const Shape& s, Rgba color, const Gradient* gradient, const Pattern* pattern,
                     float opacity, FillRule rule, Target& target) {
    const auto t = stage_start(*options_);
    const bool antialias = options_->antialias && s.antialias;
    // Spans are cut to the target's columns (the edges are the frame's),
    // unless the target has all of the frame's columns (a band).
    const auto fill_through = [&](SpanSink& painter) {
        const int x0 = target.origin_x(), x1 = x0 + target.width();
        if (x0 <= edges_.clip().x0 && edges_.clip().x1 <= x1) {
            raster_.fill(edges_, rule, antialias, painter);
            return;
        }
        ColumnClipSink clipped(painter, x0, x1);
        raster_.fill(edges_, rule, antialias, clipped);
    };
    if (pattern) {
        if (prepare_pattern(*pattern, view_ * s.transform, opacity)) {
            // The columns the fill can reach: between its edges' extremes.
            float x0 = float(edges_.clip().x1), x1 = float(edges_.clip().x0);
            for (const Edge& e : edges_.edges())
                x0 = std::min({x0, e.x0, e.x1}), x1 = std::max({x1, e.x0, e.x1});
            image_shader_.tabulate(int(std::floor(x0)), int(std::ceil(x1)));
            ImageSpanPainter<typename Target::pixel_type> painter{target, image_shader_};
            fill_through(painter);
        }
    } else if (gradient) {
        // Gradient space -> device: the shape's transform, then for
        // objectBoundingBox units the unit square onto the shape's box (an
        // empty box paints nothing, SVG 1.1 13.2.2), then gradientTransform.
        Affine to_device = view_ * s.transform;
        if (gradient->object_bounding_box) {
            const Rect b = s.path.bounds();
            if (!(b.width() > 0 && b.height() > 0)) return;
            to_device = to_device * Affine::translate(b.min().to_vec()) *
                        Affine::scale(b.width(), b.height());
        }
        if (gradient_shader_.prepare(*gradient, to_device * gradient->transform, opacity,
                                     options_->linear_light_gradients)) {
            GradientSpanPainter<typename Target::pixel_type> painter{target, gradient_shader_};
            fill_through(painter);
        }
    } else {
        const Premul c = premultiply(color, opacity);
        if (c.a > 0.0f) {
            SolidSpanPainter painter{target, c};
            fill_through(painter);
        }
    }
    add_stage_ms(stats_.raster_ms, *options_, t);
}

bool Renderer::prepare_pattern(const Pattern& p, const Affine& m, float opacity) {
    if (!(p.width > 0 && p.height > 0)) return false;
    const Affine to_device = m * p.transform; // tile space -> device
    if (p.image) {
        // Smooth sampling of an image drawn smaller than half its size
        // reads one of its levels (paint/image_levels.h), which covers the
        // same tile with fewer pixels; nearest-pixel sampling (pixelated)
        // keeps the image's own.
        const RasterImage& im = *p.image;
        const Affine image_map =
            to_device * Affine::scale(p.width / im.width, p.height / im.height);
        const RasterImage& level =
            p.smooth ? im.level(level_for(image_map, im.width, im.height)) : im;
        return image_shader_.prepare(
            level, to_device * Affine::scale(p.width / level.width, p.height / level.height),
            opacity, p.smooth, p.repeat);
    }
    // The tile is drawn at the device resolution: as many pixels as the
    // tile's sides are long on the device (its columns' lengths under the
    // map), rounded up, at least one, and fewer where that is over
    // kMaxTilePixels. A tile of a fraction of a pixel is thus drawn into
    // one pixel, whose exact-area coverage makes it the tile's mean color.
    const RasterImage* tile = tiles_.find(&p, to_device);
    if (!tile) {
        const double sx = std::hypot(to_device.a, to_device.b) * p.width;
        const double sy = std::hypot(to_device.c, to_device.d) * p.height;
        if (!(sx > 0 && sy > 0) || !std::isfinite(sx * sy)) return false;
        // Clamped as doubles: a tile far longer than wide keeps sx * sy
        // finite, yet one side times the shrink can be past int's range.
        const double shrink = std::min(1.0, std::sqrt(double(kMaxTilePixels) / (sx * sy)));
        const int w = int(std::clamp(std::ceil(sx * shrink), 1.0, double(kMaxTilePixels)));
        const int h = int(std::clamp(std::ceil(sy * shrink), 1.0, double(kMaxTilePixels / w)));
        if (!tile_renderer_) tile_renderer_ = std::make_unique<Renderer>();
        tile_canvas_.reset(w, h);
        tile_renderer_->begin(Affine::scale(w / p.width, h / p.height), *options_, {0, 0, w, h});
        tile_renderer_->draw_group(p.content, tile_canvas_);
        stats_ += tile_renderer_->stats_;
        RasterImage& drawn = tiles_.insert(&p, to_device, w, h);
        for (int y = 0; y < h; ++y)
            std::copy_n(tile_canvas_.row(y), w, drawn.pixels.begin() + std::ptrdiff_t(y) * w);
        drawn.find_opaque8();
        tile = &drawn;
    }
    return image_shader_.prepare(
        *tile, to_device * Affine::scale(p.width / tile->width, p.height / tile->height), opacity,
        p.smooth, p.repeat);
}

namespace {

// The pixels of `c` into `img` (its box: the canvas's place), as float.
template <class Pixel>
void to_filter_image(const BasicCanvas<Pixel>& c, FilterImage& img) {
    img.reset({c.origin_x(), c.origin_y(), c.origin_x() + c.width(), c.origin_y() + c.height()},
              false);
    for (int y = 0; y < c.height(); ++y) {
        const Pixel* row = c.row(y);
        Premul* out = &img.at(0, y);
        for (int x = 0; x < c.width(); ++x) out[x] = to_premul(row[x]);
    }
}

PixelRect grown(const PixelRect& r, double by) {
    const int k = int(std::min(by, double(1 << 28)));
    return {r.x0 - k, r.y0 - k, r.x1 + k, r.y1 + k};
}

} // namespace

template <class Target>
bool Renderer::filter_layer(const Group& g, Target& layer) {
    // One window for the whole chain: the union of the filters' regions,
    // cut to the layer grown by every filter's reach (so the layer's pixels
    // come out exactly as from an uncut window: bands agree bit for bit),
    // and to the frame grown by as much, at most kMaxFilterMargin.
    double reach = 0;
    PixelRect regions{};
    for (const auto& f : g.filters) {
        const Affine m = view_ * f->transform;
        reach += filter_reach(f->graph, m);
        regions = regions.united(filter_pixel_region(f->graph, m));
    }
    const PixelRect target{layer.origin_x(), layer.origin_y(), layer.origin_x() + layer.width(),
                           layer.origin_y() + layer.height()};
    const PixelRect frame = grown(frame_, std::min(reach, double(kMaxFilterMargin)));
    const PixelRect window = regions.intersected(frame).intersected(grown(target, reach));
    if (window.is_empty()) return true; // nothing to draw here
    if (filter_buffers_.size() <= filter_depth_)
        filter_buffers_.push_back(std::make_unique<FilterBuffers>());
    FilterBuffers& buf = *filter_buffers_[filter_depth_]; // nested filters take the next
    std::size_t images = 0; // the source, the inputs and what a run holds, at most
    for (const auto& f : g.filters)
        images = std::max(images, 3 + f->images.size() + filter_held_images(f->graph));
    // A chain past kUnreservedFilterBytes reserves what it may hold, kept to
    // the end of the frame (release_reserved); refused, it runs through the
    // gate, and its buffers are freed once it has run. (The source layer's
    // storage is the layer budget's, split between the threads.)
    const LeaveGate leave([&buf] { buf = FilterBuffers(); });
    if (const std::size_t bytes =
            images * std::size_t(window.width()) * std::size_t(window.height()) * sizeof(Premul);
        bytes > kUnreservedFilterBytes)
        buf.reserved.grow_to(bytes);
    Target* src = acquire_layer<Target>(window.width(), window.height(), window.x0, window.y0);
    if (!src) return false;
    ++filter_depth_;
    const PixelRect saved = frame_;
    frame_ = frame; // the content just outside the frame is drawn too
    draw_children(g, *src);
    to_filter_image(*src, buf.source);
    release_layer<Target>();
    bool ok = true;
    for (std::size_t k = 0; ok && k < g.filters.size(); ++k) {
        const Filter* f = g.filters[k].get();
        const std::size_t n = f->images.size();
        buf.inputs.resize(std::max(buf.inputs.size(), n + 2));
        for (std::size_t i = 0; i < n; ++i) draw_filter_input(f->images[i], window, buf.inputs[i]);
        draw_filter_input(f->fill_paint, window, buf.inputs[n]);
        draw_filter_input(f->stroke_paint, window, buf.inputs[n + 1]);
        const FilterSources io{
            &buf.source, {buf.inputs.data(), n}, &buf.inputs[n], &buf.inputs[n + 1], &buf.pool};
        const auto t = stage_start(*options_);
        ok = run_filter(f->graph, view_ * f->transform, io);
        add_stage_ms(stats_.raster_ms, *options_, t);
    }
    frame_ = saved;
    --filter_depth_;
    if (!ok) return false;
    const PixelRect out = window.intersected(target);
    for (int y = out.y0; y < out.y1; ++y) {
        auto* row = layer.row(y - layer.origin_y());
        for (int x = out.x0; x < out.x1; ++x)
            row[x - layer.origin_x()] =
                pixel_of<typename Target::pixel_type>(buf.source.at(x - window.x0, y - window.y0));
    }
    return true;
}

void Renderer::draw_filter_input(const Group& content, const PixelRect& window, FilterImage& img) {
    Canvas* c = content.children.empty()
                    ? nullptr
                    : acquire_layer<Canvas>(window.width(), window.height(), window.x0, window.y0);
    if (!c) { // nothing to draw, or over the layer budget: transparent
        img.reset(window, false);
        return;
    }
    draw_group(content, *c);
    to_filter_image(*c, img);
    release_layer<Canvas>();
}

// The two pixel formats a renderer draws onto.
template RenderStats Renderer::render(const Scene&, const Affine&, Canvas&, const RenderOptions&);
template RenderStats Renderer::render(const Scene&, const Affine&, Canvas8&, const RenderOptions&);
template RenderStats Renderer::render(const Scene&, const Affine&, Canvas&, const RenderOptions&,
                                      const PixelRect&);
template RenderStats Renderer::render(const Scene&, const Affine&, Canvas8&, const RenderOptions&,
                                      const PixelRect&);
template RenderStats Renderer::render_nodes(std::span<const Node* const>, const Affine&, Canvas&,
                                            const RenderOptions&, const PixelRect&);
template RenderStats Renderer::render_nodes(std::span<const Node* const>, const Affine&, Canvas8&,
                                            const RenderOptions&, const PixelRect&);

} // namespace casteljau
