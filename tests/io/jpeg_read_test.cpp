// The library's JPEG reader (io/detail/jpeg_read.h) against OpenImageIO's,
// which decoded JPEG for <image> before it: gray, YCbCr at every chroma
// subsampling, RGB, progressive, with restart markers, CMYK and YCCK (as
// Adobe's files store them), odd sizes, and an EXIF orientation; both
// report the same header and the same float values, bit for bit. The files
// are written here with libjpeg.
#include "casteljau/io/detail/jpeg_read.h"
#include "casteljau/io/image_read.h"
#include "corpus.h"
#include "reader_compare.h"

#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <gtest/gtest.h>
#include <string>
#include <vector>
// jpeglib.h needs FILE and size_t declared before it.
#include <jpeglib.h>

namespace casteljau {
namespace {

/// How to write a test JPEG.
struct Kind {
    J_COLOR_SPACE in = JCS_RGB; ///< the samples given: JCS_GRAYSCALE, JCS_RGB or JCS_CMYK
    J_COLOR_SPACE stored = JCS_YCbCr;
    int h_sampling = 1, v_sampling = 1; ///< the first component's (chroma subsampling)
    bool progressive = false;
    int restart_rows = 0;
    int orientation = 0; ///< an APP1 EXIF marker with this Orientation, when not 0
};

/// An EXIF block (little-endian TIFF) with one IFD entry: Orientation.
std::vector<unsigned char> exif(int orientation) {
    return {'E',
            'x',
            'i',
            'f',
            0,
            0, // the marker's signature
            'I',
            'I',
            42,
            0,
            8,
            0,
            0,
            0, // byte order, 42, first IFD at 8
            1,
            0,
            0x12,
            1,
            3,
            0,
            1,
            0,
            0,
            0, // one entry: 274, SHORT, count 1
            std::uint8_t(orientation),
            0,
            0,
            0,
            0,
            0,
            0,
            0}; // its value; no next IFD
}

struct Sink {
    jpeg_error_mgr mgr;
    std::jmp_buf back;
};

[[noreturn]] void on_error(j_common_ptr c) {
    std::longjmp(reinterpret_cast<Sink*>(c->err)->back, 1);
}

// libjpeg's errors longjmp here: nothing with a destructor is made after setjmp.
bool encode(jpeg_compress_struct& c, Sink& sink, const Kind& k, int w, int h, int components,
            const unsigned char* samples, const std::vector<unsigned char>& exif_data,
            unsigned char** out, unsigned long* size) {
    if (setjmp(sink.back)) return false;
    jpeg_create_compress(&c);
    jpeg_mem_dest(&c, out, size);
    c.image_width = JDIMENSION(w);
    c.image_height = JDIMENSION(h);
    c.input_components = components;
    c.in_color_space = k.in;
    jpeg_set_defaults(&c);
    jpeg_set_colorspace(&c, k.stored);
    c.comp_info[0].h_samp_factor = k.h_sampling;
    c.comp_info[0].v_samp_factor = k.v_sampling;
    if (k.progressive) jpeg_simple_progression(&c);
    c.restart_in_rows = k.restart_rows;
    jpeg_set_quality(&c, 80, TRUE);
    jpeg_start_compress(&c, TRUE);
    if (k.orientation)
        jpeg_write_marker(&c, JPEG_APP0 + 1, exif_data.data(), unsigned(exif_data.size()));
    while (c.next_scanline < c.image_height) {
        JSAMPROW row = const_cast<JSAMPROW>(samples + std::size_t(c.next_scanline) *
                                                          std::size_t(w * components));
        jpeg_write_scanlines(&c, &row, 1);
    }
    jpeg_finish_compress(&c);
    return true;
}

/// A w x h JPEG of the kind, its samples smooth ramps and noise from `rng`.
std::vector<unsigned char> make_jpeg(const Kind& k, int w, int h, testing::Rng& rng) {
    const int components = k.in == JCS_GRAYSCALE ? 1 : k.in == JCS_CMYK ? 4 : 3;
    std::vector<unsigned char> samples(std::size_t(w * h * components));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            for (int c = 0; c < components; ++c)
                samples[std::size_t((y * w + x) * components + c)] = std::uint8_t(
                    std::clamp((x * 37 + y * 11 + c * 60) % 256 + rng.integer(-40, 40), 0, 255));
    const std::vector<unsigned char> exif_data = exif(k.orientation);
    jpeg_compress_struct c{};
    Sink sink{};
    c.err = jpeg_std_error(&sink.mgr);
    sink.mgr.error_exit = on_error;
    unsigned char* buffer = nullptr;
    unsigned long size = 0;
    const bool ok = encode(c, sink, k, w, h, components, samples.data(), exif_data, &buffer, &size);
    jpeg_destroy_compress(&c);
    EXPECT_TRUE(ok);
    std::vector<unsigned char> out(buffer, buffer + size);
    std::free(buffer);
    return out;
}

void expect_same_as_oiio(const std::vector<unsigned char>& jpeg, const std::string& what) {
    detail::JpegOpened ours = detail::open_jpeg("memory", jpeg, true);
    testing::expect_same_as_oiio(testing::read_all(std::move(ours.reader), ours.error), "jpeg",
                                 jpeg, what);
}

TEST(JpegRead, EveryColorSpaceAndSubsamplingDecodesAsOpenImageIODid) {
    testing::Rng rng(2507);
    const std::vector<std::pair<std::string, Kind>> kinds = {
        {"gray", {JCS_GRAYSCALE, JCS_GRAYSCALE}},
        {"YCbCr 4:4:4", {JCS_RGB, JCS_YCbCr, 1, 1}},
        {"YCbCr 4:2:2", {JCS_RGB, JCS_YCbCr, 2, 1}},
        {"YCbCr 4:2:0", {JCS_RGB, JCS_YCbCr, 2, 2}},
        {"YCbCr 4:4:0", {JCS_RGB, JCS_YCbCr, 1, 2}},
        {"RGB", {JCS_RGB, JCS_RGB}},
        {"progressive", {JCS_RGB, JCS_YCbCr, 2, 2, true}},
        {"progressive gray", {JCS_GRAYSCALE, JCS_GRAYSCALE, 1, 1, true}},
        {"restarts", {JCS_RGB, JCS_YCbCr, 2, 2, false, 1}},
        {"CMYK", {JCS_CMYK, JCS_CMYK}},
        {"YCCK", {JCS_CMYK, JCS_YCCK}},
    };
    for (const auto& [name, k] : kinds)
        for (const auto& size :
             {std::pair{1, 1}, std::pair{13, 9}, std::pair{3, 17}, std::pair{37, 23}})
            expect_same_as_oiio(make_jpeg(k, size.first, size.second, rng),
                                name + " " + std::to_string(size.first) + "x" +
                                    std::to_string(size.second));
}

TEST(JpegRead, ExifOrientationIsReadAsOpenImageIOReadIt) {
    testing::Rng rng(2508);
    testing::expect_orientations_read_and_applied(
        [&](int o) {
            Kind k;
            k.orientation = o;
            return make_jpeg(k, 3, 2, rng);
        },
        expect_same_as_oiio);
}

// libjpeg's errors come back as messages (not its default: exiting the
// process): a file cut before its image data, and bytes that are no JPEG
// past the signature. A file cut inside its image data is drawn with what
// it holds, as OpenImageIO drew it.
TEST(JpegRead, BrokenFilesAreErrorsAndCutOnesAreDrawn) {
    testing::Rng rng(2509);
    const auto jpeg = make_jpeg({}, 37, 23, rng);
    for (const std::size_t cut : {std::size_t(3), std::size_t(20), std::size_t(150)}) {
        const std::vector<unsigned char> head(jpeg.begin(), jpeg.begin() + std::ptrdiff_t(cut));
        const ImageReadResult r = decode_image(head, 1000);
        EXPECT_FALSE(r.image) << cut;
        EXPECT_NE(r.error.find("cannot decode"), std::string::npos) << r.error;
    }
    std::vector<unsigned char> garbage = {0xff, 0xd8, 0xff, 0x00, 0x13, 0x37, 0x42};
    EXPECT_FALSE(decode_image(garbage, 1000).image);
    const std::vector<unsigned char> cut(jpeg.begin(),
                                         jpeg.end() - std::ptrdiff_t(jpeg.size() / 3));
    expect_same_as_oiio(cut, "cut inside the image data");
}

} // namespace
} // namespace casteljau
