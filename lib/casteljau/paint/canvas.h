// Canvas: premultiplied RGBA pixels, and source-over compositing.
//
// Source-over (Porter & Duff 1984) with coverage c and premultiplied source S:
//   D' = c S + (1 - c S.a) D,
// per channel. A canvas can also stand for an offscreen layer placed at an
// origin (ox, oy) of its parent: group opacity renders the group's children
// into a layer the size of the group's bounds and composites it once, with
// the group's opacity as the coverage (SVG 1.1, 14.5).
//
// Two pixel formats, one code: `Canvas` stores float (16 bytes a pixel),
// which keeps layers and partial coverage free of 8-bit rounding and is what
// the image-size limits of the readers account for; `Canvas8` stores 8 bits
// a channel (4 bytes, paint/pixel8.h), as Cairo and Skia draw, for a caller
// that wants bytes (a window, an 8-bit file) and a quarter of the memory
// traffic. Colors reach both as float `Premul`; only the stores differ.
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/paint/large_buffer.h"
#include "casteljau/paint/pixel8.h"
#include "casteljau/raster/span.h"

#include <algorithm>
#include <type_traits>
#include <vector>

namespace casteljau {

/// Source-over of premultiplied `s` scaled by coverage k onto d.
inline void blend_over(Premul& d, Premul s, float k) {
    const float inv = 1.0f - k * s.a;
    d.r = k * s.r + inv * d.r;
    d.g = k * s.g + inv * d.g;
    d.b = k * s.b + inv * d.b;
    d.a = k * s.a + inv * d.a;
}

/// blend_over of `s` onto d[0, n), every pixel through coverage k.
inline void blend_span_over(Premul* d, int n, const Premul& s, float k) {
    for (int i = 0; i < n; ++i) blend_over(d[i], s, k);
}

/// blend_over of shaded colors s[i] onto d[0, n), pixel i through coverage k[i].
inline void blend_shaded_over(Premul* d, int n, const Premul* s, const float* k) {
    for (int i = 0; i < n; ++i) blend_over(d[i], s[i], k[i]);
}

/// blend_over of shaded colors s[i] onto d[0, n), every pixel through coverage k.
inline void blend_shaded_over(Premul* d, int n, const Premul* s, float k) {
    for (int i = 0; i < n; ++i) blend_over(d[i], s[i], k);
}

/// The float color a float pixel holds: itself.
inline const Premul& to_premul(const Premul& p) { return p; }

/// A color as a pixel of the given format.
template <class Pixel>
Pixel pixel_of(const Premul& c) {
    if constexpr (std::is_same_v<Pixel, Premul>)
        return c;
    else
        return quantize(c);
}

/// A premultiplied RGBA image with pixels of type `Pixel` (Premul or
/// Premul8), or an offscreen layer placed in its parent.
template <class Pixel>
class BasicCanvas {
  public:
    using pixel_type = Pixel; ///< Premul or Premul8
    BasicCanvas() = default;
    /// Transparent, with its top-left corner at (ox, oy) of the parent canvas.
    BasicCanvas(int width, int height, int ox = 0, int oy = 0);
    /// Resizes (keeping storage when large enough) and clears to `clear`.
    void reset(int width, int height, int ox = 0, int oy = 0, Premul clear = {});
    /// Resizes (keeping storage when large enough) at origin (0, 0) without
    /// clearing: the pixels are unspecified until written. For a renderer
    /// that writes every pixel itself (BandRenderer::render clears each band
    /// to its background as it draws), whose frame a clear here would only
    /// double: 2.6% of the tiger's frame at 1024 px (perf).
    void resize(int width, int height);
    /// Makes this canvas a view of `rows` whole rows of `parent` from row y0
    /// (its own storage is kept, unused): a band drawn in place, with no copy.
    /// Valid while the parent keeps its size. The rows are cleared to `clear`
    /// lazily, each from the left up to where it is written (row() clears a
    /// whole row, composite_span up to the span's end), so the clear and the
    /// drawing meet in the cache, and no pixel under an opaque run is cleared
    /// first. settle() clears what was never written; call it before reading
    /// the pixels.
    void view_rows(BasicCanvas& parent, int y0, int rows, Premul clear);
    /// Clears the rows of a view_rows band that nothing has written yet.
    void settle();

    /// Width in pixels.
    int width() const { return w_; }
    /// Height in pixels.
    int height() const { return h_; }
    /// Column of the parent (or frame) where this canvas starts.
    int origin_x() const { return ox_; }
    /// Row of the parent (or frame) where this canvas starts.
    int origin_y() const { return oy_; }
    /// The pixels of row y (0 <= y < height()), for writing.
    Pixel* row(int y) { return row_to(y, w_); }
    /// The pixels of row y (0 <= y < height()), read-only; for a view_rows
    /// band, only after settle() (an unwritten row is not cleared before).
    const Pixel* row(int y) const { return pixels() + std::size_t(y) * std::size_t(w_); }

    /// Sets every pixel to `color`.
    void fill(Premul color);
    /// Source-over of `color` through the span's coverage (span in this canvas's pixels).
    /// The color by reference: by value, its 16 bytes travel in two registers
    /// and are joined again through the stack, a store-forwarding stall on
    /// every span (2% of the hairline scene's frame in the profile).
    void composite_span(const Span& s, const Premul& color) { composite_at(s.y, s.x, s, color); }
    /// The same for a span in the pixels of the frame this canvas is placed in
    /// (the rasterizer's coordinates): this canvas's origin is subtracted.
    void composite_frame_span(const Span& s, const Premul& color) {
        composite_at(s.y - oy_, s.x - ox_, s, color);
    }
    /// Source-over of a layer (placed at its origin, relative to this canvas's
    /// origin), scaled by `opacity`; the parts outside this canvas are dropped.
    void composite_layer(const BasicCanvas& layer, float opacity);

  private:
    /// composite_span at row y, column x of this canvas; `s` gives the
    /// length and coverage, its own y and x are not read.
    void composite_at(int y, int x, const Span& s, const Premul& c);
    /// An opaque run of len pixels from row y, column x: a store (streamed when long).
    void store_span(int y, int x, int len, const Premul& c);
    /// Row y, its columns [0, x1) ready for writing: those still awaiting
    /// the clear are cleared first.
    Pixel* row_to(int y, int x1) {
        Pixel* r = pixels() + std::size_t(y) * std::size_t(w_);
        if (!clean_.empty() && clean_[std::size_t(y)] < x1) clear_columns(y, x1);
        return r;
    }
    /// Clears row y's columns [clean_[y], x1) (opening the row, open_row),
    /// and moves its cursor to x1.
    void clear_columns(int y, int x1);
    /// The same for a row already open.
    void fill_to(int y, int x1);
    Pixel* pixels() { return view_ ? view_ : px_.data(); }
    const Pixel* pixels() const { return view_ ? view_ : px_.data(); }
    std::vector<Pixel, LargeAllocator<Pixel>> px_; // huge pages: large_buffer.h
    Pixel* view_ = nullptr;                        // another canvas's rows (view_rows), else null
    // view_rows: per row, the columns [0, clean_[y]) hold pixels and the rest
    // await the clear (a span of one shape's row is drawn left to right, so
    // one cursor a row is enough); empty: every pixel holds one.
    std::vector<int> clean_;
    // view_rows: the row written to last while it awaited the clear; when
    // another row is written, the rest of it is cleared, while it is still
    // in the cache (at settle(), a band later, it was not).
    int open_ = -1;
    void open_row(int y);
    Pixel clear_{}; // what the columns awaiting it are cleared to
    int w_ = 0, h_ = 0, ox_ = 0, oy_ = 0;
};

/// Float pixels: compositing without 8-bit rounding; what EXR output and the
/// image-size limits assume.
using Canvas = BasicCanvas<Premul>;
/// 8-bit pixels: a quarter of the memory, each composite rounded to the nearest 1/255.
using Canvas8 = BasicCanvas<Premul8>;

extern template class BasicCanvas<Premul>;
extern template class BasicCanvas<Premul8>;

// Inline, into the painters: called once per span, and a thin shape's spans
// are a few pixels (2% of the hairline scene's frame as a call).
template <class Pixel>
inline void BasicCanvas<Pixel>::composite_at(int y, int x, const Span& s, const Premul& c) {
    const float* k = s.coverage;
    if (!k && c.a == 1.0f && s.solid == 1.0f) { // opaque over the whole span: a store
        store_span(y, x, s.len, c);
        return;
    }
    Pixel* d = row_to(y, x + s.len) + x;
    // A shape's span on the next row usually starts near this one (outlines
    // are continuous), and rows are a stride apart that no hardware
    // prefetcher follows: ask for that pixel's line now.
    if (y + 1 < h_) {
        __builtin_prefetch(d + w_, 1);
        __builtin_prefetch(d + w_ + s.len - 1, 1);
    }
    if (!k) { // one coverage for the whole span
        blend_span_over(d, s.len, c, s.solid);
        return;
    }
    if constexpr (std::is_same_v<Pixel, Premul8>) { // four pixels at a time, no run tests
        blend_span_over(d, s.len, c, k);
        return;
    }
    if (c.a < 1.0f) {
        for (int i = 0; i < s.len; ++i) blend_over(d[i], c, k[i]);
        return;
    }
    // Float, opaque: where fully covered the source replaces the pixel (the
    // general formula gives the same bits, at the price of a read), run by
    // run. (Bytes are blended four at a time above, where the read is shared
    // and the run tests mispredicted.)
    const Pixel p = pixel_of<Pixel>(c);
    for (int i = 0; i < s.len;) {
        int j = i;
        while (j < s.len && k[j] == 1.0f) ++j;
        std::fill(d + i, d + j, p);
        for (i = j; i < s.len && k[i] != 1.0f; ++i) blend_over(d[i], c, k[i]);
    }
}

/// Adapts the raster's span interface (absolute pixel coordinates) to
/// solid-color compositing on a canvas placed at its origin.
template <class Pixel>
class SolidSpanPainter final : public SpanSink {
  public:
    /// Paints `color` onto `c`.
    SolidSpanPainter(BasicCanvas<Pixel>& c, Premul color) : canvas_(c), color_(color) {}
    /// Source-over of the color through the span's coverage.
    /// Not through a new Span with the origin subtracted: GCC computes its y
    /// and x as a pair, with one 8-byte load of the two fields the sweep has
    /// just stored apart, a store-forwarding stall on every span (14% of this
    /// function's samples in the hairline scene's profile).
    void span(const Span& s) override { canvas_.composite_frame_span(s, color_); }

  private:
    BasicCanvas<Pixel>& canvas_;
    Premul color_;
};

/// Adapts the span interface to shaded compositing: each pixel's color comes
/// from the shader, `shader.shade(x, y, n, out)` giving the colors at the
/// centres of n device pixels of a row (GradientShader, ImageShader), a
/// chunk of the span at a time.
template <class Pixel, class Shader>
class ShadedSpanPainter final : public SpanSink {
  public:
    /// Paints `shader` onto `c`.
    ShadedSpanPainter(BasicCanvas<Pixel>& c, const Shader& shader) : canvas_(c), shader_(shader) {}
    /// Source-over of the shaded pixels through the span's coverage.
    void span(const Span& s) override {
        Pixel* d = canvas_.row(s.y - canvas_.origin_y()) + (s.x - canvas_.origin_x());
        // A shader that can store its pixels as composited at coverage 1
        // (ImageShader::store_opaque) does so: no colors, no blend.
        if constexpr (std::is_same_v<Pixel, Premul8> &&
                      requires { shader_.store_opaque(0, 0, 0, d); })
            if (!s.coverage && s.solid == 1.0f && shader_.store_opaque(s.x, s.y, s.len, d)) return;
        for (int i = 0; i < s.len; i += kChunk) {
            const int n = std::min(kChunk, s.len - i);
            shader_.shade(s.x + i, s.y, n, colors_);
            if (s.coverage)
                blend_shaded_over(d + i, n, colors_, s.coverage + i);
            else
                blend_shaded_over(d + i, n, colors_, s.solid);
        }
    }

  private:
    /// Pixels shaded a call: 1 KiB of colors, which stay in the L1 cache
    /// until they are blended.
    static constexpr int kChunk = 64;
    BasicCanvas<Pixel>& canvas_;
    const Shader& shader_;
    Premul colors_[kChunk];
};

/// Gradient compositing.
template <class Pixel>
using GradientSpanPainter = ShadedSpanPainter<Pixel, GradientShader>;

} // namespace casteljau
