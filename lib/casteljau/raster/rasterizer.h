// The scanline driver: edges -> per-row accumulation -> sweep -> spans.
//
// Edges are sorted by their first row once (mostly a counting sort); rows
// are visited top to bottom, in strips of kStripRows, with an active list of
// the edges crossing the strip, and rows without edges are skipped, so the
// cost is O(E + R + sum over rows of (active edges + swept columns)), R the
// rows from the first edge's top to the last's within the band: it grows
// with the outline and the covered spans, never with the canvas area. All
// buffers are kept between calls.
//
// Antialiased mode deposits exact areas (accumulate.h), except for a
// rectangle's two vertical edges, whose areas are products (box.h). Aliased mode samples
// each pixel at its centre: a pixel is inside when the fill rule holds for the
// winding number at (x + 1/2, y + 1/2), found by crossing the row's centre line
// with the edges; its spans have coverage 1.
#pragma once

#include "casteljau/raster/accumulate.h"
#include "casteljau/raster/edge.h"
#include "casteljau/raster/span.h"
#include "casteljau/raster/sweep.h"

#include <array>
#include <cstdint>
#include <vector>

namespace casteljau {

/// The scanline driver: edges to spans, with all buffers kept between calls.
class Rasterizer {
  public:
    /// Emits the spans of the rows [edges.row_begin(), edges.row_end()), in the
    /// clip rectangle's columns, in absolute pixel coordinates.
    void fill(const EdgeList& edges, FillRule rule, bool antialias, SpanSink& sink);
    /// Frees the buffers that grow with the edges (those that grow with the
    /// width stay).
    void release() {
        keys_ = std::vector<std::uint64_t>(), row_start_ = std::vector<std::uint32_t>();
        sorted_ = std::vector<Active>(), active_ = std::vector<Active>();
        crossings_ = std::vector<Crossing>();
    }

  private:
    struct Active {
        float x0, y0, y1, dxdy, dir;
    };
    struct Crossing {
        float x, dir;
    };
    /// Rows per pass over the active edges (antialiased). Tiger frames
    /// (cairo_compare_bench, 8-bit): 0.39-0.40x Cairo at 4 rows, 0.37-0.38 at
    /// 16 and 32, 0.44 at 1 (a pass per row); 16 rows' buffers are 64 KB at
    /// 1024 px, which the second-level cache holds.
    static constexpr int kStripRows = 16;
    void strip_antialiased(int y0, int y1);
    void row_aliased(int y, FillRule rule, SpanSink& sink);

    /// Fills sorted_ from the edges, in the order every band agrees on.
    void sort_edges(const std::vector<Edge>& list, int top);

    std::vector<std::uint64_t> keys_;      ///< the sort's, edges from above: row, then index
    std::vector<std::uint32_t> row_start_; ///< the sort's, other edges: per row, where they go
    std::vector<Active> sorted_, active_;
    std::vector<Crossing> crossings_;
    std::vector<float> coverage_;
    std::array<CoverageRow, kStripRows> rows_; ///< the strip's rows, in order
    int width_ = 0, x0_ = 0;
};

} // namespace casteljau
