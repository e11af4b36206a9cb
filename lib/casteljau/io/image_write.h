// Writing images through OpenImageIO, atomically.
//
// The format follows the file extension (png, tif/tiff, exr, jpg/jpeg; anything
// else OpenImageIO knows). 8-bit formats get the values quantised with
// rounding; EXR and TIFF are written as 32-bit float; JPEG gets RGB only. The image goes to a
// temporary file in the destination's folder (same extension, so OpenImageIO
// picks the same writer), which is renamed over the destination only once
// complete: a failed or interrupted write never leaves a damaged or partial
// file, and an existing file stays untouched until the new one is whole.
#pragma once

#include <span>
#include <string>

namespace casteljau {

/// Float RGBA pixels to write: a view, not owned.
struct ImageView {
    int width = 0, height = 0;
    /// width * height RGBA pixels, row-major from the top, un-premultiplied,
    /// values in [0, 1] already in the output's encoding (sRGB for 8-bit files).
    std::span<const float> rgba;
};

/// Returns an empty string on success, otherwise what went wrong (with the path).
std::string write_image_atomic(const std::string& path, const ImageView& image);

} // namespace casteljau
