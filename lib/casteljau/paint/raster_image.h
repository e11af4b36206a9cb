// RasterImage: decoded pixels to paint with (SVG <image>, and the tiles
// patterns are rendered into).
//
// Pixels are premultiplied and sRGB-encoded, as the canvas holds them
// (paint/color.h), row-major from the top-left. A RasterImage is immutable
// once built and shared by every paint that draws it.
//
// An opaque image (every alpha exactly 1) may also carry its pixels rounded
// to 8 bits (opaque8, made by find_opaque8): where an 8-bit canvas takes
// such a pixel at coverage 1 and opacity 1, source-over gives
// round(255 S + 0 D) = quantize(S), those very bytes (pixel8.h), so they are
// copied instead of composited (ImageShader::store_opaque). Pattern tiles
// carry it (drawn on the pixel grid, mostly at their own resolution);
// decoded images do not: most are opaque and drawn scaled, and the copy
// would be a quarter more memory than the 16 bytes a pixel the image
// limits count (SvgOptions::max_image_pixels).
//
// Drawn smaller than half its size, an image is sampled from one of its
// levels (level(), image_levels.h): the image shrunk by 2^k, built on first
// use and kept with it, a third of its pixels more at most.
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/paint/image_levels.h"
#include "casteljau/paint/pixel8.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace casteljau {

/// A width x height image of premultiplied float pixels.
struct RasterImage {
    int width = 0, height = 0;
    std::vector<Premul> pixels; ///< width * height, row-major
    /// quantize(pixels[i]) when every pixel is opaque (find_opaque8), else empty.
    std::vector<Premul8> opaque8;

    /// The pixel at column x, row y (0 <= x < width, 0 <= y < height).
    const Premul& at(int x, int y) const {
        return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
    }

    /// Fills opaque8 when every pixel's alpha is exactly 1, and empties it
    /// otherwise: call it once the pixels are final.
    void find_opaque8() {
        opaque8.clear();
        if (!std::all_of(pixels.begin(), pixels.end(), [](const Premul& p) { return p.a == 1.0f; }))
            return;
        opaque8.resize(pixels.size());
        std::transform(pixels.begin(), pixels.end(), opaque8.begin(),
                       [](const Premul& p) { return quantize(p); });
    }

    /// Level k (image_levels.h): this image shrunk to max(1, width >> k) x
    /// max(1, height >> k), k clamped to [0, the last level, 1 x 1]; level
    /// 0 is the image itself. Built from the pixels on first use (they must
    /// be final by then) and kept; safe to call from several threads.
    const RasterImage& level(int k) const { return k <= 0 ? *this : levels_.get(*this, k); }

  private:
    ImageLevels levels_;
};

} // namespace casteljau
