// Canvas: premultiplied RGBA pixels in float, and source-over compositing.
//
// Source-over (Porter & Duff 1984) with coverage c and premultiplied source S:
//   D' = c S + (1 - c S.a) D,
// per channel. A canvas can also stand for an offscreen layer placed at an
// origin (ox, oy) of its parent: group opacity renders the group's children
// into a layer the size of the group's bounds and composites it once, with
// the group's opacity as the coverage (SVG 1.1, 14.5).
//
// Float keeps layers and partial coverage free of 8-bit rounding; a pixel is
// 16 bytes, which is what the image-size limits of the readers account for.
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/paint/gradient.h"
#include "casteljau/raster/span.h"

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

/// A premultiplied float RGBA image, or an offscreen layer placed in its parent.
class Canvas {
  public:
    Canvas() = default;
    /// Transparent, with its top-left corner at (ox, oy) of the parent canvas.
    Canvas(int width, int height, int ox = 0, int oy = 0);
    /// Resizes (keeping storage when large enough) and clears to `clear`.
    void reset(int width, int height, int ox = 0, int oy = 0, Premul clear = {});
    /// Makes this canvas a view of `rows` whole rows of `parent` from row y0
    /// (its own storage is kept, unused), cleared to `clear`: a band drawn in
    /// place, with no copy. Valid while the parent keeps its size.
    void view_rows(Canvas& parent, int y0, int rows, Premul clear);

    /// Width in pixels.
    int width() const { return w_; }
    /// Height in pixels.
    int height() const { return h_; }
    /// Column of the parent (or frame) where this canvas starts.
    int origin_x() const { return ox_; }
    /// Row of the parent (or frame) where this canvas starts.
    int origin_y() const { return oy_; }
    /// The pixels of row y (0 <= y < height()).
    Premul* row(int y) { return pixels() + std::size_t(y) * std::size_t(w_); }
    /// The pixels of row y (0 <= y < height()), read-only.
    const Premul* row(int y) const { return pixels() + std::size_t(y) * std::size_t(w_); }

    /// Sets every pixel to `color`.
    void fill(Premul color);
    /// Source-over of `color` through the span's coverage (span in this canvas's pixels).
    void composite_span(const Span& s, Premul color);
    /// Source-over of a layer (placed at its origin, relative to this canvas's
    /// origin), scaled by `opacity`; the parts outside this canvas are dropped.
    void composite_layer(const Canvas& layer, float opacity);

  private:
    Premul* pixels() { return view_ ? view_ : px_.data(); }
    const Premul* pixels() const { return view_ ? view_ : px_.data(); }
    std::vector<Premul> px_;
    Premul* view_ = nullptr; // another canvas's rows (view_rows), else null
    int w_ = 0, h_ = 0, ox_ = 0, oy_ = 0;
};

/// Adapts the raster's span interface (absolute pixel coordinates) to
/// solid-color compositing on a canvas placed at its origin.
class SolidSpanPainter final : public SpanSink {
  public:
    /// Paints `color` onto `c`.
    SolidSpanPainter(Canvas& c, Premul color) : canvas_(c), color_(color) {}
    /// Source-over of the color through the span's coverage.
    void span(const Span& s) override {
        canvas_.composite_span(
            {s.y - canvas_.origin_y(), s.x - canvas_.origin_x(), s.len, s.coverage, s.solid},
            color_);
    }

  private:
    Canvas& canvas_;
    Premul color_;
};

/// Adapts the span interface to gradient compositing: each pixel's color comes
/// from the shader at the pixel's centre.
class GradientSpanPainter final : public SpanSink {
  public:
    /// Paints the gradient `shader` onto `c`.
    GradientSpanPainter(Canvas& c, const GradientShader& shader) : canvas_(c), shader_(shader) {}
    /// Source-over of the shaded pixels through the span's coverage.
    void span(const Span& s) override {
        Premul* d = canvas_.row(s.y - canvas_.origin_y()) + (s.x - canvas_.origin_x());
        for (int i = 0; i < s.len; ++i) blend_over(d[i], shader_.at(s.x + i, s.y), s.at(i));
    }

  private:
    Canvas& canvas_;
    const GradientShader& shader_;
};

} // namespace casteljau
