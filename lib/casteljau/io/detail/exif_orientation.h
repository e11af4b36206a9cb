// The EXIF orientation of an image, from the TIFF structure an EXIF block
// holds (PNG's eXIf chunk; JPEG's APP1 marker after its "Exif\0\0"): the
// Orientation tag (TIFF 6.0, 8: 274, of type SHORT) of the first IFD, as
// OpenImageIO reads it. io/image_read.cpp applies it.
#pragma once

#include <cstddef>

namespace casteljau::detail {

/// The Orientation (1 to 8) in the `n` bytes of TIFF data at `tiff` (TIFF
/// 6.0, 2: byte order, 42, the first IFD's offset; an IFD: a count of
/// 12-byte entries tag, type, count, value); 1 when it has none or is
/// malformed.
int exif_orientation(const unsigned char* tiff, std::size_t n);

} // namespace casteljau::detail
