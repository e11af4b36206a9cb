#include "casteljau/raster/accumulate.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

void CoverageRow::reset(int width) {
    width_ = width;
    acc_.assign(std::size_t(width) + 2, 0.0f);
    marks_.assign((std::size_t(width) + 2 + 63) / 64, 0);
    begin_ = width_ + 1, end_ = 0;
}

void CoverageRow::clear_range() {
    if (begin_ < end_)
        for (std::size_t w = std::size_t(begin_) >> 6; w <= std::size_t(end_ - 1) >> 6; ++w)
            marks_[w] = 0;
    begin_ = width_ + 1, end_ = 0;
}

} // namespace casteljau
