#include "casteljau/paint/canvas.h"

#include "casteljau/paint/fill_run.h"

#include <algorithm>
#include <cstdint>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace casteljau {

namespace {

// d[0, n) = c, through the cache.
void fill_run(Premul* d, int n, const Premul& c) { std::fill(d, d + n, c); }

// Opaque float runs of at least this many bytes (1024 pixels) are stored
// past the cache: a fill that wide is mostly not drawn over again while
// still cached, and a plain store first reads each line it writes (read for
// ownership), doubling the memory traffic. Shorter runs stay in the cache
// for the shapes drawn on top.
constexpr int kStreamBytes = 16384;

// d[0, n) = c for an opaque span: past the cache when long.
void store_run(Premul* d, int n, const Premul& c) {
#if defined(__SSE2__)
    if (n * int(sizeof c) >= kStreamBytes) {
        const __m128 v = _mm_setr_ps(c.r, c.g, c.b, c.a);
        // A whole 64-byte cache line per iteration, from the first line
        // boundary: the write-combining buffer fills a line and writes it
        // out whole. (One pixel per iteration ran at 55% of the speed in a
        // build where the loop straddled a 64-byte code boundary: 4.8 ms
        // against 2.6 for the 64 MiB fill.)
        int i = 0;
        for (; i < n && (reinterpret_cast<std::uintptr_t>(d + i) & 63) != 0; ++i) d[i] = c;
        for (; i + 4 <= n; i += 4) {
            auto* line = reinterpret_cast<float*>(d + i);
            _mm_stream_ps(line, v);
            _mm_stream_ps(line + 4, v);
            _mm_stream_ps(line + 8, v);
            _mm_stream_ps(line + 12, v);
        }
        std::fill(d + i, d + n, c);
        return;
    }
#endif
    fill_run(d, n, c);
}

// 8-bit opaque spans stay in the cache: the rows of a 2048 x 2048 frame are
// 8 KB and the frame 16 MiB, which the last-level cache holds; streaming
// them measured slower (0.68 against 0.57 ms for the full-canvas fill).
void store_run(Premul8* d, int n, Premul8 c) { fill_run(d, n, c); }

} // namespace

template <class Pixel>
BasicCanvas<Pixel>::BasicCanvas(int width, int height, int ox, int oy) {
    reset(width, height, ox, oy);
}

template <class Pixel>
void BasicCanvas<Pixel>::reset(int width, int height, int ox, int oy, Premul clear) {
    w_ = width, h_ = height, ox_ = ox, oy_ = oy;
    view_ = nullptr;
    clean_.clear();
    px_.assign(std::size_t(width) * std::size_t(height), pixel_of<Pixel>(clear));
}

template <class Pixel>
void BasicCanvas<Pixel>::resize(int width, int height) {
    w_ = width, h_ = height, ox_ = 0, oy_ = 0;
    view_ = nullptr;
    clean_.clear();
    px_.resize(std::size_t(width) * std::size_t(height));
}

template <class Pixel>
void BasicCanvas<Pixel>::view_rows(BasicCanvas& parent, int y0, int rows, Premul clear) {
    w_ = parent.w_, h_ = rows, ox_ = parent.ox_, oy_ = parent.oy_ + y0;
    view_ = parent.row(y0);
    clean_.assign(std::size_t(rows), 0);
    open_ = -1;
    clear_ = pixel_of<Pixel>(clear);
}

template <class Pixel>
void BasicCanvas<Pixel>::settle() {
    for (int y = 0; y < int(clean_.size()); ++y) row(y);
#if defined(__SSE2__)
    _mm_sfence(); // streamed stores (store_run) are visible before the band is handed on
#endif
}

template <class Pixel>
void BasicCanvas<Pixel>::clear_columns(int y, int x1) {
    open_row(y);
    fill_to(y, x1);
}

template <class Pixel>
void BasicCanvas<Pixel>::fill_to(int y, int x1) {
    // From a local: an 8-bit pixel's channels are chars, which may alias
    // anything, so stores through the row could change the member clear_
    // for all GCC knows, and it reloads it for every pixel (scalar 4-byte
    // stores).
    const Pixel c = clear_;
    int& clean = clean_[std::size_t(y)];
    fill_run(pixels() + std::size_t(y) * std::size_t(w_) + clean, x1 - clean, c);
    clean = x1;
}

template <class Pixel>
void BasicCanvas<Pixel>::open_row(int y) {
    if (y == open_) return;
    if (open_ >= 0) fill_to(open_, w_);
    open_ = y;
}

template <class Pixel>
void BasicCanvas<Pixel>::fill(Premul color) {
    const Pixel c = pixel_of<Pixel>(color);
    for (int y = 0; y < h_; ++y) fill_run(pixels() + std::size_t(y) * std::size_t(w_), w_, c);
    std::fill(clean_.begin(), clean_.end(), w_);
}

template <class Pixel>
void BasicCanvas<Pixel>::store_span(int y, int x, int len, const Premul& c) {
    // The columns left of the run that await the clear are cleared; the
    // run's own are overwritten, so the cursor passes them uncleared.
    Pixel* r = row_to(y, x);
    if (!clean_.empty() && clean_[std::size_t(y)] < x + len) {
        open_row(y);
        clean_[std::size_t(y)] = x + len;
    }
    store_run(r + x, len, pixel_of<Pixel>(c));
}

template <class Pixel>
void BasicCanvas<Pixel>::composite_layer(const BasicCanvas& layer, float opacity) {
    const int dx = layer.ox_ - ox_, dy = layer.oy_ - oy_;
    const int x0 = std::max(0, dx), x1 = std::min(w_, dx + layer.w_);
    const int y0 = std::max(0, dy), y1 = std::min(h_, dy + layer.h_);
    for (int y = y0; y < y1; ++y) {
        const Pixel* s = layer.row(y - dy) + (x0 - dx);
        Pixel* d = row(y) + x0;
        for (int i = 0; i < x1 - x0; ++i) blend_over(d[i], to_premul(s[i]), opacity);
    }
}

template class BasicCanvas<Premul>;
template class BasicCanvas<Premul8>;

} // namespace casteljau
