// Bit-exact picture comparison for tests.
#pragma once

#include "casteljau/paint/canvas.h"

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

} // namespace casteljau::testing
