// Reference coverage for raster tests: the same outlines sampled 256 x 256
// times per pixel, computed per sub-scanline (crossings sorted, winding walked,
// samples in each inside interval counted in closed form), so a 64 x 64 image
// costs milliseconds while being exactly what point sampling would give.
#pragma once

#include "casteljau/geom/point.h"
#include "casteljau/raster/span.h"
#include "casteljau/raster/sweep.h"

#include <vector>

namespace casteljau::testing {

using Polygon = std::vector<Point>; // closed implicitly

std::vector<float> supersampled_coverage(const std::vector<Polygon>& polys, FillRule rule, int w,
                                         int h, int samples = 256);

// Collects spans into a dense coverage image, checking the interface's rules
// (rows in order, spans in order without overlap, coverage in [0, 1]).
class CoverageImage : public SpanSink {
  public:
    CoverageImage(int w, int h) : w_(w), h_(h), cov_(std::size_t(w * h), 0.0f) {}
    void span(const Span& s) override;
    float at(int x, int y) const { return cov_[std::size_t(y * w_ + x)]; }
    const std::vector<float>& data() const { return cov_; }
    bool order_ok() const { return order_ok_; }

  private:
    int w_, h_;
    std::vector<float> cov_;
    int last_y_ = -1, last_end_ = 0;
    bool order_ok_ = true;
};

} // namespace casteljau::testing
