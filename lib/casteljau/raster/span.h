// The one interface between the rasterizer and the compositor.
//
// A Span is a run of `len` pixels on row `y` starting at column `x`, with one
// coverage value in [0, 1] per pixel (the fraction of the pixel's area inside
// the shape under the fill rule). Spans of one sweep arrive in increasing y,
// and within a row in increasing x without overlap; pixels not covered by any
// span have coverage 0. `coverage` is valid only during the call.
#pragma once

namespace casteljau {

struct Span {
    int y = 0, x = 0, len = 0;
    const float* coverage = nullptr;
};

class SpanSink {
  public:
    virtual void span(const Span& s) = 0;

  protected:
    ~SpanSink() = default;
};

} // namespace casteljau
