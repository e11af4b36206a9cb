// Bit-exact picture comparison for tests.
#pragma once

#include "casteljau/paint/canvas.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace casteljau::testing {

// Rows of `tile` (placed at its origin in `full`) whose pixels differ, in any
// bit, from the same pixels of `full`; two canvases of one size at origin 0
// are compared whole.
template <class Pixel>
int differing_rows(const BasicCanvas<Pixel>& full, const BasicCanvas<Pixel>& tile) {
    int differing = 0;
    for (int y = 0; y < tile.height(); ++y)
        differing += std::memcmp(full.row(y + tile.origin_y()) + tile.origin_x(), tile.row(y),
                                 std::size_t(tile.width()) * sizeof(Pixel)) != 0;
    return differing;
}

// The largest difference of any channel between two float canvases of one size.
inline float max_difference(const Canvas& a, const Canvas& b) {
    float d = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const Premul p = a.row(y)[x], q = b.row(y)[x];
            d = std::max({d, std::fabs(p.r - q.r), std::fabs(p.g - q.g), std::fabs(p.b - q.b),
                          std::fabs(p.a - q.a)});
        }
    return d;
}

} // namespace casteljau::testing
