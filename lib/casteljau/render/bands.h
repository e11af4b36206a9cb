// Rendering in horizontal bands, on one thread or several.
//
// The frame is cut into bands of kBandRows rows, which the threads take one
// at a time as they finish the last; on several threads, the last bands
// (one per thread) are taken in halves, so that a thread slowed down near
// the end keeps the others waiting for at most half a band. The threads are
// a WorkerPool's, kept from frame to frame. A thread renders the whole scene
// into each of its bands with its own Renderer, in place (the band canvas is
// a view of the frame's rows, Canvas::view_rows, whose rows are cleared to
// the background as they are first written, and settled when the band is
// done). Bands pay even on one thread: a band (kBandRows x width x 16 bytes
// of float, 4 of Canvas8) stays in cache while every shape crossing it is
// composited, where a whole frame would not (measured in bench/render).
// Edge geometry is always clipped to the frame, never to a band (see
// EdgeList), and every pixel is composited by the same shapes in the same
// order, so the result is bit-identical to one thread (tested).
// Flattening is repeated per band for shapes that cross several bands; pieces
// wholly outside a band are culled before flattening. The scene's top-level
// nodes are sorted into the bands they reach once per frame
// (Renderer::node_reach_box), so a band visits only those: a node outside a
// band changes none of its pixels, so leaving it out changes no bit.
#pragma once

#include "casteljau/render/renderer.h"
#include "casteljau/render/worker_pool.h"

#include <memory>
#include <tuple>
#include <vector>

namespace casteljau {

/// 128 rows of a 1024 px wide frame are 2 MiB of float RGBA, about a mid-level
/// cache; 64 and 256 measured slower on the dense scene (bench/render).
inline constexpr int kBandRows = 128;
static_assert(kBandRows % kStrokeStripRows == 0, "a band is whole stroke strips");

/// Renders a frame in horizontal bands, on one thread or several, bit-identically.
class BandRenderer {
  public:
    /// Clears `canvas` (origin 0, 0; a Canvas or a Canvas8) to `background`
    /// and renders `scene` into it. The stats add up the bands' times (CPU
    /// time, not wall time) and counts.
    template <class Pixel>
    RenderStats render(const Scene& scene, const Affine& view, BasicCanvas<Pixel>& canvas,
                       const RenderOptions& options, Premul background, int threads);

  private:
    /// Puts each of the root's children into the list of every band it reaches.
    void sort_into_bands(const Scene& scene, const Affine& view, int height, int bands);

    std::vector<std::unique_ptr<Renderer>> renderers_;
    std::vector<std::vector<const Node*>> band_nodes_;            ///< per band, kept between frames
    std::tuple<std::vector<Canvas>, std::vector<Canvas8>> bands_; ///< per thread, per format
    std::vector<RenderStats> stats_;   ///< per thread, kept between frames
    std::unique_ptr<WorkerPool> pool_; ///< made on the first frame on several threads
};

} // namespace casteljau
