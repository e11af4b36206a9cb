// Edge building: device-space line segments -> clipped, y-ordered edges.
//
// An Edge runs downwards (y0 < y1) and remembers its original direction as
// `dir` (+1 when the segment went down, -1 when it went up): the winding
// contribution. Horizontal segments contribute nothing and are dropped.
//
// Clipping to the clip rectangle [x0, x1] x [y0, y1] keeps the coverage exact:
// * y: the part above y0 or below y1 is cut off (it covers no row).
// * x: the part left of x0 is replaced by its projection onto x = x0 (a
//   vertical edge at the left border: it still changes the winding of every
//   pixel to its right, and a vertical edge on the border covers no pixel area
//   itself), and the part right of x1 by its projection onto x = x1 (it
//   changes nothing visible). Segments are split where they cross the borders
//   so that the projected part is exactly the part outside.
// Coordinates stay absolute (device pixels of the whole frame). A band of
// rows [row_begin, row_end) may be asked for: segments entirely outside it
// are dropped, and the others are stored exactly as without the band, so
// rendering in bands gives the same bits as rendering whole.
// Coordinates are double on input and float after clipping: clipped values lie
// in [0, 16384], where float resolves 2^-10 px, far below 1/255 coverage.
#pragma once

#include "casteljau/geom/point.h"

#include <algorithm>
#include <utility>
#include <vector>

namespace casteljau {

/// Pixels [x0, x1) x [y0, y1).
struct PixelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    /// Number of columns.
    int width() const { return x1 - x0; }
    /// Number of rows.
    int height() const { return y1 - y0; }
    /// Whether it holds no pixel.
    bool is_empty() const { return x1 <= x0 || y1 <= y0; }
    /// The pixels in both (possibly empty).
    PixelRect intersected(const PixelRect& r) const {
        return {std::max(x0, r.x0), std::max(y0, r.y0), std::min(x1, r.x1), std::min(y1, r.y1)};
    }
    /// The smallest rectangle holding both; an empty one adds nothing.
    PixelRect united(const PixelRect& r) const {
        if (r.is_empty()) return *this;
        if (is_empty()) return r;
        return {std::min(x0, r.x0), std::min(y0, r.y0), std::max(x1, r.x1), std::max(y1, r.y1)};
    }
};

/// A clipped, directed line segment in device pixels, top to bottom.
struct Edge {
    float x0, y0, x1, y1; ///< y0 < y1
    float dir;            ///< +1 or -1
};

/// Edge building: device-space segments clipped into edges, kept across paths.
class EdgeList {
  public:
    /// Starts a new list clipped to `clip`, for the rows [row_begin, row_end);
    /// keeps the storage.
    void reset(PixelRect clip, int row_begin, int row_end);
    /// Starts a new list for a width x height canvas (all rows).
    void reset(int width, int height) { reset({0, 0, width, height}, 0, height); }
    /// Frees the storage (the edges are gone).
    void release() { edges_ = std::vector<Edge>(); }
    /// Adds the segment a -> b, clipped. Precondition: finite coordinates.
    /// Inline for the common case, a segment inside the clip, as every
    /// flattened vertex of a shape on the canvas adds one.
    void add_line(Point a, Point b) {
        if (a.y == b.y) return;
        const float dir = a.y < b.y ? 1.0f : -1.0f;
        if (a.y > b.y) std::swap(a, b);
        // Outside the band: dropped, before any arithmetic that could differ.
        if (b.y <= row_begin_ || a.y >= row_end_) return;
        if (clip_.y0 <= a.y && b.y <= clip_.y1 && std::min(a.x, b.x) >= clip_.x0 &&
            std::max(a.x, b.x) <= clip_.x1) {
            push(a.x, a.y, b.x, b.y, dir); // what add_clipped's cuts would give
            return;
        }
        add_clipped(a, b, dir);
    }

    /// The edges added so far.
    const std::vector<Edge>& edges() const { return edges_; }
    /// The clip rectangle.
    const PixelRect& clip() const { return clip_; }
    /// First row the edges are built for.
    int row_begin() const { return row_begin_; }
    /// One past the last row the edges are built for.
    int row_end() const { return row_end_; }

  private:
    /// add_line's segment, a.y < b.y, crossing the clip's border.
    void add_clipped(Point a, Point b, float dir);
    void push(double x0, double y0, double x1, double y1, float dir) {
        const float fy0 = float(y0), fy1 = float(y1);
        if (fy0 < fy1) edges_.push_back({float(x0), fy0, float(x1), fy1, dir});
    }

    std::vector<Edge> edges_;
    PixelRect clip_;
    int row_begin_ = 0, row_end_ = 0;
};

} // namespace casteljau
