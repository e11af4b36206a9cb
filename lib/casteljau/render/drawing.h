// Drawing: a retained scene for applications that edit it shape by shape and
// redraw only what changed.
//
// Shapes are kept in drawing order, each with its device box cached
// (Renderer::reach_box: outside it the shape changes no pixel). An edit
// returns the pixels it damaged, the old box united with the new one, and
// render_region() redraws just those: the shapes whose cached boxes meet the
// dirty rectangle are drawn, in order, into a tile the size of the rectangle,
// cleared to the background, which is then copied into the canvas. The tile
// gets exactly the pixels a full render gives there (Renderer::render_nodes:
// edges are clipped to the whole frame, coverage is computed for whole rows
// and cut to the tile's columns only when composited), so a partial redraw
// after an edit leaves the canvas bit-identical to a full render of the
// edited drawing (tested).
//
// Cost of a redraw: one scan of the cached boxes (four comparisons per
// shape), plus the shapes crossing the rectangle, each flattened and swept
// over the dirty rows only, plus compositing the dirty area. Nothing scales
// with the canvas or with the shapes that do not cross the rectangle, except
// that scan.
#pragma once

#include "casteljau/raster/edge.h"
#include "casteljau/render/bands.h"
#include "casteljau/render/renderer.h"
#include "casteljau/scene/scene.h"
#include "casteljau/text/layout.h"

#include <cstddef>
#include <memory>
#include <optional>
#include <tuple>
#include <vector>

namespace casteljau {

/// What a fill or a stroke is painted with: a solid color, a gradient, a
/// pattern or an image, and an opacity.
struct Paint {
    Rgba color;                               ///< used when there is no gradient nor pattern
    std::shared_ptr<const Gradient> gradient; ///< paints instead of `color` when set
    float opacity = 1;                        ///< multiplies the color's alpha
    std::shared_ptr<const Pattern> pattern = nullptr; ///< paints instead of both when set

    /// A solid color.
    static Paint solid(Rgba c) { return {c, nullptr, 1}; }
    /// A linear gradient from `from` to `to`, in the shape's path coordinates.
    static Paint linear(Point from, Point to, std::vector<GradientStop> stops);
    /// An image stretched onto `where` (path coordinates), its edge pixels
    /// extended beyond; sampled bilinearly, or the nearest pixel when not `smooth`.
    static Paint image(std::shared_ptr<const RasterImage> image, const Rect& where,
                       bool smooth = true);
    /// A pattern: its content drawn into each tile at the device resolution.
    static Paint tiled(Pattern pattern);
};

/// A clip for Group::clip: the area of `path` (mapped to the canvas by
/// `transform`) under `rule`, antialiased.
std::shared_ptr<const Mask> clip_of(const Path& path, const Affine& transform = Affine::identity(),
                                    FillRule rule = FillRule::NonZero);

/// A filter for Group::filters: a Gaussian blur of standard deviation
/// `sigma`, drawn over `region`; both in the coordinates `transform` maps to
/// the canvas (a blur spreads about 3 sigma: grow the region by as much).
std::shared_ptr<const Filter> blur_filter(double sigma, const Rect& region,
                                          const Affine& transform = Affine::identity());
/// A filter for Group::filters: the group over its shadow, its alpha
/// blurred by `sigma`, moved by `offset` and colored `color`; in the
/// coordinates `transform` maps to the canvas, over `region`.
std::shared_ptr<const Filter> drop_shadow_filter(Vec2 offset, double sigma, Rgba color,
                                                 const Rect& region,
                                                 const Affine& transform = Affine::identity());

/// A retained, editable list of shapes on a width x height pixel canvas.
class Drawing {
  public:
    /// Identifies a shape; stable for the drawing's life (shapes are never renumbered).
    using ShapeId = std::size_t;

    /// An empty drawing whose device space is the canvas's pixels.
    Drawing(int width, int height);
    /// Canvas width in pixels.
    int width() const { return width_; }
    /// Canvas height in pixels.
    int height() const { return height_; }

    /// Adds a filled path (path coordinates mapped to pixels by `transform`).
    ShapeId fill(const Path& path, const Paint& paint, const Affine& transform = Affine::identity(),
                 FillRule rule = FillRule::NonZero);
    /// Adds a stroked path; the stroke's width is in path coordinates.
    ShapeId stroke(const Path& path, const Paint& paint, const StrokeGeometry& geometry,
                   const Affine& transform = Affine::identity());
    /// Adds a line of text filled with `paint`, its baseline starting at
    /// `origin` (text/layout.h's text_to_path: shaped, bidi, font fallback),
    /// its glyph outlines flattened and antialiased as every path is.
    ShapeId text(FontDatabase& fonts, std::string_view utf8, const TextStyle& style, Point origin,
                 const Paint& paint, const Affine& transform = Affine::identity());
    /// Adds any shape (fill and stroke together, element opacity).
    ShapeId add(Shape shape);
    /// Adds `image` stretched onto `where` (mapped to pixels by `transform`).
    ShapeId image(std::shared_ptr<const RasterImage> image, const Rect& where,
                  const Affine& transform = Affine::identity(), bool smooth = true);
    /// Adds a group: its shapes drawn together into a layer, then filtered
    /// (Group::filters, see blur_filter, drop_shadow_filter, or any
    /// FilterGraph), clipped, masked (Group::clip, Group::mask, see clip_of)
    /// and composited with its opacity and blend mode. Its shapes' transforms map to the canvas.
    /// Hit tests (shape_at, shapes_in) pass over groups.
    ShapeId add(Group group);
    /// Number of shapes, removed ones included.
    std::size_t size() const { return boxes_.size(); }
    /// Shape `id` as last set (precondition: a shape, not a group).
    const Shape& shape(ShapeId id) const;
    /// Item `id`, a shape or a group, as last set.
    const Node& node(ShapeId id) const { return scene_.root.children[id]; }
    /// Replaces item `id` by a shape; returns the pixels to redraw.
    PixelRect replace(ShapeId id, Shape shape) { return replace(id, Node{std::move(shape)}); }
    /// Replaces item `id` by a shape or a group; returns the pixels to redraw.
    PixelRect replace(ShapeId id, Node node);
    /// Removes shape `id` (it becomes an empty shape); returns the pixels to redraw.
    PixelRect remove(ShapeId id) { return replace(id, Shape{}); }
    /// The pixels shape `id` can change, clipped to the canvas.
    PixelRect damage(ShapeId id) const;
    /// The topmost shape whose fill holds `p` (device pixels, exact on the curves)
    /// or whose stroke lies within `tolerance` px of it; none over empty canvas.
    std::optional<ShapeId> shape_at(Point p, double tolerance = 0.5) const;
    /// The shapes whose fill or stroke meets `r` (device pixels), in drawing order:
    /// rubber-band selection. Fills are tested exactly on their curves, strokes
    /// on their outline (caps, joins and dashes as drawn) to within 0.01 px.
    std::vector<ShapeId> shapes_in(const Rect& r) const;
    /// The drawing as a scene (top-level shapes in order), for Renderer or BandRenderer.
    const Scene& scene() const { return scene_; }

    /// Renders everything onto `canvas` (a Canvas or a Canvas8, width() x
    /// height(), origin 0, 0) over `background`.
    template <class Pixel>
    RenderStats render(BasicCanvas<Pixel>& canvas, Premul background,
                       const RenderOptions& options = {}, int threads = 1);
    /// Re-renders only `dirty` (clipped to the canvas) of a canvas rendered before.
    template <class Pixel>
    RenderStats render_region(BasicCanvas<Pixel>& canvas, const PixelRect& dirty, Premul background,
                              const RenderOptions& options = {});

  private:
    int width_, height_;
    Scene scene_;
    std::vector<Rect> boxes_; // Renderer::reach_box of each shape, in pixels
    BandRenderer bands_;
    Renderer renderer_;
    std::tuple<Canvas, Canvas8> tiles_; // render_region's, per pixel format
    std::vector<const Node*> crossing_; // reused by render_region
};

/// The smallest pixel rectangle holding both `a` and `b` (either may be empty).
PixelRect united(const PixelRect& a, const PixelRect& b);

} // namespace casteljau
