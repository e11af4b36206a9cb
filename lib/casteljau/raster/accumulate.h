// Exact-area coverage accumulation for one scanline (the scheme of libart,
// FreeType's smooth rasterizer and font-rs).
//
// For a row of unit-height pixels and a shape bounded by directed edges, the
// signed coverage of pixel i is c_i = sum over edges of
//     dir * integral over the edge's y-extent in the row of clamp(i + 1 - x(y), 0, 1) dy,
// the area of the pixel lying to the right of the edge, signed by the edge's
// direction; summed over a closed outline this is the integral of the winding
// number over the pixel. The row buffer stores first differences
// acc[i] = c_i - c_{i-1}, so an edge touches only the columns it crosses plus
// one, and a running sum (sweep.h) recovers c_i for the whole row.
//
// Per column i that the edge crosses, with the edge's part in the column
// spanning x in [s0, s1] and height h_i (h / dx per unit of x):
//     c_i = dir * (sum_{j < i} h_j + h_i * (i + 1 - (s0 + s1) / 2)),
// the first term being the full-width coverage of the rows of the edge that
// passed left of the column, the second the trapezoid right of the edge
// inside it; after the last column c = dir * h. Vertical edges are the
// one-column case. The arithmetic is float: coordinates are below 2^14.
//
// Sparse rows. Besides the differences the row keeps one bit per column an
// edge touched, so the sweep visits touched columns only (next_marked): a
// row of a wide shape costs its edges, not its width.
#pragma once

#include "casteljau/raster/edge.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

namespace casteljau {

/// One scanline of area/cover differences: the accumulation stage.
class CoverageRow {
  public:
    /// A zeroed row for `width` pixels; the storage is kept across calls.
    void reset(int width);

    /// Adds a segment lying inside the row: 0 <= ya < yb <= 1 in row-local y,
    /// 0 <= x <= width. `dir` is the edge's winding direction.
    void add_segment(float xa, float ya, float xb, float yb, float dir);

    /// The touched columns are [begin(), end()); empty when begin() >= end().
    int begin() const { return begin_; }
    /// One past the last touched column.
    int end() const { return end_; }
    /// The accumulated differences (width + 2 entries).
    float* data() { return acc_.data(); }
    /// Row width in pixels.
    int width() const { return width_; }
    /// Forgets the touched columns after a sweep has zeroed them.
    void clear_range();
    /// The first touched column in [j, end), or `end` when there is none.
    int next_marked(int j, int end) const {
        if (j >= end) return end;
        std::size_t w = std::size_t(j) >> 6;
        std::uint64_t bits = marks_[w] & (~std::uint64_t(0) << (j & 63));
        while (bits == 0) {
            if (int(++w << 6) >= end) return end;
            bits = marks_[w];
        }
        return std::min(end, int(w << 6) + std::countr_zero(bits));
    }

  private:
    void touch(int i0, int i1);
    std::vector<float> acc_; ///< width + 2 entries: an edge at x = width writes acc[width + 1]
    std::vector<std::uint64_t> marks_; ///< bit i: column i was touched since the last sweep
    int width_ = 0, begin_ = 0, end_ = 0;
};

} // namespace casteljau
