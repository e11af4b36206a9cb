// Renderer: a Scene onto a Canvas or a Canvas8. Shape by shape: edges (flatten + clip,
// raster/path_edges.h) -> coverage spans (raster/rasterizer.h) -> source-over
// compositing (paint/canvas.h); groups with opacity go through an offscreen
// layer limited to the group's bounds. The renderer keeps its edge list,
// rasterizer buffers and layers between shapes and frames: in steady state a
// frame allocates nothing new.
#pragma once

#include "casteljau/flatten/path_flatten.h"
#include "casteljau/paint/canvas.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/raster/edge.h"
#include "casteljau/raster/rasterizer.h"
#include "casteljau/scene/scene.h"
#include "casteljau/stroke/stroker.h"

#include <memory>
#include <span>
#include <tuple>
#include <vector>

namespace casteljau {

/// Stroke outlines are built per strip of this many frame rows (see
/// draw_stroke): a band of kBandRows rows (bands.h) is whole strips, so it
/// builds each outline once.
inline constexpr int kStrokeStripRows = 128;

/// How to render: flattening, antialiasing, statistics, gradient interpolation.
struct RenderOptions {
    FlattenOptions flatten;
    bool antialias = true;
    bool measure_error = false;          ///< fold the exact flattening error into the stats (slow)
    bool linear_light_gradients = false; ///< interpolate gradients in linear light, not sRGB
    bool time_stages = false;            ///< fill in RenderStats' stage times (clock reads)
};

/// What a render did and how long it took.
struct RenderStats {
    FlattenStats flatten;
    double flatten_ms = 0; ///< edge building: culling, flattening, clipping (time_stages only)
    double raster_ms = 0;  ///< accumulation, sweep and compositing (time_stages only)

    /// Sums counts and times; keeps the largest depth and error.
    RenderStats& operator+=(const RenderStats& o);
};

/// Draws a Scene onto a canvas of either pixel format (Canvas, Canvas8),
/// keeping its buffers between shapes and frames.
class Renderer {
  public:
    /// Draws `scene` onto all of `canvas` (the canvas is the frame), mapping
    /// scene device space by `view` (e.g. a scale to the output size).
    template <class Pixel>
    RenderStats render(const Scene& scene, const Affine& view, BasicCanvas<Pixel>& canvas,
                       const RenderOptions& options);
    /// The same where `frame` is the whole image in pixels and `canvas` one
    /// band of it (its origin tells where); edges are clipped to the frame's
    /// rows so that bands match the whole bit for bit.
    template <class Pixel>
    RenderStats render(const Scene& scene, const Affine& view, BasicCanvas<Pixel>& canvas,
                       const RenderOptions& options, const PixelRect& frame);
    /// Draws only the given nodes, in order, as render() would draw them as the
    /// root's children: for a caller that culls with its own index (see
    /// Drawing). `canvas` may be any tile of `frame`, and gets exactly the
    /// pixels a render of the whole frame gives there.
    template <class Pixel>
    RenderStats render_nodes(std::span<const Node* const> nodes, const Affine& view,
                             BasicCanvas<Pixel>& canvas, const RenderOptions& options,
                             const PixelRect& frame);

    /// The device box (under `view`) outside which a shape changes no pixel:
    /// its control box mapped, grown by the stroke's reach.
    static Rect reach_box(const Shape& s, const Affine& view);

    /// reach_box of a node: a shape's, or the union of a group's children's.
    static Rect node_reach_box(const Node& n, const Affine& view);

    /// How far (device px) a shape's stroke can reach beyond its path.
    static double stroke_reach(const Shape& s, const Affine& to_device);

  private:
    void begin(const Affine& view, const RenderOptions& options, const PixelRect& frame);
    template <class Target>
    void draw_group(const Group& g, Target& target, int depth);
    template <class Target>
    void draw_node(const Node& n, Target& target, int depth);
    template <class Target>
    void draw_shape(const Shape& s, Target& target, float opacity);
    /// Draws into an offscreen layer over the node's bounds, composited with `opacity`.
    template <class Target, class Draw>
    void in_layer(const Node& n, Target& target, int depth, float opacity, Draw draw);
    template <class Target>
    void draw_stroke(const Shape& s, const Affine& m, Target& target, float opacity);
    /// Composites the current edge list with a solid color or a gradient.
    template <class Target>
    void paint(const Shape& s, Rgba color, const Gradient* gradient, float opacity, FillRule rule,
               Target& target);
    /// The layer of nesting depth `depth`, in the target's pixel format.
    template <class Target>
    Target& layer(int depth);

    EdgeList edges_;
    Rasterizer raster_;
    GradientShader gradient_shader_;   ///< its color table is reused across shapes
    Stroker stroker_;                  ///< stroke outlines, buffers reused across shapes
    StrokeGeometry hairline_geometry_; ///< a hairline's widened copy of its geometry
    /// One layer per group nesting depth, per pixel format.
    std::tuple<std::vector<std::unique_ptr<Canvas>>, std::vector<std::unique_ptr<Canvas8>>> layers_;
    Affine view_;
    PixelRect frame_;
    const RenderOptions* options_ = nullptr;
    RenderStats stats_;
};

} // namespace casteljau
