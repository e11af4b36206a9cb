// Axis-aligned rectangles: coverage as a product of overlaps, without the
// accumulation and the sweep.
//
// A rectangle [xl, xr] x [yt, yb] covers pixel (i, y) by exactly
//     (min(xr, i + 1) - max(xl, i)) * (min(yb, y + 1) - max(yt, y)),
// both factors clamped at 0: the area the accumulation (accumulate.h) would
// deposit and the sweep sum up, computed directly. Each row is then at most a
// partial column, one run of constant coverage and another partial column, so
// a backdrop, a bar of a chart or a full-canvas fill costs a store per pixel
// and a few spans per row, as pixman's box fills do for Cairo.
//
// Such a shape reaches the rasterizer as two vertical edges of opposite
// directions over the same rows: edge building drops the horizontal sides and
// projects sides outside the clip onto its borders (edge.h). Its winding is
// +-1 inside and 0 outside, where both fill rules agree. The coverage can
// differ from the sweep's by the float rounding of the running sum (~1e-7),
// and is the same in every band or tile: it depends on the pixel and the
// edges only.
#pragma once

#include "casteljau/raster/edge.h"
#include "casteljau/raster/span.h"

namespace casteljau {

/// Emits the spans of the rows [edges.row_begin(), edges.row_end()) of the
/// rectangle that `edges` hold, antialiased, and returns true; returns false,
/// emitting nothing, when they are not two vertical edges of opposite
/// directions over the same rows.
bool fill_box(const EdgeList& edges, SpanSink& sink);

} // namespace casteljau
