#include "casteljau/io/detail/jpeg_write.h"

#include "casteljau/io/detail/jpeg_errors.h"

#include <cstdio>
#include <cstdlib>

namespace casteljau::detail {

namespace {

// Calls libjpeg, whose errors longjmp back here: no object with a
// destructor. The encoded bytes go to a buffer libjpeg allocates (*buffer).
bool compress(jpeg_compress_struct& c, JpegErrors& e, int w, int h, const std::uint8_t* rgb,
              unsigned char** buffer, unsigned long* size) {
    if (setjmp(e.back)) return false;
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, buffer, size);
    c.image_width = JDIMENSION(w);
    c.image_height = JDIMENSION(h);
    c.input_components = 3;
    c.in_color_space = JCS_RGB;
    jpeg_set_defaults(&c); // YCbCr at 4:2:0, JFIF, baseline Huffman tables
    jpeg_set_quality(&c, kJpegQuality, TRUE);
    jpeg_start_compress(&c, TRUE);
    while (c.next_scanline < c.image_height) {
        auto row = const_cast<JSAMPROW>(rgb + std::size_t(c.next_scanline) * std::size_t(w) * 3);
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    return true;
}

} // namespace

std::string encode_jpeg(int w, int h, std::span<const std::uint8_t> rgb,
                        std::vector<unsigned char>& out) {
    if (w <= 0 || h <= 0 || rgb.size() != std::size_t(w) * std::size_t(h) * 3)
        return "cannot encode a " + std::to_string(w) + " x " + std::to_string(h) + " JPEG from " +
               std::to_string(rgb.size()) + " bytes";
    jpeg_compress_struct c{};
    JpegErrors e{};
    e.attach(reinterpret_cast<j_common_ptr>(&c));
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    const bool ok = compress(c, e, w, h, rgb.data(), &buffer, &size);
    jpeg_destroy_compress(&c);
    if (ok) out.assign(buffer, buffer + size);
    std::free(buffer);
    return ok ? std::string() : std::string(e.message);
}

} // namespace casteljau::detail
