// The one interface between the rasterizer and the compositor.
//
// A Span is a run of `len` pixels on row `y` starting at column `x`, with one
// coverage value in [0, 1] per pixel (the fraction of the pixel's area inside
// the shape under the fill rule). Spans of one sweep arrive in increasing y,
// and within a row in increasing x without overlap; pixels not covered by any
// span have coverage 0. `coverage` is valid only during the call.
#pragma once

namespace casteljau {

/// A run of pixels of one row, with one coverage value per pixel.
struct Span {
    int y = 0, x = 0, len = 0;
    const float* coverage = nullptr;
};

/// Receives spans: the one interface between rasterizer and compositor.
class SpanSink {
  public:
    /// Called once per span, rows in increasing y, within a row in increasing x.
    virtual void span(const Span& s) = 0;

  protected:
    ~SpanSink() = default;
};

/// Passes on the part of each span within the columns [x0, x1): lets a
/// rasterizer sweep whole rows of a larger frame while only a tile of it is
/// composited (partial re-render), without changing any coverage value.
class ColumnClipSink final : public SpanSink {
  public:
    /// Passes spans on to `inner`, cut to the columns [x0, x1).
    ColumnClipSink(SpanSink& inner, int x0, int x1) : inner_(inner), x0_(x0), x1_(x1) {}
    /// Passes on the part of s within the columns.
    void span(const Span& s) override {
        const int a = s.x > x0_ ? s.x : x0_;
        const int b = s.x + s.len < x1_ ? s.x + s.len : x1_;
        if (a < b) inner_.span({s.y, a, b - a, s.coverage + (a - s.x)});
    }

  private:
    SpanSink& inner_;
    int x0_, x1_;
};

} // namespace casteljau
