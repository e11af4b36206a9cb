// Stroking: a path and a stroke style -> closed outlines whose nonzero fill is
// the stroke (SVG 1.1, 11.4).
//
// Offsets. The outline's sides are the offset curves O(t) = P(t) +- h n(t),
// h = width / 2, n the unit normal, sampled at parameters chosen so that, per
// chord of the samples,
//   (b) the normal turns by at most dphi = 2 acos(1 - tol / (2h)), at most
//       pi/8 (at least 4 samples per quarter turn), over the whole piece
//       between the samples, not only from one end to the other: every
//       tangent of the piece lies in the cone of its control polygon's legs,
//       and the legs must lie within dphi of each other (a normal that swings
//       away and back between two samples with the same normal, as on the
//       curve below, drew a band 0.7x as wide as the stroke), and
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
// End tangents. A handle (a control point next to an end point) shorter
// than tol/64 is collapsed onto its end point before the segment is
// sampled, so the tangent there, which caps and joins take, points to the
// next control point farther than tol/64 from that end (to the other end if
// none is). tol is in device pixels (the renderer passes its tolerance in
// user units), so the threshold is 1/256 px at the default 0.25 px. On
// M30 150 C 30.0001 150 150 30 150.0001 30 the exact tangent at each end is
// +x and turns to the chord's 45 degrees within t ~ 1e-6, and the exact
// offset ends in a cap square to +x and a 45-degree wedge of radius h: a
// change of size h in the drawing from handles 1e-4 px long, which Cairo,
// Skia and resvg do not draw (they draw a straight band with square caps).
// Why tol/64: it is the chord below which (b) already leaves the normal's
// turns unresolved (rounded as a cusp), and a handle that short steers the
// normal over about as short a stretch of curve; at the default tolerance it
// is the grid of Cairo's 24.8 fixed point, where a handle under about 1/512
// px is zero and the next distinct control point gives the tangent. (Skia
// and tiny-skia, which resvg uses, take the next point only for a handle of
// exactly zero, but stroke a cubic whose inner control points lie within
// 0.3% of its size of the line through its outer ones as a line: a rule in
// the curve's size, not in pixels.) The collapsed curve is within tol/64 of
// the given one (the moved points' Bernstein weights sum to at most 1), and
// (a) is held to tol/64 less on it, so its outline is within tol of the
// given curve's stroke but for the unresolved turns at its ends. Below
// 0.0064 px of tolerance the example's handles are kept, and its wedges drawn.
//
// Joins (between segments): on the outer side miter (falling back to bevel
// when the miter ratio 1 / sin(theta/2) exceeds the limit), round (an arc of
// radius h) or bevel. On the inner side the two offsets cross, at X (for
// lines h / cos(turn/2) from the joint p, h tan(turn/2) along each segment
// from it), and the side is cut there: ..., X, ... . Between X and p the two
// segments' bands overlap, and a side through the joint, ..., A, p, B, ...
// (A and B the offsets at p), goes round that overlap a second time:
// winding 2, which nonzero fills right, but which exact-area coverage, the
// winding integrated over a pixel and then clamped to 1, counts twice in a
// pixel that holds winding 0 too. At an inner corner on a pixel's centre,
// the stroke covers 3/4 of the pixel and the rasterizer gave it 1
// (M5 5 H75 V75, 1 px wide, at (74,5); librsvg gives 3/4). X is searched
// on kMeetEdges edges of each offset next to the joint, nearest first, and
// taken when the offsets it cuts off lie in the other segment's band (within
// h + tol of it): where they cross only farther on (the path coming back
// across itself), the loop they close goes round a hole of the stroke.
// Where there is none (a segment shorter than h tan(turn/2), a turn back by
// nearly 180 degrees) the side goes through the joint. Such pixels, and
// those where other parts of a stroke overlap (the path crossing itself,
// dashes meeting at a corner, the inner offset of a curve folding where its
// radius of curvature is below h), keep the approximate coverage. Caps at
// the ends of open subpaths: butt, round (half disc), square (extends h
// along the tangent). A zero-length subpath draws a disc (round caps), an
// axis-aligned square (square caps) or nothing (butt), as SVG 1.1
// implementation notes say. Dashes split each subpath at arc lengths
// measured on a 1e-3 * tol flattening (its length error is below 1e-6
// relative) before stroking; on a closed subpath, a dash through its start
// goes on through the closing join (as Cairo and Skia draw it), without caps.
//
// Only what can be seen is built. With a `visible` box, the parts of the path
// farther from it than the stroke can reach (h times the miter limit, at least
// sqrt 2 and at most 1e6, plus tol) are left out: solid strokes keep the path's
// segments near the box (lines clipped, curves halved; a closed subpath cut so
// keeps its closing join), dashes are walked only along chords within reach,
// and a chord out of reach advances the pattern in O(pattern length). So a
// stroke of a path reaching 1e308, or a dashed path 1e9 px long, costs what its
// visible part costs. At most kMaxDashes dash boundaries are walked; beyond,
// the path is stroked solid (as Skia does past a million dashes), which
// bounds a pattern far finer than a pixel. At most kMaxOutlinePoints (2^23)
// points are built per call: a subpath that would take more is not drawn,
// nor any after it, which bounds the memory of round joins on a stroke
// millions of pixels wide, and of curves sampled past what could fit (a
// segment's samples stop there; after such a subpath the working buffers are
// freed rather than kept for the next call).
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
    /// valid until the next call. `tolerance` and `visible` are in the same
    /// coordinates; a tolerance that is not finite and > 0 gives no polygons.
    std::span<const Polygon> outline(const Path& path, const StrokeGeometry& style,
                                     double tolerance, const Rect& visible = Rect::everything());

    /// Where the working buffers reserve what they grow to, past 1.3 MB
    /// (stroker.cpp, kUnreserved: 80 bytes an element of the largest), kept
    /// while the buffers are: reserve(bytes) takes them, or refuses, and
    /// outline() then grows on unreserved; unreserve gives back. A renderer
    /// passes render/memory_gate.h's, whose reserve enters the gate when it
    /// refuses. nullptr for both (the default): nothing is counted.
    void set_memory_budget(bool (*reserve)(std::size_t), void (*unreserve)(std::size_t));

    /// Frees every buffer, the last outline's polygons too, and gives back
    /// the reservation.
    void release();

    /// The bytes reserved (0 when the buffers are below the reservation's
    /// threshold, or no budget is set).
    std::size_t reserved() const;

    /// The buffers (opaque: defined in stroker.cpp).
    struct Buffers;

  private:
    std::span<const Polygon> outline_scaled(const Path& path, const StrokeGeometry& style,
                                            double tolerance, const Rect& visible, double size);
    std::unique_ptr<Buffers> b_;
};

/// Appends the outline polygons of the stroke (in the path's own coordinates)
/// to `out`: Stroker::outline with buffers of its own, for one-off use.
void stroke_outline(const Path& path, const StrokeGeometry& style, double tolerance,
                    std::vector<Polygon>& out, const Rect& visible = Rect::everything());

} // namespace casteljau
