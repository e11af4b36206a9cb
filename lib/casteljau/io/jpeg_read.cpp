#include "casteljau/io/detail/jpeg_read.h"

#include "casteljau/io/detail/exif_orientation.h"
#include "casteljau/io/detail/jpeg_errors.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <vector>

namespace casteljau::detail {

namespace {

/// An 8-bit sample of OIIO's CMYK to RGB conversion: x k as floats of the
/// samples over 255, scaled back and rounded half up, clamped.
unsigned char times(unsigned char x, unsigned char k) {
    const float v = float(x) * kSampleScale8 * (float(k) * kSampleScale8) * 255.0f + 0.5f;
    return static_cast<unsigned char>(std::clamp(v, 0.0f, 255.0f));
}

// The functions below call libjpeg, whose errors longjmp back to their
// setjmp: they hold no object with a destructor.

/// Starts the decompressor on the file or the bytes; false on error.
bool start(jpeg_decompress_struct& c, JpegErrors& e, std::FILE* file,
           std::span<const unsigned char> memory) {
    if (setjmp(e.back)) return false;
    jpeg_create_decompress(&c);
    if (file)
        jpeg_stdio_src(&c, file);
    else
        jpeg_mem_src(&c, memory.data(), static_cast<unsigned long>(memory.size()));
    return true;
}

/// Reads the markers before the image data and sets the output color
/// space; fills `h`. False on error.
bool read_header(jpeg_decompress_struct& c, JpegErrors& e, ImageHeader& h, bool& cmyk) {
    if (setjmp(e.back)) return false;
    jpeg_save_markers(&c, JPEG_APP0 + 1, 0xffff); // EXIF
    jpeg_read_header(&c, TRUE);
    cmyk = c.jpeg_color_space == JCS_CMYK || c.jpeg_color_space == JCS_YCCK;
    if (cmyk) c.out_color_space = JCS_CMYK; // YCCK to CMYK by libjpeg, to RGB here
    jpeg_calc_output_dimensions(&c);
    h.width = int(c.output_width);
    h.height = int(c.output_height);
    h.depth = 1;
    h.channels = cmyk ? 3 : c.output_components;
    for (jpeg_saved_marker_ptr m = c.marker_list; m; m = m->next)
        if (m->marker == JPEG_APP0 + 1 && m->data_length > 6 &&
            std::memcmp(m->data, "Exif\0\0", 6) == 0) {
            h.orientation = exif_orientation(m->data + 6, m->data_length - 6);
            break;
        }
    return true;
}

/// Decodes every row into `row` one at a time and its first `channels`
/// samples (RGB for CMYK) to floats from `out`, a pixel `stride` bytes
/// apart; then the markers after the image. False on error.
bool read_rows(jpeg_decompress_struct& c, JpegErrors& e, bool cmyk, int channels, JSAMPLE* row,
               float* out, std::size_t stride) {
    if (setjmp(e.back)) return false;
    jpeg_start_decompress(&c);
    const std::size_t w = c.output_width, n = std::size_t(c.output_components);
    while (c.output_scanline < c.output_height) {
        const std::size_t y = c.output_scanline;
        jpeg_read_scanlines(&c, &row, 1);
        for (std::size_t x = 0; x < w; ++x) {
            auto* dst =
                reinterpret_cast<float*>(reinterpret_cast<char*>(out) + (y * w + x) * stride);
            const JSAMPLE* s = row + x * n;
            for (int k = 0; k < channels; ++k)
                dst[k] = float(cmyk ? times(s[k], s[3]) : s[k]) * kSampleScale8;
        }
    }
    jpeg_finish_decompress(&c);
    return true;
}

class JpegReader final : public ImageReader {
  public:
    ~JpegReader() override {
        if (started_) jpeg_destroy_decompress(&c_);
        if (file_) std::fclose(file_);
    }
    const ImageHeader& header() const override { return header_; }
    std::string read(int channels, float* out, std::size_t stride) override {
        std::vector<JSAMPLE> row(std::size_t(c_.output_width) * std::size_t(c_.output_components));
        if (!read_rows(c_, errors_, cmyk_, std::min(channels, header_.channels), row.data(), out,
                       stride))
            return errors_.message;
        return {};
    }

    jpeg_decompress_struct c_{};
    JpegErrors errors_{};
    std::FILE* file_ = nullptr;
    bool started_ = false, cmyk_ = false;
    ImageHeader header_;
};

} // namespace

JpegOpened open_jpeg(const std::string& name, std::span<const unsigned char> memory,
                     bool from_memory) {
    JpegOpened r;
    auto reader = std::make_unique<JpegReader>();
    if (!from_memory && !(reader->file_ = std::fopen(name.c_str(), "rb"))) {
        r.error = "cannot open the file";
        return r;
    }
    jpeg_decompress_struct& c = reader->c_;
    reader->errors_.attach(reinterpret_cast<j_common_ptr>(&c));
    reader->started_ = start(c, reader->errors_, reader->file_, memory);
    if (!reader->started_ || !read_header(c, reader->errors_, reader->header_, reader->cmyk_)) {
        r.error = reader->errors_.message;
        return r;
    }
    r.reader = std::move(reader);
    return r;
}

} // namespace casteljau::detail
