// Textures looked up by the surface's (s, t).
//
// * Checker: squares of 1/8 in (s, t), box-filtered over the pixel's
//   footprint (ds, dt): the box-filtered square wave is the difference
//   quotient of its integral, a triangle wave, and the 2D checker is the
//   product of two square waves, so its filtered value is the product of the
//   two filtered ones. No aliasing moire at grazing angles, no mip maps.
// * Image: PNG, JPEG and WebP read by the library's decoders
//   (io/image_read.h, EXIF orientation applied), any other format through
//   OpenImageIO (its module, loaded on first use: io/detail/oiio_module.h);
//   stored linear, looked up bilinearly and repeated in both directions
//   (s = 0..1 spans the image once). No mip maps: minified image textures
//   alias.
// Values are linear-light RGB albedo in [0, 1].
#pragma once

#include "casteljau/geom/point.h"

#include <cstddef>
#include <string>
#include <vector>

namespace casteljau {

/// A linear RGB color.
struct Rgb {
    float r = 0, g = 0, b = 0;
};

/// A surface texture: the analytic checker or an image, sampled at (s, t).
class Texture {
  public:
    /// The checker.
    Texture() = default;
    /// The pixel limits of an image texture, as of output images.
    static constexpr int kMaxTextureSide = 16384;
    static constexpr std::size_t kMaxTexturePixels = std::size_t(1) << 26;

    /// Reads an image; returns an empty string on success, otherwise the error.
    std::string load(const std::string& path);
    /// `footprint`: the extent in (s, t) of one pixel, for filtering.
    Rgb at(Point st, Vec2 footprint) const;

  private:
    /// load() of a format the library decodes (io/image_read.h).
    std::string load_decoded(const std::string& path);
    /// Why a w x h texture is over the limits; "" when it is not.
    static std::string size_error(const std::string& path, int w, int h);
    Rgb checker(Point st, Vec2 footprint) const;
    Rgb texel(int x, int y) const;

    std::vector<Rgb> px_;
    int w_ = 0, h_ = 0;
};

} // namespace casteljau
