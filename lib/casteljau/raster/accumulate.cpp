#include "casteljau/raster/accumulate.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

void CoverageRow::reset(int width) {
    width_ = width;
    acc_.assign(std::size_t(width) + 3, 0.0f);
    marks_.assign((std::size_t(width) + 3 + 63) / 64, 0);
    begin_ = width_ + 1, end_ = 0;
}

} // namespace casteljau
