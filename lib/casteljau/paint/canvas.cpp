#include "casteljau/paint/canvas.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace casteljau {

namespace {

// Opaque runs of at least this many bytes (1024 float pixels) are stored
// past the cache: a fill that wide is mostly not drawn over again while
// still cached, and a plain store first reads each line it writes (read for
// ownership), doubling the memory traffic. Shorter runs stay in the cache
// for the shapes drawn on top.
constexpr std::size_t kStreamBytes = 16384;

// d[0, n) = c.
template <class Pixel>
void store_run(Pixel* d, int n, Pixel c) {
#if defined(__SSE2__)
    static_assert(16 % sizeof(Pixel) == 0, "pixels tile a 16-byte store");
    if (std::size_t(n) * sizeof(Pixel) >= kStreamBytes) {
        constexpr int per = int(16 / sizeof(Pixel)); // pixels per 16-byte store
        Pixel four[per];
        std::fill(four, four + per, c);
        __m128i v;
        std::memcpy(&v, four, sizeof v);
        int i = 0;
        // Stream from the first 16-byte aligned pixel (pixels are aligned to their size).
        for (; i < n && (reinterpret_cast<std::uintptr_t>(d + i) & 15) != 0; ++i) d[i] = c;
        for (; i + per <= n; i += per) _mm_stream_si128(reinterpret_cast<__m128i*>(d + i), v);
        std::fill(d + i, d + n, c);
        return;
    }
#endif
    std::fill(d, d + n, c);
}

} // namespace

template <class Pixel>
BasicCanvas<Pixel>::BasicCanvas(int width, int height, int ox, int oy) {
    reset(width, height, ox, oy);
}

template <class Pixel>
void BasicCanvas<Pixel>::reset(int width, int height, int ox, int oy, Premul clear) {
    w_ = width, h_ = height, ox_ = ox, oy_ = oy;
    view_ = nullptr;
    stale_.clear();
    px_.assign(std::size_t(width) * std::size_t(height), pixel_of<Pixel>(clear));
}

template <class Pixel>
void BasicCanvas<Pixel>::view_rows(BasicCanvas& parent, int y0, int rows, Premul clear) {
    w_ = parent.w_, h_ = rows, ox_ = parent.ox_, oy_ = parent.oy_ + y0;
    view_ = parent.row(y0);
    stale_.assign(std::size_t(rows), 1);
    clear_ = pixel_of<Pixel>(clear);
}

template <class Pixel>
void BasicCanvas<Pixel>::settle() {
    for (int y = 0; y < int(stale_.size()); ++y) row(y);
#if defined(__SSE2__)
    _mm_sfence(); // streamed stores (store_run) are visible before the band is handed on
#endif
}

template <class Pixel>
void BasicCanvas<Pixel>::clear_row_except(Pixel* r, int y, int x0, int x1) {
    std::fill(r, r + x0, clear_);
    std::fill(r + std::max(x0, x1), r + w_, clear_);
    stale_[std::size_t(y)] = 0;
}

template <class Pixel>
void BasicCanvas<Pixel>::fill(Premul color) {
    Pixel* p = pixels();
    std::fill(p, p + std::size_t(w_) * std::size_t(h_), pixel_of<Pixel>(color));
    std::fill(stale_.begin(), stale_.end(), 0);
}

template <class Pixel>
void BasicCanvas<Pixel>::store_span(int y, int x, int len, const Premul& c) {
    store_run(row_except(y, x, x + len) + x, len, pixel_of<Pixel>(c));
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
