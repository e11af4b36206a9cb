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
    /// The accumulated differences (width + 3 entries).
    float* data() { return acc_.data(); }
    /// Row width in pixels.
    int width() const { return width_; }
    /// Forgets the touched columns after a sweep has zeroed them.
    void clear_range();
    /// The first touched column in [j, end), or `end` when there is none.
    int next_marked(int j, int end) const { return next_bit(j, end, 0); }
    /// The first untouched column in [j, end), or `end` when there is none.
    int next_unmarked(int j, int end) const { return next_bit(j, end, ~std::uint64_t(0)); }

  private:
    // The first column in [j, end) whose mark differs from `flip`'s bits (0:
    // the first marked one; all ones: the first unmarked one).
    int next_bit(int j, int end, std::uint64_t flip) const {
        if (j >= end) return end;
        std::size_t w = std::size_t(j) >> 6;
        std::uint64_t bits = (marks_[w] ^ flip) & (~std::uint64_t(0) << (j & 63));
        while (bits == 0) {
            if (int(++w << 6) >= end) return end;
            bits = marks_[w] ^ flip;
        }
        return std::min(end, int(w << 6) + std::countr_zero(bits));
    }
    void touch(int i0, int i1);
    std::vector<float>
        acc_; ///< width + 3 entries: an edge at x = width writes up to acc[width + 2]
    std::vector<std::uint64_t> marks_; ///< bit i: column i was touched since the last sweep
    int width_ = 0, begin_ = 0, end_ = 0;
};

// Inline: the rasterizer calls these once per edge or row, on rows of a few
// columns, where a call costs as much as the work.
inline void CoverageRow::touch(int i0, int i1) {
    begin_ = std::min(begin_, i0);
    end_ = std::max(end_, i1);
    // Bits [i0, i1): the words' masks from the first bit and to the last one.
    // An edge usually touches a few columns, within one word.
    constexpr std::uint64_t kOnes = ~std::uint64_t(0);
    const std::size_t w0 = std::size_t(i0) >> 6, w1 = std::size_t(i1 - 1) >> 6;
    const std::uint64_t from = kOnes << (i0 & 63), to = kOnes >> (63 - ((i1 - 1) & 63));
    if (w0 == w1) {
        marks_[w0] |= from & to;
        return;
    }
    marks_[w0] |= from;
    for (std::size_t w = w0 + 1; w < w1; ++w) marks_[w] = kOnes;
    marks_[w1] |= to;
}

inline void CoverageRow::clear_range() {
    if (begin_ < end_)
        for (std::size_t w = std::size_t(begin_) >> 6; w <= std::size_t(end_ - 1) >> 6; ++w)
            marks_[w] = 0;
    begin_ = width_ + 1, end_ = 0;
}

inline void CoverageRow::add_segment(float xa, float ya, float xb, float yb, float dir) {
    const float h = (yb - ya) * dir;
    const float x_left = std::min(xa, xb), x_right = std::max(xa, xb);
    const int first = std::min(int(x_left), width_), last = std::min(int(x_right), width_);
    if (last - first <= 1) {
        // At most two columns (every steep edge): the loop below in closed
        // form, without its branches, which mispredicted on whether an
        // edge's row crosses a column border (12% of the accumulation's
        // samples in the tiger's profile). The edge's part left of
        // x = first + 1 has height h0, the rest h1. An edge within one
        // column (h1 = 0, c1 = h) adds an exact 0 to the third, which stays
        // unmarked, as in the loop.
        const float mid = std::min(float(first + 1), x_right);
        const float dx = x_right - x_left;
        const float h0 = dx > 0 ? h * ((mid - x_left) / dx) : h, h1 = h - h0;
        const float c0 = h0 * (float(first + 1) - 0.5f * (x_left + mid));
        const float c1 = h0 + h1 * (float(first + 2) - 0.5f * (mid + x_right));
        float* a = acc_.data() + first;
        a[0] += c0;
        a[1] += c1 - c0;
        a[2] += h - c1;
        touch(first, last + 2);
        return;
    }
    const float h_per_x = h / (x_right - x_left);
    float passed = 0, prev = 0; // sum of h_j for j < i; c_{i-1}
    for (int i = first; i <= last; ++i) {
        const float s0 = std::max(x_left, float(i)), s1 = std::min(x_right, float(i + 1));
        const float hi = (s1 - s0) * h_per_x;
        const float c = passed + hi * (float(i + 1) - 0.5f * (s0 + s1));
        acc_[std::size_t(i)] += c - prev;
        prev = c;
        passed += hi;
    }
    acc_[std::size_t(last) + 1] += h - prev;
    touch(first, last + 2);
}

} // namespace casteljau
