// Pixel indices from coordinates, clamped to a range before the conversion:
// converting a double outside int's range to int is undefined behaviour, and
// geometry far off the image (up to 1e308, or NaN from an overflow) reaches
// these conversions. NaN takes the low end.
#pragma once

#include <cmath>

namespace casteljau {

/// floor(x) without a library call: baseline x86-64 has no rounding
/// instruction (SSE4.1 brings one), so std::floor is a call into libm, in
/// loops run once a pixel. Beyond 2^52 every double is whole; NaN and the
/// infinities pass through. Unlike std::floor, -0 gives +0.
inline double floor_whole(double x) {
    if (!(std::fabs(x) < 0x1p52)) return x;
    const double t = double(static_cast<long long>(x));
    return t > x ? t - 1 : t;
}

inline int floor_in(double v, int lo, int hi) {
    const double f = std::floor(v);
    return f >= lo ? (f <= hi ? int(f) : hi) : lo;
}

inline int ceil_in(double v, int lo, int hi) {
    const double c = std::ceil(v);
    return c >= lo ? (c <= hi ? int(c) : hi) : lo;
}

} // namespace casteljau
