// Rendering in horizontal bands on several threads.
//
// The frame is cut into `threads` bands of rows; each thread renders the whole
// scene into its own band canvas with its own Renderer, and the bands are
// copied into the frame. Edge geometry is always clipped to the frame, never
// to a band (see EdgeList), and every pixel is composited by the same shapes
// in the same order, so the result is bit-identical to one thread (tested).
// Flattening is repeated per band for shapes that cross several bands; pieces
// wholly outside a band are culled before flattening.
#pragma once

#include "casteljau/render/renderer.h"

#include <memory>
#include <vector>

namespace casteljau {

class BandRenderer {
  public:
    // Clears `canvas` (origin 0, 0) to `background` and renders `scene` into it.
    // The stats add up the bands' times (CPU time, not wall time) and counts.
    RenderStats render(const Scene& scene, const Affine& view, Canvas& canvas,
                       const RenderOptions& options, Premul background, int threads);

  private:
    std::vector<std::unique_ptr<Renderer>> renderers_;
    std::vector<Canvas> bands_;
};

} // namespace casteljau
