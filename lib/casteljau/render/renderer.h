// Renderer: a Scene onto a Canvas or a Canvas8. Shape by shape: edges (flatten + clip,
// raster/path_edges.h) -> coverage spans (raster/rasterizer.h) -> source-over
// compositing (paint/canvas.h). A group that needs a layer (opacity, clip,
// mask, blend mode, isolation) is drawn into an offscreen layer limited to
// its bounds, which is then clipped and masked by its clip's and mask's
// content drawn into layers of the same place (paint/mask.h), and
// composited with the group's opacity and blend mode (paint/blend.h).
// Patterns are drawn into a tile at the device resolution, then painted as
// an image (paint/image_shader.h). A filtered group is drawn into a layer
// over its filter region, grown by how far the filter reads (filter/run.h)
// and cut to the frame grown by at most kMaxFilterMargin, and the filter
// runs on it before the clip and mask. The renderer keeps its edge list,
// rasterizer buffers, layers and tiles between shapes and frames: in steady
// state a frame allocates nothing new.
//
// Layer memory: one layer per group, clip or mask in flight, each at most
// the target's size, and at most a budget in flight at once (kMaxLayerBytes,
// shared by the threads of a BandRenderer): a group nested deeper than that
// allows is drawn straight onto what is under it, its opacity and blend
// mode left out, or not at all when it is clipped or masked (a degraded
// picture, not an unbounded one, and never one that shows what a clip hides). Pattern tiles are at
// most kMaxTilePixels each, and a renderer keeps at most kMaxTilePixels of them
// (tile_cache.h; an opaque tile's 8-bit copy, a quarter more, besides), one
// renderer per pattern nesting level.
#pragma once

#include "casteljau/filter/filter_image.h"
#include "casteljau/flatten/path_flatten.h"
#include "casteljau/paint/canvas.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/paint/image_shader.h"
#include "casteljau/raster/edge.h"
#include "casteljau/raster/rasterizer.h"
#include "casteljau/render/memory_gate.h"
#include "casteljau/render/tile_cache.h"
#include "casteljau/scene/scene.h"
#include "casteljau/stroke/stroker.h"

#include <array>
#include <cstddef>
#include <memory>
#include <span>
#include <tuple>
#include <vector>

namespace casteljau {

/// Stroke outlines are built per strip of this many frame rows (see
/// draw_stroke): a band of kBandRows rows (bands.h) is whole strips, so it
/// builds each outline once.
inline constexpr int kStrokeStripRows = 128;

/// The most pixels a pattern tile is drawn into (16 MiB of float pixels):
/// a larger tile at device resolution is drawn at a lower one.
inline constexpr long kMaxTilePixels = 1L << 20;

/// The most bytes of layers in flight at once (groups, clips, masks), per
/// renderer: 512 MiB, sixteen 2048 x 1024 float layers, or a float band of
/// a 16384 px wide frame (kBandRows rows, 32 MiB) sixteen deep.
inline constexpr std::size_t kMaxLayerBytes = std::size_t(512) << 20;

/// How far beyond the frame (device px) a filter's input is drawn: a blur
/// or offset pulls that much of what lies outside the frame into it.
/// (resvg draws nothing outside the canvas; browsers draw the whole region.)
inline constexpr int kMaxFilterMargin = 256;

/// The bytes of images a filter chain may hold (its source, inputs and
/// intermediate results, counted as run_filter bounds them) without a
/// reservation from the memory budget (memory_gate.h): 4 MiB, a blur on a
/// band of a 512 px wide frame.
inline constexpr std::size_t kUnreservedFilterBytes = std::size_t(4) << 20;

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

    /// reach_box of a node: a shape's, or group_reach_box of a group.
    static Rect node_reach_box(const Node& n, const Affine& view);
    /// The union of a group's children's reach boxes, cut to its clip's
    /// and its mask's content (nothing shows outside them).
    static Rect group_reach_box(const Group& g, const Affine& view);

    /// How far (device px) a shape's stroke can reach beyond its path.
    static double stroke_reach(const Shape& s, const Affine& to_device);

    /// The bytes of layers this renderer may have in flight (kMaxLayerBytes
    /// unless set): BandRenderer gives each of its threads an equal share,
    /// so a picture degraded by the budget may differ between thread counts.
    void set_layer_budget(std::size_t bytes) { layer_budget_ = bytes; }

    /// Frees the buffers that hold a reservation from the memory budget
    /// (memory_gate.h: strokes and filter chains past a few MB) and gives it
    /// back, so that an idle renderer keeps no share of the budget. render()
    /// calls it at the end of the frame, BandRenderer after all bands.
    void release_reserved();

  private:
    void begin(const Affine& view, const RenderOptions& options, const PixelRect& frame);
    /// Frees the stroker's, the edges' and the rasterizer's buffers.
    void release_stroke_buffers();
    template <class Target>
    void draw_children(const Group& g, Target& target);
    template <class Target>
    void draw_group(const Group& g, Target& target);
    template <class Target>
    void draw_node(const Node& n, Target& target);
    template <class Target>
    void draw_shape(const Shape& s, Target& target, float opacity);
    /// Draws into an offscreen layer over `box` (device px) cut to the
    /// target, composited with `opacity` and `blend`.
    template <class Target, class Draw>
    void in_layer(const Rect& box, Target& target, float opacity, BlendMode blend, Draw draw);
    /// Draws the group's children and runs its filters into `layer`; false
    /// when a filter is in error or over a limit (the group is not drawn).
    template <class Target>
    bool filter_layer(const Group& g, Target& layer);
    /// Draws `content` over `window` into `img` (float, sRGB).
    void draw_filter_input(const Group& content, const PixelRect& window, FilterImage& img);
    /// Scales `layer` by the mask's value, from its content drawn at the same place.
    template <class Target>
    void mask_layer(const Mask& mask, Target& layer);
    template <class Target>
    void draw_stroke(const Shape& s, const Affine& m, Target& target, float opacity);
    /// Composites the current edge list with a paint: a solid color, a
    /// gradient or a pattern.
    template <class Target>
    void paint(const Shape& s, Rgba color, const Gradient* gradient, const Pattern* pattern,
               float opacity, FillRule rule, Target& target);
    /// Sets image_shader_ to paint `p` mapped to device space by `m` (the
    /// shape's user space to device); false when it paints nothing.
    bool prepare_pattern(const Pattern& p, const Affine& m, float opacity);
    /// A free layer in the target's pixel format, reset to w x h at (x0, y0);
    /// null when it would take the layers in flight over kMaxLayerBytes.
    /// Release in reverse order.
    template <class Target>
    Target* acquire_layer(int w, int h, int x0, int y0);
    template <class Target>
    void release_layer();

    EdgeList edges_;
    Rasterizer raster_;
    GradientShader gradient_shader_;   ///< its color table is reused across shapes
    Stroker stroker_;                  ///< stroke outlines, buffers reused across shapes
    StrokeGeometry hairline_geometry_; ///< a hairline's widened copy of its geometry
    /// Layers in flight, a stack per pixel format; the first layers_used_[f]
    /// of format f (0 float, 1 8-bit) are taken. One count per format: an
    /// 8-bit frame's filter draws its input on float layers, and a shared
    /// count indexed past the float layers there were (regression:
    /// tests/svg/agreement/filter_primitives.svg on the 8-bit canvas).
    std::tuple<std::vector<std::unique_ptr<Canvas>>, std::vector<std::unique_ptr<Canvas8>>> layers_;
    std::array<int, 2> layers_used_{};
    std::size_t layer_bytes_ = 0; ///< the pixels of the layers in flight
    std::size_t layer_budget_ = kMaxLayerBytes;
    std::vector<std::size_t> layer_sizes_; ///< each one's, a stack
    ImageShader image_shader_;             ///< images and pattern tiles
    /// Patterns' tiles: drawn by a renderer of their own, kept for the
    /// frame under their pattern and map (tile_cache.h).
    std::unique_ptr<Renderer> tile_renderer_;
    Canvas tile_canvas_;
    TileCache tiles_{kMaxTilePixels};
    /// A filtered group's layer in float, and its feImage, FillPaint and
    /// StrokePaint drawings: one set per level of filters within filters.
    struct FilterBuffers {
        FilterImage source;
        std::vector<FilterImage> inputs;
        std::vector<FilterImage> pool;     ///< run_filter's intermediate images
        memory_gate::Reservation reserved; ///< what they may grow to, while kept
    };
    std::vector<std::unique_ptr<FilterBuffers>> filter_buffers_;
    std::size_t filter_depth_ = 0;
    Affine view_;
    PixelRect frame_;
    const RenderOptions* options_ = nullptr;
    RenderStats stats_;
};

} // namespace casteljau
