// The one interface between the rasterizer and the compositor.
//
// A Span is a run of `len` pixels on row `y` starting at column `x`, with one
// coverage value in [0, 1] per pixel (the fraction of the pixel's area inside
// the shape under the fill rule), or, when `coverage` is null, the coverage
// `solid` for all of them: the inside of a shape, where the coverage is
// constant, reaches the compositor as one number, so wide fills cost a store
// per pixel and no coverage array. Spans of one sweep arrive in increasing y,
// and within a row in increasing x without overlap (adjacent spans may touch);
// pixels not covered by any span have coverage 0. `coverage` is valid only
// during the call.
#pragma once

namespace casteljau {

/// A run of pixels of one row, with one coverage value per pixel or one for all.
struct Span {
    int y = 0, x = 0, len = 0;
    const float* coverage = nullptr; ///< per pixel; null: every pixel has `solid`
    float solid = 0;                 ///< the coverage of every pixel when `coverage` is null
    /// The coverage of the i-th pixel.
    float at(int i) const { return coverage ? coverage[i] : solid; }
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
        if (a < b)
            inner_.span({s.y, a, b - a, s.coverage ? s.coverage + (a - s.x) : nullptr, s.solid});
    }

  private:
    SpanSink& inner_;
    int x0_, x1_;
};

} // namespace casteljau
