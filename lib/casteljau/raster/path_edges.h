// Edge building for whole paths: flatten + clip, with curves culled against
// the canvas before they are flattened.
//
// A curve is flattened only where it can matter. Its control box (which holds
// the curve) is tested against the canvas first:
// * above, below or right of the canvas: dropped; it covers nothing visible
//   (right of it, its winding only affects pixels beyond the canvas);
// * left of the canvas: replaced by its chord, which has the same net crossing
//   of every row (curve minus chord is a closed loop left of every pixel, so
//   it adds no winding there); the edge list projects it onto x = 0;
// * crossing the canvas and much larger than it: halved by de Casteljau (an
//   explicit stack, at most kCullDepth levels) and each half tested again;
// * otherwise: flattened with the given options.
// So a circle of radius 1e7 px mostly off the canvas costs a few dozen splits
// plus the flattening of the pieces that cross the canvas, and coordinates up
// to 1e9 px stay exact in double until the clipped edges are stored. Only
// pieces near the canvas are ever flattened, so the flattener never sees
// coordinates far beyond it. A piece still larger than 4 canvas sizes after
// kCullDepth halvings (a curve over 2^40 times the canvas, up to 1e308 px) is
// drawn as its chord: flattening it would square coordinates past the double
// range, and no image could show the difference at that scale anyway.
// A path whose whole control box lies inside the canvas and the band of rows
// asked for skips the tests: every curve of it would be flattened whole.
//
// Filling closes every subpath (SVG 1.1, 11.3): an open subpath gets the
// closing line from its last point to its start.
#pragma once

#include "casteljau/curve/path.h"
#include "casteljau/flatten/flatten.h"
#include "casteljau/flatten/path_flatten.h"
#include "casteljau/raster/edge.h"

namespace casteljau {

/// Adds the filled outline of `path` under `to_device` to `edges` (whose canvas
/// size is set). With `measure_error` the exact error measure of every
/// flattened piece is folded into the returned stats (for --stats; slow).
FlattenStats add_path_edges(const Path& path, const Affine& to_device,
                            const FlattenOptions& options, EdgeList& edges,
                            bool measure_error = false);

} // namespace casteljau
