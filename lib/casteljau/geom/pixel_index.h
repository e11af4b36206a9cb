// Pixel indices from coordinates, clamped to a range before the conversion:
// converting a double outside int's range to int is undefined behaviour, and
// geometry far off the image (up to 1e308, or NaN from an overflow) reaches
// these conversions. NaN takes the low end.
#pragma once

#include <cmath>

namespace casteljau {

inline int floor_in(double v, int lo, int hi) {
    const double f = std::floor(v);
    return f >= lo ? (f <= hi ? int(f) : hi) : lo;
}

inline int ceil_in(double v, int lo, int hi) {
    const double c = std::ceil(v);
    return c >= lo ? (c <= hi ? int(c) : hi) : lo;
}

} // namespace casteljau
