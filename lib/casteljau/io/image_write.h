// Writing images, atomically: PNG by the library's own encoder
// (png_write.h), JPEG by libjpeg (detail/jpeg_write.h), every other format
// through OpenImageIO, loaded on first use (io/detail/oiio_module.h;
// without it such a write fails with a message).
//
// The format follows the file extension (png, tif/tiff, exr, jpg/jpeg; anything
// else OpenImageIO knows). 8-bit formats get float values quantised with
// rounding (or 8-bit values as they are); EXR and TIFF are written as 32-bit
// float; JPEG gets RGB only. The image goes to a temporary file in the
// destination's folder (same extension, so OpenImageIO picks the same
// writer), which is renamed over the destination only once complete: a
// failed or interrupted write never leaves a damaged or partial file, and an
// existing file stays untouched until the new one is whole.
//
// The caller states whether the pixels are straight or premultiplied, and the
// file's alpha is made to agree with that, for every format. PNG stores
// straight values: premultiplied ones are divided by alpha in float before
// rounding (dividing rounded bytes would lose the color of faint pixels).
// OpenImageIO takes a buffer as premultiplied unless told otherwise: straight
// values are labelled so. TIFF records the convention in its ExtraSamples tag
// and keeps the values as given. OpenEXR files are premultiplied by
// definition and OpenImageIO's EXR writer ignores the label, so straight
// pixels are premultiplied here for EXR. JPEG has no alpha and drops it:
// flatten the image first.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace casteljau {

/// How the color channels of an ImageView relate to its alpha.
enum class Alpha {
    straight,      ///< color independent of alpha (un-premultiplied), as PNG stores it
    premultiplied, ///< color already multiplied by alpha, as OpenEXR stores it
};

/// Float RGBA pixels to write: a view, not owned.
struct ImageView {
    int width = 0, height = 0;
    /// width * height RGBA pixels, row-major from the top, values in [0, 1]
    /// already in the output's encoding (sRGB for 8-bit files).
    std::span<const float> rgba{};
    /// What the color values in `rgba` are; the file is labelled (or, for
    /// EXR, converted) to match.
    Alpha alpha = Alpha::straight;
    /// Or 8-bit values (255 for 1), used when `rgba` is empty: an 8-bit
    /// format stores them as they are (no rounding here); a float format
    /// gets them divided by 255.
    std::span<const std::uint8_t> rgba8{};
};

/// The path's extension, lowercased, with its dot (".png"): what picks the
/// format, in any case (".PNG", ".Tif").
std::string image_extension(const std::string& path);

/// Whether write_image_atomic stores 32-bit float for this path's extension
/// (EXR, TIFF); every other format stores 8 bits a channel.
bool stores_float(const std::string& path);

/// Returns an empty string on success, otherwise what went wrong (with the path).
std::string write_image_atomic(const std::string& path, const ImageView& image);

} // namespace casteljau
