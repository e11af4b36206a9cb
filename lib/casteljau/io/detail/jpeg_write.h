// Encoding JPEG with libjpeg (libjpeg-turbo), for `-o picture.jpg`:
// through OpenImageIO's module every JPEG written waited for the module and
// its ~260 libraries to load. The settings are those OpenImageIO 2.4's
// writer used, so that files are as good and as large as before: quality
// 98, 4:2:0 chroma, a JFIF header, baseline with the standard Huffman
// tables (OIIO's EXIF block, which held only its version, is not written).
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace casteljau::detail {

/// The quality OpenImageIO 2.4 wrote JPEG at by default.
inline constexpr int kJpegQuality = 98;

/// Encodes a w x h image of 8-bit sRGB pixels, 3 bytes each, rows from the
/// top (`rgb`, w h 3 bytes), into `out`; "" or libjpeg's message.
std::string encode_jpeg(int w, int h, std::span<const std::uint8_t> rgb,
                        std::vector<unsigned char>& out);

} // namespace casteljau::detail
