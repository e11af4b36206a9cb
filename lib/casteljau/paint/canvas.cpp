#include "casteljau/paint/canvas.h"

#include <algorithm>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace casteljau {

namespace {

// Opaque runs at least this long (16 KB) are stored past the cache: a fill
// that wide is mostly not drawn over again while still cached, and a plain
// store first reads each line it writes (read for ownership), doubling the
// memory traffic. Shorter runs stay in the cache for the shapes drawn on top.
constexpr int kStreamRun = 1024;

// d[0, n) = c.
void store_run(Premul* d, int n, Premul c) {
#if defined(__SSE2__)
    if (n >= kStreamRun) {
        const __m128 v = _mm_setr_ps(c.r, c.g, c.b, c.a);
        int i = 0;
        // Pixels are 16 bytes, float-aligned: stream from the first 16-byte aligned one.
        for (; i < n && (reinterpret_cast<std::uintptr_t>(d + i) & 15) != 0; ++i) d[i] = c;
        for (; i < n; ++i) _mm_stream_ps(reinterpret_cast<float*>(d + i), v);
        return;
    }
#endif
    std::fill(d, d + n, c);
}

} // namespace

Canvas::Canvas(int width, int height, int ox, int oy) { reset(width, height, ox, oy); }

void Canvas::reset(int width, int height, int ox, int oy, Premul clear) {
    w_ = width, h_ = height, ox_ = ox, oy_ = oy;
    view_ = nullptr;
    stale_.clear();
    px_.assign(std::size_t(width) * std::size_t(height), clear);
}

void Canvas::view_rows(Canvas& parent, int y0, int rows, Premul clear) {
    w_ = parent.w_, h_ = rows, ox_ = parent.ox_, oy_ = parent.oy_ + y0;
    view_ = parent.row(y0);
    stale_.assign(std::size_t(rows), 1);
    clear_ = clear;
}

void Canvas::settle() {
    for (int y = 0; y < int(stale_.size()); ++y) row(y);
#if defined(__SSE2__)
    _mm_sfence(); // streamed stores (store_run) are visible before the band is handed on
#endif
}

void Canvas::clear_row_except(Premul* r, int y, int x0, int x1) {
    std::fill(r, r + x0, clear_);
    std::fill(r + std::max(x0, x1), r + w_, clear_);
    stale_[std::size_t(y)] = 0;
}

void Canvas::fill(Premul color) {
    Premul* p = pixels();
    std::fill(p, p + std::size_t(w_) * std::size_t(h_), color);
    std::fill(stale_.begin(), stale_.end(), 0);
}

void Canvas::store_span(int y, int x, int len, const Premul& c) {
    store_run(row_except(y, x, x + len) + x, len, c);
}

void Canvas::composite_layer(const Canvas& layer, float opacity) {
    const int dx = layer.ox_ - ox_, dy = layer.oy_ - oy_;
    const int x0 = std::max(0, dx), x1 = std::min(w_, dx + layer.w_);
    const int y0 = std::max(0, dy), y1 = std::min(h_, dy + layer.h_);
    for (int y = y0; y < y1; ++y) {
        const Premul* s = layer.row(y - dy) + (x0 - dx);
        Premul* d = row(y) + x0;
        for (int i = 0; i < x1 - x0; ++i) {
            blend_over(d[i], s[i], opacity);
        }
    }
}

} // namespace casteljau
