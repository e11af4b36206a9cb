// Decoding JPEG with libjpeg (libjpeg-turbo), for <image>: through
// OpenImageIO's module a document with a JPEG image took 4x rsvg-convert's
// time to file, most of it the module and its ~260 libraries loading.
//
// The values are those OpenImageIO 2.4's JPEG reader gives, which decoded
// JPEG before (tests/io/jpeg_read_test.cpp compares the two on gray, color
// at every chroma subsampling, progressive, CMYK and Adobe's YCCK files):
// libjpeg's default decompression (the accurate integer DCT, smooth chroma
// upsampling); gray stays one channel, YCbCr becomes RGB; CMYK and YCCK
// (Adobe's, stored inverted) become RGB as OIIO converts them, each of R, G,
// B the product C K, M K, Y K of the samples over 255, rounded back to 8
// bits. 8-bit samples become floats by multiplying by 1/255, as OIIO's
// conversion does. The orientation is read from the APP1 marker's EXIF
// (detail/exif_orientation.h). A file cut short is a libjpeg warning, not
// an error: what it held is drawn and the rest is libjpeg's gray, as OIIO
// and browsers draw it; a stream libjpeg cannot go on with is an error.
#pragma once

#include "casteljau/io/detail/oiio_codec.h"

#include <memory>
#include <span>
#include <string>

namespace casteljau::detail {

/// An opened JPEG: the reader, or null with `error` set (libjpeg's message).
struct JpegOpened {
    std::unique_ptr<ImageReader> reader;
    std::string error;
};

/// Opens the JPEG file `name`, or, when `from_memory`, the bytes `memory`
/// (which must outlive the reader). Reads the header only.
JpegOpened open_jpeg(const std::string& name, std::span<const unsigned char> memory,
                     bool from_memory);

} // namespace casteljau::detail
