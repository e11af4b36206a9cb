// Reading raster images (PNG, JPEG, GIF, WebP, TIFF) into premultiplied
// float RasterImages, for SVG <image>: the I/O border, where a file's header
// is checked against a pixel limit before any pixel is decoded and every
// failure becomes an error message.
#pragma once

#include "casteljau/paint/raster_image.h"

#include <cstddef>
#include <memory>
#include <span>
#include <string>

namespace casteljau {

/// A decoded image, or why there is none.
struct ImageReadResult {
    std::shared_ptr<const RasterImage> image; ///< null on error
    std::string error;                        ///< empty on success
};

/// Decodes the image file at `path`. The format is found from the file's
/// first bytes, not its name. Only the first frame or page is read;
/// gray becomes RGB, a missing alpha is 1, and EXIF orientation is applied.
/// Values stay sRGB-encoded, premultiplied. Images of more than
/// `max_pixels` pixels (width * height, as the file declares them) are
/// refused before their pixels are decoded. Errors start with the path.
ImageReadResult read_image_file(const std::string& path, std::size_t max_pixels);

/// The same for the bytes of an image file in memory (a data: URL's).
/// Errors name no source: the caller knows where the bytes came from.
ImageReadResult decode_image(std::span<const unsigned char> bytes, std::size_t max_pixels);

/// Whether the image file at `path` is one the library decodes itself (PNG,
/// JPEG, WebP, known by their signatures): read_image_file then loads no
/// OpenImageIO, but for an animated WebP. False when it cannot be read.
bool decodes_without_openimageio(const std::string& path);

/// Whether OpenImageIO, which decodes GIF, TIFF and animated WebP (and
/// encodes TIFF and EXR), can be loaded (it is loaded on first use: see
/// io/detail/oiio_module.h); when it cannot, `why`, if given, says why.
/// For telling a missing installation from a bad file after a failure.
bool openimageio_available(std::string* why = nullptr);

} // namespace casteljau
