#include "casteljau/raster/rasterizer.h"

#include "casteljau/raster/box.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>

namespace casteljau {

// Edges in order of their first row, then of addition. Any two edges then
// meet a row in the same order whichever subset of the outline a band or
// tile holds, so the rows' float sums, and the pixels, are the same bit for
// bit. Edges that start above the pass's first row `top` (those crossing
// into a band) come first, by a comparison sort on (row, index): they are
// few, one per crossing of the outline with the band's top. The others by a
// stable counting sort over the rows they start in, which lie in the band.
// (A comparison sort of all edges by y0 took 12% of the mispredicted branches
// of the thin-stroke scene, cachegrind; rows need no finer order.)
// Clipped y0 >= 0 (edge.h), so int() is the floor.
void Rasterizer::sort_edges(const std::vector<Edge>& list, int top) {
    keys_.clear();
    int first_row = INT_MAX, last_row = top;
    for (std::uint32_t i = 0; i < list.size(); ++i) {
        const int row = int(list[i].y0);
        if (row < top) {
            keys_.push_back(std::uint64_t(row) << 32 | i);
        } else {
            first_row = std::min(first_row, row);
            last_row = std::max(last_row, row);
        }
    }
    std::sort(keys_.begin(), keys_.end());
    if (first_row > last_row) first_row = last_row; // every edge starts above `top`
    // row_start_[r - first_row + 1] counts the edges of row r, then becomes
    // the prefix sum after the edges from above: where row r's edges go.
    row_start_.assign(std::size_t(last_row - first_row) + 2, 0);
    row_start_[0] = std::uint32_t(keys_.size());
    for (const Edge& e : list)
        if (int(e.y0) >= top) ++row_start_[std::size_t(int(e.y0) - first_row) + 1];
    for (std::size_t r = 1; r < row_start_.size(); ++r) row_start_[r] += row_start_[r - 1];
    const auto to_active = [&](const Edge& e) -> Active {
        return {e.x0 - float(x0_), e.y0, e.y1, (e.x1 - e.x0) / (e.y1 - e.y0), e.dir};
    };
    sorted_.resize(list.size());
    for (std::size_t k = 0; k < keys_.size(); ++k)
        sorted_[k] = to_active(list[std::uint32_t(keys_[k])]);
    for (const Edge& e : list)
        if (int(e.y0) >= top)
            sorted_[row_start_[std::size_t(int(e.y0) - first_row)]++] = to_active(e);
}

void Rasterizer::fill(const EdgeList& edges, FillRule rule, bool antialias, SpanSink& sink) {
    width_ = edges.clip().width();
    x0_ = edges.clip().x0;
    const int row_end = edges.row_end();
    const std::vector<Edge>& list = edges.edges();
    if (list.empty() || width_ <= 0) return;
    if (antialias && fill_box(edges, sink)) return;
    sort_edges(list, edges.row_begin());
    if (antialias && rows_[0].width() != width_)
        for (CoverageRow& row : rows_) row.reset(width_);
    active_.clear();
    std::size_t next = 0;
    int y = std::max(edges.row_begin(), int(sorted_[0].y0));
    while (y < row_end && (next < sorted_.size() || !active_.empty())) {
        if (active_.empty()) { // skip empty rows, but never past the band
            y = std::max(y, int(sorted_[next].y0));
            if (y >= row_end) break;
        }
        const int strip_end = std::min(row_end, y + kStripRows);
        const float bottom = float(strip_end);
        while (next < sorted_.size() && sorted_[next].y0 < bottom)
            active_.push_back(sorted_[next++]);
        if (antialias) {
            strip_antialiased(y, strip_end);
            for (int r = y; r < strip_end; ++r)
                sweep_row(rows_[std::size_t(r - y)], r, x0_, rule, coverage_, sink);
        } else {
            for (int r = y; r < strip_end; ++r) row_aliased(r, rule, sink);
        }
        // Retire edges that end in this strip.
        std::erase_if(active_, [bottom](const Active& a) { return a.y1 <= bottom; });
        y = strip_end;
    }
}

// Each active edge deposits its part of every row of the strip in turn: the
// edge's fields stay in registers and its rows' branches follow its slope,
// where a pass over the active list per row reloaded every edge per row and
// mispredicted between edges of different slopes. Each row still receives
// the edges' deposits in the active list's order, with the arithmetic of a
// row at a time, so its sums are the same bit for bit.
void Rasterizer::strip_antialiased(int y0, int y1) {
    const float w = float(width_);
    for (const Active& a : active_) {
        const int first = std::max(y0, int(a.y0)), last = std::min(y1, int(std::ceil(a.y1)));
        // Every row in [floor y0, ceil y1) meets the edge (ya < yb): an active
        // edge ends below the strip's top (it is retired otherwise).
        for (int y = first; y < last; ++y) {
            const float top = float(y), bottom = float(y + 1);
            const float ya = std::max(a.y0, top), yb = std::min(a.y1, bottom);
            const float xa = a.x0 + (ya - a.y0) * a.dxdy, xb = a.x0 + (yb - a.y0) * a.dxdy;
            rows_[std::size_t(y - y0)].add_segment(std::clamp(xa, 0.0f, w), ya - top,
                                                   std::clamp(xb, 0.0f, w), yb - top, a.dir);
        }
    }
}

void Rasterizer::row_aliased(int y, FillRule rule, SpanSink& sink) {
    const float yc = float(y) + 0.5f;
    crossings_.clear();
    for (const Active& a : active_)
        if (a.y0 <= yc && yc < a.y1) crossings_.push_back({a.x0 + (yc - a.y0) * a.dxdy, a.dir});
    std::sort(crossings_.begin(), crossings_.end(),
              [](const Crossing& a, const Crossing& b) { return a.x < b.x; });
    float winding = 0;
    for (std::size_t i = 0; i < crossings_.size(); ++i) {
        winding += crossings_[i].dir;
        if (apply_fill_rule(winding, rule) < 0.5f) continue;
        // Pixels whose centre x + 1/2 lies in [x_i, x_{i+1}); past the last
        // crossing (an outline culled at the right border) up to the row's end.
        const float next = i + 1 < crossings_.size() ? crossings_[i + 1].x : float(width_) + 1.0f;
        const int x0 = std::max(0, int(std::ceil(crossings_[i].x - 0.5f)));
        const int x1 = std::min(width_, int(std::ceil(next - 0.5f)));
        if (x1 > x0) sink.span({y, x0_ + x0, x1 - x0, nullptr, 1.0f});
    }
}

} // namespace casteljau
