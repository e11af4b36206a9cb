// Decoding WebP with libwebp, for <image>, as the PNG and JPEG readers do
// for theirs: through OpenImageIO's module a document with a WebP image
// waited for the module and its ~260 libraries to load.
//
// libwebp's RGBA, or RGB where the file has no alpha, 8-bit samples times
// 1/255 (tests/io/webp_read_test.cpp compares them with OpenImageIO 2.4's
// reader, which decoded WebP before, on lossy and lossless files with and
// without alpha): without alpha, OIIO's values bit for bit; with alpha,
// straight, which image_read.cpp premultiplies in float as it does PNG's,
// where OIIO premultiplied in 8 bits (within half a step of its values).
// An animated WebP is left to OpenImageIO (its first frame): open_webp says
// so.
#pragma once

#include "casteljau/io/detail/oiio_codec.h"

#include <memory>
#include <span>
#include <string>

namespace casteljau::detail {

/// An opened WebP: the reader, or null with `error` set; `animated` (and no
/// reader) for an animation, which OpenImageIO reads.
struct WebpOpened {
    std::unique_ptr<ImageReader> reader;
    std::string error;
    bool animated = false;
};

/// Opens the WebP file `name`, or, when `from_memory`, the bytes `memory`
/// (which must outlive the reader). Reads the header only (a file's bytes
/// are read whole: libwebp decodes from memory).
WebpOpened open_webp(const std::string& name, std::span<const unsigned char> memory,
                     bool from_memory);

} // namespace casteljau::detail
