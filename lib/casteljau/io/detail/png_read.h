// Decoding PNG with libpng, for <image>: without it every document with a
// PNG image would load OpenImageIO's module (about 200 ms, 20 times a small
// render). libpng is loaded anyway (FreeType needs it).
//
// The values are those OpenImageIO 2.4's PNG reader gives, which decoded
// PNG before (tests/io/png_read_test.cpp compares the two on every kind of
// PNG): libpng expands palettes, gray below 8 bits and tRNS to 8-bit
// channels (png_set_expand); 8- and 16-bit samples become floats by
// multiplying by 1/255 or 1/65535 as OIIO's conversion does; alpha is
// straight (PNG 4.3); no gamma or ICC transform; the orientation is read
// from an eXIf chunk before the image data (the TIFF Orientation tag of its
// first IFD, as OIIO reads it). Interlaced images are deinterlaced.
#pragma once

#include "casteljau/io/detail/oiio_codec.h"

#include <memory>
#include <span>
#include <string>

namespace casteljau::detail {

/// An opened PNG: the reader, or null with `error` set (libpng's message).
struct PngOpened {
    std::unique_ptr<ImageReader> reader;
    std::string error;
};

/// Opens the PNG file `name`, or, when `from_memory`, the bytes `memory`
/// (which must outlive the reader). Reads the header only.
PngOpened open_png(const std::string& name, std::span<const unsigned char> memory,
                   bool from_memory);

} // namespace casteljau::detail
