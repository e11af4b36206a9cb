// The library's own image readers (PNG, JPEG: io/detail/png_read.h,
// jpeg_read.h) against OpenImageIO's, which decoded those formats before
// them: the same header and the same float values, bit for bit.
#pragma once

#include "casteljau/io/detail/oiio_module.h"
#include "casteljau/io/image_read.h"

#include <algorithm>
#include <cstring>
#include <gtest/gtest.h>
#include <memory>
#include <string>
#include <vector>

namespace casteljau::testing {

/// A reader's header and values; the values of up to 4 channels, 4 a
/// pixel, as image_read.cpp reads them.
struct Read {
    detail::ImageHeader header;
    std::vector<float> values;
    std::string error;
};

/// Everything `reader` reads, or `error` when there is no reader.
inline Read read_all(std::unique_ptr<detail::ImageReader> reader, std::string error) {
    Read r;
    if (!reader) {
        r.error = error.empty() ? "no reader" : error;
        return r;
    }
    r.header = reader->header();
    r.values.assign(std::size_t(r.header.width) * std::size_t(r.header.height) * 4, -1.0f);
    r.error = reader->read(std::min(r.header.channels, 4), r.values.data(), 4 * sizeof(float));
    return r;
}

/// `ours` (read_all of the library's reader of `bytes`) equals what
/// OpenImageIO's reader of `format` reads from them.
inline void expect_same_as_oiio(const Read& ours, const char* format,
                                const std::vector<unsigned char>& bytes, const std::string& what) {
    const detail::OiioModule& oiio = detail::oiio_module();
    ASSERT_TRUE(oiio.codec) << oiio.error;
    detail::OiioOpened theirs = oiio.codec->open(format, "memory", bytes, true, true);
    const Read& a = ours;
    const Read b = read_all(std::move(theirs.reader), theirs.error);
    ASSERT_EQ(a.error, "") << what;
    ASSERT_EQ(b.error, "") << what;
    EXPECT_EQ(a.header.width, b.header.width) << what;
    EXPECT_EQ(a.header.height, b.header.height) << what;
    EXPECT_EQ(a.header.channels, b.header.channels) << what;
    EXPECT_EQ(a.header.straight, b.header.straight) << what;
    EXPECT_EQ(a.header.orientation, b.header.orientation) << what;
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    for (std::size_t i = 0; i < a.values.size(); ++i)
        ASSERT_EQ(std::memcmp(&a.values[i], &b.values[i], sizeof(float)), 0)
            << what << ": value " << i << " is " << a.values[i] << ", OIIO's " << b.values[i];
}

/// For each EXIF orientation o from 1 to 8, `make(o)`, the bytes of a 3 x 2
/// image tagged o, reads as OpenImageIO reads it (`same(bytes, what)`,
/// a format's expect_same_as_oiio) and decodes turned as the tag says: 5
/// to 8 exchange rows and columns.
template <class Make, class Same>
void expect_orientations_read_and_applied(Make make, Same same) {
    for (int o = 1; o <= 8; ++o) {
        const std::vector<unsigned char> bytes = make(o);
        same(bytes, "orientation " + std::to_string(o));
        const ImageReadResult r = decode_image(bytes, 100);
        ASSERT_TRUE(r.image) << r.error;
        EXPECT_EQ(r.image->width, o >= 5 ? 2 : 3) << o;
    }
}

} // namespace casteljau::testing
