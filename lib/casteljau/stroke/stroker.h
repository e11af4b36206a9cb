// Stroking: a path and a stroke style -> closed outlines whose nonzero fill is
// the stroke (SVG 1.1, 11.4).
//
// Offsets. The outline's sides are the offset curves O(t) = P(t) +- h n(t),
// h = width / 2, n the unit normal, sampled at parameters chosen so that, per
// chord of the samples,
//   (b) the normal turns by at most dphi = 2 acos(1 - tol / (2h)), at most
//       pi/8 (at least 4 samples per quarter turn), and
//   (a) the base curve is within tol - h (1 - cos(dphi/2)) of its chord (the
//       guided flattener's test, flatten/guided.h): tol/2, or more for thin
//       strokes, whose dphi is capped,
// whence the offset curve stays within tol of the offset chord: the offset of
// a point is the base point moved by h along a direction that sweeps at most
// dphi, and a circular arc of angle dphi leaves its chord by
// h (1 - cos(dphi/2)). Normals are exact at every sample:
// the curve is never flattened first and offset after. Where the normal turns
// fast over a vanishing length (a cusp), subdivision stops at a chord of
// tol/64 and the offset sides are joined by a round arc there.
//
// Joins (between segments): on the outer side miter (falling back to bevel
// when the miter ratio 1 / sin(theta/2) exceeds the limit), round (an arc of
// radius h) or bevel; on the inner side the sides are connected through the
// joint itself, which the nonzero rule fills correctly. Caps at the ends of
// open subpaths: butt, round (half disc), square (extends h along the
// tangent). A zero-length subpath draws a disc (round caps), an axis-aligned
// square (square caps) or nothing (butt), as SVG 1.1 implementation notes say.
// Dashes split each subpath at arc lengths measured on a 1e-3 * tol
// flattening (its length error is below 1e-6 relative) before stroking.
//
// Only what can be seen is built. With a `visible` box, the parts of the path
// farther from it than the stroke can reach (h times the miter limit, at
// least sqrt 2 and at most 1e6, plus tol) are left out: solid strokes keep
// the path's segments near the box (lines clipped, curves halved), dashes
// are walked only along chords within reach, and a chord out of reach
// advances the pattern in O(pattern length). So a stroke of a path reaching
// 1e308, or a dashed path 1e9 px long, costs what its visible part costs. At
// most kMaxDashes dash boundaries are walked; beyond, the path's remaining
// dashes are not drawn, which bounds a pattern far finer than a pixel. At
// most kMaxOutlinePoints (2^23) points are built per call: a subpath that
// would take more is not drawn, nor any after it, which bounds the memory
// of round joins on a stroke millions of pixels wide.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/geom/rect.h"
#include "casteljau/scene/scene.h"

#include <memory>
#include <span>
#include <vector>

namespace casteljau {

using Polygon = std::vector<Point>;

/// Builds stroke outlines, keeping every buffer between calls: a renderer
/// stroking path after path allocates nothing once they have grown.
class Stroker {
  public:
    Stroker();
    ~Stroker();
    /// Moves the buffers.
    Stroker(Stroker&&) noexcept;
    /// Moves the buffers.
    Stroker& operator=(Stroker&&) noexcept;

    /// The outline polygons of the stroke (in the path's own coordinates),
    /// valid until the next call. `tolerance` (> 0) and `visible` are in the
    /// same coordinates.
    std::span<const Polygon> outline(const Path& path, const StrokeGeometry& style,
                                     double tolerance, const Rect& visible = Rect::everything());

    /// The buffers (opaque: defined in stroker.cpp).
    struct Buffers;

  private:
    std::unique_ptr<Buffers> b_;
};

/// Appends the outline polygons of the stroke (in the path's own coordinates)
/// to `out`: Stroker::outline with buffers of its own, for one-off use.
void stroke_outline(const Path& path, const StrokeGeometry& style, double tolerance,
                    std::vector<Polygon>& out, const Rect& visible = Rect::everything());

} // namespace casteljau
