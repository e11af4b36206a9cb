// Written files read back by the formats' own libraries (libpng, libtiff,
// OpenEXR, libjpeg), not by OpenImageIO: whether a file's values are straight
// or premultiplied must be what the format (or, for TIFF, the file's
// ExtraSamples tag) says, since that is what every other program assumes.
// Reading back through OpenImageIO cannot show a mislabel: it undoes on
// reading what it did on writing (a PNG whose color was divided by alpha
// once too often is multiplied on reading, giving back the values written).
//
// The canvases hold swatches of translucent colors composited over
// transparency, each a flat 16 x 16 block (a JPEG MCU at 4:2:0, so that the
// lossy JPEG decodes it flat). The expected values come from what each
// canvas holds (for Canvas8, premultiplied bytes, whose straight color at a
// low alpha is coarser than the swatch's), and must match within one 8-bit
// step (JPEG: see its test).
#include "casteljau/io/canvas_write.h"
#include "casteljau/io/image_write.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <array>
#include <cmath>
#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <jpeglib.h>
#include <memory>
#include <png.h>
#include <string>
#include <tiffio.h>
#include <type_traits>
#include <unistd.h>
#include <vector>

namespace casteljau {
namespace {

namespace fs = std::filesystem;

struct TempDir {
    fs::path path;
    TempDir()
        : path(fs::temp_directory_path() / ("casteljau_readback_" + std::to_string(::getpid()))) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string file(const std::string& name) const { return (path / name).string(); }
};

/// A straight sRGB color in bytes, and its alpha.
struct Swatch {
    int r, g, b;
    float a;
};

// The issue's color first; alpha near 0 and near 1, opaque, and transparent.
constexpr std::array<Swatch, 6> kSwatches{{{0x77, 0x66, 0x99, 0.51f},
                                           {0xff, 0x00, 0x00, 0.02f},
                                           {0x20, 0xc0, 0x40, 0.98f},
                                           {0x33, 0x66, 0x99, 0.25f},
                                           {0xe0, 0xd0, 0x10, 1.0f},
                                           {0x80, 0x80, 0x80, 0.0f}}};
constexpr int kBlock = 16;
constexpr double kStep = 1.0 / 255;

template <class Canvas>
Canvas swatch_canvas() {
    Canvas canvas(kBlock * int(kSwatches.size()), kBlock);
    for (int y = 0; y < canvas.height(); ++y)
        for (int x = 0; x < canvas.width(); ++x) {
            const Swatch& s = kSwatches[std::size_t(x / kBlock)];
            const Rgba c{float(s.r) / 255, float(s.g) / 255, float(s.b) / 255, s.a};
            blend_over(canvas.row(y)[x], premultiply(c), 1.0f);
        }
    return canvas;
}

/// A pixel as the canvas holds it: premultiplied, and straight (0 where transparent).
struct Held {
    std::array<double, 4> premul, straight;
};

template <class Canvas>
Held held(const Canvas& canvas, int x, int y) {
    const Premul p = to_premul(canvas.row(y)[x]);
    const double a = p.a, inv = a > 0 ? 1 / a : 0;
    return {{p.r, p.g, p.b, a}, {p.r * inv, p.g * inv, p.b * inv, a}};
}

double srgb_to_linear(double v) {
    return v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
}

/// Decoded pixels, interleaved, as values in [0, 1].
struct Decoded {
    int width = 0, height = 0, channels = 0;
    std::vector<double> px;
    int extra_sample = -1; ///< TIFF: the alpha's ExtraSamples value
    double at(int x, int y, int c) const {
        return px[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) +
                  std::size_t(c)];
    }
};

// libpng reports errors by longjmp: nothing here is modified after setjmp.
bool png_decode(png_structp png, png_infop info, std::FILE* f) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, f);
    png_read_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    return true;
}

// The samples as stored: no transform at all.
void read_png(const std::string& path, Decoded& d) {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::fopen(path.c_str(), "rb"), std::fclose);
    ASSERT_TRUE(f) << path;
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    ASSERT_TRUE(png);
    png_infop info = png_create_info_struct(png);
    const bool ok = info && png_decode(png, info, f.get());
    if (ok) {
        d.width = int(png_get_image_width(png, info));
        d.height = int(png_get_image_height(png, info));
        d.channels = png_get_channels(png, info);
        const int depth = png_get_bit_depth(png, info), type = png_get_color_type(png, info);
        if (depth == 8 && type == PNG_COLOR_TYPE_RGB_ALPHA) {
            png_bytepp rows = png_get_rows(png, info);
            for (int y = 0; y < d.height; ++y)
                for (int i = 0; i < d.width * d.channels; ++i) d.px.push_back(rows[y][i] / 255.0);
        }
    }
    png_destroy_read_struct(&png, &info, nullptr);
    ASSERT_TRUE(ok) << path;
    ASSERT_EQ(d.channels, 4) << path;
    ASSERT_EQ(d.px.size(), std::size_t(d.width * d.height * 4)) << path << ": not 8-bit RGBA";
}

void read_tiff(const std::string& path, Decoded& d) {
    std::unique_ptr<TIFF, void (*)(TIFF*)> t(TIFFOpen(path.c_str(), "r"), TIFFClose);
    ASSERT_TRUE(t) << path;
    std::uint32_t w = 0, h = 0;
    std::uint16_t channels = 0, bits = 0, format = 0, planar = 0, extras = 0;
    std::uint16_t* extra = nullptr;
    ASSERT_TRUE(TIFFGetField(t.get(), TIFFTAG_IMAGEWIDTH, &w));
    ASSERT_TRUE(TIFFGetField(t.get(), TIFFTAG_IMAGELENGTH, &h));
    ASSERT_TRUE(TIFFGetFieldDefaulted(t.get(), TIFFTAG_SAMPLESPERPIXEL, &channels));
    ASSERT_TRUE(TIFFGetFieldDefaulted(t.get(), TIFFTAG_BITSPERSAMPLE, &bits));
    ASSERT_TRUE(TIFFGetFieldDefaulted(t.get(), TIFFTAG_SAMPLEFORMAT, &format));
    ASSERT_TRUE(TIFFGetFieldDefaulted(t.get(), TIFFTAG_PLANARCONFIG, &planar));
    ASSERT_TRUE(TIFFGetField(t.get(), TIFFTAG_EXTRASAMPLES, &extras, &extra)) << "no alpha";
    ASSERT_EQ(channels, 4);
    ASSERT_EQ(bits, 32);
    ASSERT_EQ(format, SAMPLEFORMAT_IEEEFP);
    ASSERT_EQ(planar, PLANARCONFIG_CONTIG);
    ASSERT_EQ(extras, 1);
    ASSERT_FALSE(TIFFIsTiled(t.get()));
    d.width = int(w), d.height = int(h), d.channels = 4, d.extra_sample = extra[0];
    std::vector<float> row(std::size_t(w) * 4);
    for (std::uint32_t y = 0; y < h; ++y) {
        ASSERT_EQ(TIFFReadScanline(t.get(), row.data(), y, 0), 1) << path << " row " << y;
        d.px.insert(d.px.end(), row.begin(), row.end());
    }
}

void read_exr(const std::string& path, Decoded& d) {
    Imf::InputFile file(path.c_str());
    const Imath::Box2i window = file.header().dataWindow();
    ASSERT_EQ(window.min.x, 0);
    ASSERT_EQ(window.min.y, 0);
    d.width = window.max.x + 1, d.height = window.max.y + 1, d.channels = 4;
    std::vector<float> px(std::size_t(d.width) * std::size_t(d.height) * 4);
    Imf::FrameBuffer buffer;
    const char* names[] = {"R", "G", "B", "A"};
    for (int c = 0; c < 4; ++c) {
        ASSERT_TRUE(file.header().channels().findChannel(names[c])) << path << " " << names[c];
        buffer.insert(names[c],
                      Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(&px[std::size_t(c)]),
                                 4 * sizeof(float), std::size_t(d.width) * 4 * sizeof(float)));
    }
    file.setFrameBuffer(buffer);
    file.readPixels(0, window.max.y);
    d.px.assign(px.begin(), px.end());
}

struct JpegError {
    jpeg_error_mgr mgr;
    std::jmp_buf jump;
};

[[noreturn]] void jpeg_fail(j_common_ptr j) {
    std::longjmp(reinterpret_cast<JpegError*>(j->err)->jump, 1);
}

// libjpeg reports errors through error_exit: here by longjmp, and nothing is
// modified after setjmp.
bool jpeg_decode(jpeg_decompress_struct* j, JpegError* err, const std::string& bytes, Decoded* d) {
    if (setjmp(err->jump)) return false;
    jpeg_mem_src(j, reinterpret_cast<const unsigned char*>(bytes.data()), bytes.size());
    jpeg_read_header(j, TRUE);
    j->out_color_space = JCS_RGB;
    // Chroma is stored at half resolution; the default (fancy) upsampling
    // blends it across the swatches' borders, the plain one keeps each flat.
    j->do_fancy_upsampling = FALSE;
    jpeg_start_decompress(j);
    d->width = int(j->output_width), d->height = int(j->output_height), d->channels = 3;
    std::vector<unsigned char> row(std::size_t(d->width) * 3);
    while (j->output_scanline < j->output_height) {
        JSAMPROW p = row.data();
        jpeg_read_scanlines(j, &p, 1);
        for (unsigned char v : row) d->px.push_back(v / 255.0);
    }
    jpeg_finish_decompress(j);
    return true;
}

void read_jpeg(const std::string& path, Decoded& d) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), {}};
    ASSERT_FALSE(bytes.empty()) << path;
    jpeg_decompress_struct j{};
    JpegError err{};
    j.err = jpeg_std_error(&err.mgr);
    err.mgr.error_exit = jpeg_fail;
    jpeg_create_decompress(&j);
    const bool ok = jpeg_decode(&j, &err, bytes, &d);
    jpeg_destroy_decompress(&j);
    ASSERT_TRUE(ok) << path;
    ASSERT_EQ(d.channels, 3);
}

/// Compares every pixel of `d` with `want(held pixel)` (channels of `d`),
/// within `tol`; color only where the held alpha is not 0 when `skip_clear`.
template <class Canvas, class Want>
void expect_pixels(const Canvas& canvas, const Decoded& d, const std::string& what, Want want,
                   bool skip_clear, double tol = kStep) {
    ASSERT_EQ(d.width, canvas.width()) << what;
    ASSERT_EQ(d.height, canvas.height()) << what;
    int bad = 0;
    for (int y = 0; y < d.height; ++y)
        for (int x = 0; x < d.width; ++x) {
            const Held h = held(canvas, x, y);
            const std::array<double, 4> e = want(h);
            for (int c = 0; c < d.channels; ++c) {
                if (skip_clear && c < 3 && h.premul[3] == 0) continue;
                const double got = d.at(x, y, c);
                if (std::abs(got - e[std::size_t(c)]) > tol && bad++ < 8)
                    ADD_FAILURE() << what << ": swatch " << x / kBlock << " pixel (" << x << ", "
                                  << y << ") channel " << c << ": " << got * 255 << " / 255, want "
                                  << e[std::size_t(c)] * 255 << " / 255";
            }
        }
    EXPECT_EQ(bad, 0) << what << ": channels off by more than " << tol * 255 << " / 255";
}

template <class Canvas>
class ImageReadback : public ::testing::Test {
  public:
    static std::string name() { return std::is_same_v<Canvas, Canvas8> ? "Canvas8" : "Canvas"; }
};
using Canvases = ::testing::Types<Canvas, Canvas8>;
TYPED_TEST_SUITE(ImageReadback, Canvases);

// PNG stores straight alpha: the color bytes are the swatch's (the held
// color un-premultiplied), the alpha byte round(255 a).
TYPED_TEST(ImageReadback, PngHoldsStraightColorAndAlpha) {
    TempDir dir;
    const auto canvas = swatch_canvas<TypeParam>();
    const std::string path = dir.file("a.png");
    ASSERT_EQ(write_canvas_atomic(path, canvas), "");
    Decoded d;
    ASSERT_NO_FATAL_FAILURE(read_png(path, d));
    expect_pixels(
        canvas, d, this->name() + " png", [](const Held& h) { return h.straight; }, true);
}

// TIFF may store either convention, but the ExtraSamples tag must say which
// one the values are in.
TYPED_TEST(ImageReadback, TiffValuesAgreeWithItsExtraSamplesTag) {
    TempDir dir;
    const auto canvas = swatch_canvas<TypeParam>();
    const std::string path = dir.file("a.tif");
    ASSERT_EQ(write_canvas_atomic(path, canvas), "");
    Decoded d;
    ASSERT_NO_FATAL_FAILURE(read_tiff(path, d));
    ASSERT_TRUE(d.extra_sample == EXTRASAMPLE_UNASSALPHA ||
                d.extra_sample == EXTRASAMPLE_ASSOCALPHA)
        << "ExtraSamples " << d.extra_sample;
    const bool straight = d.extra_sample == EXTRASAMPLE_UNASSALPHA;
    expect_pixels(
        canvas, d, this->name() + (straight ? " tiff (unassociated)" : " tiff (associated)"),
        [straight](const Held& h) { return straight ? h.straight : h.premul; }, straight);
}

// EXR is scene-linear and premultiplied: the linear straight color times alpha.
TYPED_TEST(ImageReadback, ExrHoldsLinearPremultipliedColor) {
    TempDir dir;
    const auto canvas = swatch_canvas<TypeParam>();
    const std::string path = dir.file("a.exr");
    ASSERT_EQ(write_canvas_atomic(path, canvas), "");
    Decoded d;
    ASSERT_NO_FATAL_FAILURE(read_exr(path, d));
    expect_pixels(
        canvas, d, this->name() + " exr",
        [](const Held& h) {
            const double a = h.straight[3];
            return std::array<double, 4>{srgb_to_linear(h.straight[0]) * a,
                                         srgb_to_linear(h.straight[1]) * a,
                                         srgb_to_linear(h.straight[2]) * a, a};
        },
        false);
}

// JPEG has no alpha: the color over white, c a + (1 - a), in sRGB. Within
// 2.5 steps rather than one: the color is stored as 8-bit YCbCr, rounded on
// the way in and out (blue = Y + 1.772 (Cb - 128) turns half a step of Cb
// into 0.9; 1.5 steps measured). Over black instead would be 120 steps off
// for the issue's color.
TYPED_TEST(ImageReadback, JpegHoldsTheColorOverWhite) {
    TempDir dir;
    const auto canvas = swatch_canvas<TypeParam>();
    const std::string path = dir.file("a.jpg");
    ASSERT_EQ(write_canvas_atomic(path, canvas), "");
    Decoded d;
    ASSERT_NO_FATAL_FAILURE(read_jpeg(path, d));
    expect_pixels(
        canvas, d, this->name() + " jpeg",
        [](const Held& h) {
            const double k = 1 - h.premul[3];
            return std::array<double, 4>{h.premul[0] + k, h.premul[1] + k, h.premul[2] + k, 1};
        },
        false, 2.5 * kStep);
}

// The issue's file: #776699 at fill-opacity 0.51 over transparency is
// (0x77, 0x66, 0x99, 130) in the PNG, as rsvg-convert writes it, from either canvas.
TYPED_TEST(ImageReadback, TheIssueColorIsWrittenOnce) {
    TempDir dir;
    TypeParam canvas(10, 10);
    canvas.fill(premultiply(Rgba{0x77 / 255.0f, 0x66 / 255.0f, 0x99 / 255.0f, 0.51f}));
    const std::string path = dir.file("issue.png");
    ASSERT_EQ(write_canvas_atomic(path, canvas), "");
    Decoded d;
    ASSERT_NO_FATAL_FAILURE(read_png(path, d));
    const int want[4] = {0x77, 0x66, 0x99, 130};
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(d.at(5, 5, c) * 255, want[c], 1.0) << "channel " << c;
}

// write_image_atomic on its own: the file agrees with what the view says its
// pixels are, whichever that is.
TEST(ImageViewAlpha, EachFormatAgreesWithTheStatedConvention) {
    TempDir dir;
    // One pixel, straight: color (0.6, 0.4, 0.2), alpha 0.5; and premultiplied.
    const std::vector<float> straight{0.6f, 0.4f, 0.2f, 0.5f};
    const std::vector<float> premul{0.3f, 0.2f, 0.1f, 0.5f};
    const std::array<double, 4> want_straight{0.6, 0.4, 0.2, 0.5};
    const std::array<double, 4> want_premul{0.3, 0.2, 0.1, 0.5};
    const auto expect_near = [](const Decoded& d, const std::array<double, 4>& want,
                                const std::string& what, double tol) {
        for (int c = 0; c < 4; ++c)
            EXPECT_NEAR(d.at(0, 0, c), want[std::size_t(c)], tol) << what << " channel " << c;
    };
    for (const Alpha alpha : {Alpha::straight, Alpha::premultiplied}) {
        const std::string tag = alpha == Alpha::straight ? "straight" : "premultiplied";
        const ImageView view{1, 1, alpha == Alpha::straight ? straight : premul, alpha};
        {
            // PNG is straight: premultiplied pixels are divided (after 8-bit
            // rounding, hence the extra step).
            Decoded d;
            ASSERT_EQ(write_image_atomic(dir.file(tag + ".png"), view), "");
            ASSERT_NO_FATAL_FAILURE(read_png(dir.file(tag + ".png"), d));
            expect_near(d, want_straight, tag + " png", 2 * kStep);
        }
        {
            // TIFF keeps the values and labels them.
            Decoded d;
            ASSERT_EQ(write_image_atomic(dir.file(tag + ".tif"), view), "");
            ASSERT_NO_FATAL_FAILURE(read_tiff(dir.file(tag + ".tif"), d));
            EXPECT_EQ(d.extra_sample,
                      alpha == Alpha::straight ? EXTRASAMPLE_UNASSALPHA : EXTRASAMPLE_ASSOCALPHA)
                << tag;
            expect_near(d, alpha == Alpha::straight ? want_straight : want_premul, tag + " tiff",
                        1e-6);
        }
        {
            // EXR is premultiplied: straight pixels are premultiplied.
            Decoded d;
            ASSERT_EQ(write_image_atomic(dir.file(tag + ".exr"), view), "");
            ASSERT_NO_FATAL_FAILURE(read_exr(dir.file(tag + ".exr"), d));
            expect_near(d, want_premul, tag + " exr", 1e-6);
        }
    }
}

} // namespace
} // namespace casteljau
