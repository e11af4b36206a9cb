#include "casteljau/io/detail/png_read.h"

#include "casteljau/io/detail/exif_orientation.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <png.h>
#include <vector>

namespace casteljau::detail {

namespace {

/// What libpng's callbacks share: the input, and the last error message.
struct Source {
    std::FILE* file = nullptr;
    const unsigned char* data = nullptr;
    std::size_t size = 0, pos = 0;
    char error[256] = {};
};

// libpng reports errors here and expects no return: it longjmps to the
// setjmp of the function that called it.
void on_error(png_structp png, png_const_charp message) {
    auto* s = static_cast<Source*>(png_get_error_ptr(png));
    std::snprintf(s->error, sizeof s->error, "%s", message);
    png_longjmp(png, 1);
}

void on_warning(png_structp, png_const_charp) {} // ancillary trouble: the image is still good

void read_memory(png_structp png, png_bytep out, png_size_t n) {
    auto* s = static_cast<Source*>(png_get_io_ptr(png));
    if (n > s->size - s->pos) png_error(png, "the data ends before the image does");
    std::memcpy(out, s->data + s->pos, n);
    s->pos += n;
}

// The two functions below call libpng, whose errors longjmp back to their
// setjmp: they hold no object with a destructor.

/// Reads the chunks before the image data and sets the transforms; fills
/// `h`. False on error.
bool read_header(png_structp png, png_infop info, ImageHeader& h, int& bit_depth) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    png_set_expand(png); // palette to RGB, gray below 8 bits to 8, tRNS to alpha
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    h.width = int(png_get_image_width(png, info));
    h.height = int(png_get_image_height(png, info));
    h.depth = 1;
    h.channels = png_get_channels(png, info);
    h.straight = true;
    bit_depth = png_get_bit_depth(png, info);
    png_uint_32 size = 0;
    png_bytep exif = nullptr;
    if (png_get_eXIf_1(png, info, &size, &exif) && exif)
        h.orientation = exif_orientation(exif, size);
    return true;
}

/// Decodes every row, then the chunks after them (their CRCs checked, as
/// OIIO's reader did). False on error.
bool read_rows(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    png_read_end(png, nullptr);
    return true;
}

/// The samples of h rows of w pixels of N channels (16-bit big-endian when
/// Wide, else 8-bit) as floats in [0, 1]: the first `channels` of each
/// pixel's, to the pixel's floats `stride` bytes apart from `out`. Made for
/// each count and depth, so that the compiler unrolls and vectorizes it (a
/// 2048 px RGBA image: 13% of its start to file, tested per sample).
template <std::size_t N, bool Wide>
void to_float(const png_bytep* rows, std::size_t w, std::size_t h, std::size_t channels, float* out,
              std::size_t stride) {
    for (std::size_t y = 0; y < h; ++y)
        for (std::size_t x = 0; x < w; ++x) {
            auto* dst =
                reinterpret_cast<float*>(reinterpret_cast<char*>(out) + (y * w + x) * stride);
            const unsigned char* src = rows[y] + x * N * (Wide ? 2 : 1);
            for (std::size_t c = 0; c < N; ++c)
                if (c < channels)
                    dst[c] = Wide ? float(src[2 * c] << 8 | src[2 * c + 1]) * kSampleScale16
                                  : float(src[c]) * kSampleScale8;
        }
}

using ToFloat = void (*)(const png_bytep*, std::size_t, std::size_t, std::size_t, float*,
                         std::size_t);
/// to_float by [16-bit][channels - 1].
constexpr ToFloat kToFloat[2][4] = {
    {to_float<1, false>, to_float<2, false>, to_float<3, false>, to_float<4, false>},
    {to_float<1, true>, to_float<2, true>, to_float<3, true>, to_float<4, true>}};

class PngReader final : public ImageReader {
  public:
    ~PngReader() override {
        png_destroy_read_struct(&png_, &info_, nullptr);
        if (source_.file) std::fclose(source_.file);
    }
    const ImageHeader& header() const override { return header_; }

    std::string read(int channels, float* out, std::size_t stride) override {
        const std::size_t w = std::size_t(header_.width), h = std::size_t(header_.height);
        const std::size_t row_bytes = png_get_rowbytes(png_, info_);
        std::vector<unsigned char> bytes(row_bytes * h);
        std::vector<png_bytep> rows(h);
        for (std::size_t y = 0; y < h; ++y) rows[y] = bytes.data() + y * row_bytes;
        if (!read_rows(png_, rows.data())) return source_.error;
        // png_get_channels gives 1 to 4.
        kToFloat[bit_depth_ == 16][std::clamp(header_.channels, 1, 4) - 1](
            rows.data(), w, h, std::size_t(channels), out, stride);
        return {};
    }

    Source source_;
    png_structp png_ = nullptr;
    png_infop info_ = nullptr;
    ImageHeader header_;
    int bit_depth_ = 8;
};

} // namespace

PngOpened open_png(const std::string& name, std::span<const unsigned char> memory,
                   bool from_memory) {
    PngOpened r;
    auto reader = std::make_unique<PngReader>();
    Source& s = reader->source_;
    if (from_memory) {
        s.data = memory.data(), s.size = memory.size();
    } else if (!(s.file = std::fopen(name.c_str(), "rb"))) {
        r.error = "cannot open the file";
        return r;
    }
    reader->png_ = png_create_read_struct(PNG_LIBPNG_VER_STRING, &s, on_error, on_warning);
    if (reader->png_) reader->info_ = png_create_info_struct(reader->png_);
    if (!reader->info_) {
        r.error = "out of memory";
        return r;
    }
    if (from_memory)
        png_set_read_fn(reader->png_, &s, read_memory);
    else
        png_init_io(reader->png_, s.file);
    if (!read_header(reader->png_, reader->info_, reader->header_, reader->bit_depth_)) {
        r.error = s.error;
        return r;
    }
    r.reader = std::move(reader);
    return r;
}

} // namespace casteljau::detail
