// RasterImage: decoded pixels to paint with (SVG <image>, and the tiles
// patterns are rendered into).
//
// Pixels are premultiplied and sRGB-encoded, as the canvas holds them
// (paint/color.h), row-major from the top-left. A RasterImage is immutable
// once built and shared by every paint that draws it.
#pragma once

#include "casteljau/paint/color.h"

#include <cstddef>
#include <vector>

namespace casteljau {

/// A width x height image of premultiplied float pixels.
struct RasterImage {
    int width = 0, height = 0;
    std::vector<Premul> pixels; ///< width * height, row-major

    /// The pixel at column x, row y (0 <= x < width, 0 <= y < height).
    const Premul& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }
};

} // namespace casteljau
