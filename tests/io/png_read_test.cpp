// The library's PNG reader (io/detail/png_read.h) against OpenImageIO's,
// which decoded PNG for <image> before it: on every color type and bit depth
// PNG has, with and without tRNS, interlaced or not, and with an eXIf
// orientation, both report the same header and the same float values, bit
// for bit. The files are written here with libpng.
#include "casteljau/io/detail/png_read.h"
#include "casteljau/io/image_read.h"
#include "corpus.h"
#include "reader_compare.h"

#include <csetjmp>
#include <cstring>
#include <gtest/gtest.h>
#include <png.h>
#include <string>
#include <vector>

namespace casteljau {
namespace {

/// How to write a test PNG.
struct Kind {
    int color_type, bit_depth;
    bool trns = false, interlaced = false;
    int orientation = 0; ///< an eXIf chunk with this Orientation, when not 0
};

void append(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<unsigned char>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

/// An eXIf chunk's TIFF data (big-endian) with one IFD entry: Orientation.
std::vector<unsigned char> exif(int orientation) {
    return {'M', 'M', 0, 42,   0, 0, 0, 8, // byte order, 42, first IFD at 8
            0,   1,   1, 0x12, 0, 3, 0, 0, 0, 1, 0, std::uint8_t(orientation), 0, 0, 0, 0, 0, 0};
}

// libpng's errors longjmp here: nothing with a destructor is made after setjmp.
bool encode(png_structp png, png_infop info, const Kind& k, int w, int h, png_bytepp rows,
            png_colorp palette, int colors, png_bytep alphas, png_color_16p trns_color,
            png_bytep exif_data, std::vector<unsigned char>* out) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_write_fn(png, out, append, nullptr);
    png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), k.bit_depth, k.color_type,
                 k.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (k.color_type == PNG_COLOR_TYPE_PALETTE) png_set_PLTE(png, info, palette, colors);
    if (k.trns) png_set_tRNS(png, info, alphas, colors, trns_color);
    if (k.orientation) png_set_eXIf_1(png, info, 26, exif_data);
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, info);
    return true;
}

/// A w x h PNG of the kind, its samples drawn from `rng`.
std::vector<unsigned char> make_png(const Kind& k, int w, int h, testing::Rng& rng) {
    const int channels = k.color_type == PNG_COLOR_TYPE_RGB          ? 3
                         : k.color_type == PNG_COLOR_TYPE_RGB_ALPHA  ? 4
                         : k.color_type == PNG_COLOR_TYPE_GRAY_ALPHA ? 2
                                                                     : 1;
    const int max = (1 << k.bit_depth) - 1;
    const int colors = k.color_type == PNG_COLOR_TYPE_PALETTE ? 1 << k.bit_depth : 0;
    const std::size_t row_bytes = (std::size_t(w) * channels * k.bit_depth + 7) / 8;
    std::vector<unsigned char> bytes(row_bytes * std::size_t(h), 0);
    std::vector<png_bytep> rows(static_cast<std::size_t>(h));
    // Samples packed big-endian, as PNG stores them (7.2); one value in
    // eight repeats the first, so that tRNS's color matches somewhere.
    for (int y = 0; y < h; ++y) {
        rows[std::size_t(y)] = bytes.data() + std::size_t(y) * row_bytes;
        for (int i = 0; i < w * channels; ++i) {
            const int v = rng.integer(0, 7) == 0 ? 0 : rng.integer(0, max);
            const std::size_t bit = std::size_t(i) * std::size_t(k.bit_depth);
            unsigned char* p = rows[std::size_t(y)] + bit / 8;
            if (k.bit_depth == 16)
                p[0] = std::uint8_t(v >> 8), p[1] = std::uint8_t(v);
            else
                *p |= std::uint8_t(v << (8 - k.bit_depth - int(bit % 8)));
        }
    }
    std::vector<png_color> palette(std::size_t(std::max(colors, 1)));
    std::vector<png_byte> alphas(palette.size());
    for (std::size_t i = 0; i < palette.size(); ++i) {
        palette[i] = {std::uint8_t(rng.integer(0, 255)), std::uint8_t(rng.integer(0, 255)),
                      std::uint8_t(rng.integer(0, 255))};
        alphas[i] = std::uint8_t(rng.integer(0, 255));
    }
    png_color_16 trns_color{0, 0, 0, 0, 0}; // the value 0 of each channel is transparent
    std::vector<unsigned char> exif_data = exif(k.orientation);
    std::vector<unsigned char> out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    const bool ok = encode(png, info, k, w, h, rows.data(), palette.data(), colors, alphas.data(),
                           &trns_color, exif_data.data(), &out);
    png_destroy_write_struct(&png, &info);
    EXPECT_TRUE(ok);
    return out;
}

void expect_same_as_oiio(const std::vector<unsigned char>& png, const std::string& what) {
    detail::PngOpened ours = detail::open_png("memory", png, true);
    testing::expect_same_as_oiio(testing::read_all(std::move(ours.reader), ours.error), "png", png,
                                 what);
}

TEST(PngRead, EveryColorTypeAndDepthDecodesAsOpenImageIODid) {
    testing::Rng rng(2504);
    std::vector<Kind> kinds;
    for (int depth : {1, 2, 4, 8, 16}) kinds.push_back({PNG_COLOR_TYPE_GRAY, depth});
    for (int depth : {1, 2, 4, 8}) kinds.push_back({PNG_COLOR_TYPE_PALETTE, depth});
    for (int depth : {8, 16}) {
        kinds.push_back({PNG_COLOR_TYPE_RGB, depth});
        kinds.push_back({PNG_COLOR_TYPE_GRAY_ALPHA, depth});
        kinds.push_back({PNG_COLOR_TYPE_RGB_ALPHA, depth});
    }
    const std::size_t plain = kinds.size();
    for (std::size_t i = 0; i < plain; ++i) {
        Kind k = kinds[i];
        if (k.color_type != PNG_COLOR_TYPE_GRAY_ALPHA && k.color_type != PNG_COLOR_TYPE_RGB_ALPHA) {
            k.trns = true; // transparency without an alpha channel
            kinds.push_back(k);
        }
        k = kinds[i];
        k.interlaced = true;
        kinds.push_back(k);
    }
    for (const Kind& k : kinds)
        for (const auto& size : {std::pair{1, 1}, std::pair{13, 9}, std::pair{3, 17}}) {
            const std::string what = "type " + std::to_string(k.color_type) + " depth " +
                                     std::to_string(k.bit_depth) + (k.trns ? " tRNS" : "") +
                                     (k.interlaced ? " interlaced " : " ") +
                                     std::to_string(size.first) + "x" + std::to_string(size.second);
            expect_same_as_oiio(make_png(k, size.first, size.second, rng), what);
        }
}

TEST(PngRead, ExifOrientationIsReadAsOpenImageIOReadIt) {
    testing::Rng rng(2505);
    testing::expect_orientations_read_and_applied(
        [&](int o) {
            return make_png({PNG_COLOR_TYPE_RGB, 8, false, false, o}, 3, 2, rng);
        },
        expect_same_as_oiio);
}

// libpng's errors come back as messages (not a longjmp into nowhere, nor a
// crash): a file cut anywhere, and a CRC that does not match.
TEST(PngRead, TruncatedAndCorruptFilesAreErrors) {
    testing::Rng rng(2506);
    auto png = make_png({PNG_COLOR_TYPE_RGB_ALPHA, 8}, 13, 9, rng);
    for (const std::size_t cut :
         {std::size_t(8), std::size_t(33), png.size() / 2, png.size() - 1}) {
        const std::vector<unsigned char> head(png.begin(), png.begin() + std::ptrdiff_t(cut));
        const ImageReadResult r = decode_image(head, 1000);
        EXPECT_FALSE(r.image) << cut;
        EXPECT_NE(r.error.find("cannot decode"), std::string::npos) << r.error;
    }
    png[45] ^= 0x55; // inside IDAT's data (it starts at 41): its CRC no longer matches
    const ImageReadResult r = decode_image(png, 1000);
    EXPECT_FALSE(r.image);
    EXPECT_NE(r.error, "");
}

} // namespace
} // namespace casteljau
