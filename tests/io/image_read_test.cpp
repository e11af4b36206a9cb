// Reading images: each format's pixels come back premultiplied exactly once,
// gray expanded and alpha added, EXIF orientation applied as TIFF 6.0
// defines it, memory and file decodes agree, and oversized or
// broken input is refused with a message, cheaply and without a crash.
#include "casteljau/io/image_read.h"
#include "cpu_time.h"

#include <OpenImageIO/imageio.h>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <random>
#include <string>
#include <sys/resource.h>
#include <unistd.h>
#include <vector>

namespace casteljau {
namespace {

namespace fs = std::filesystem;
using testing::cpu_seconds;

constexpr std::size_t kLimit = 1 << 24;

// Names built with +=, not "literal" + std::to_string(...): GCC 12 at -O3
// warns (-Wrestrict) about a false overlap in that operator+.
std::string numbered(std::string name, int n) {
    name += std::to_string(n);
    return name;
}

struct TempDir {
    fs::path path;
    TempDir() : path(fs::temp_directory_path() / numbered("casteljau_imgread_", ::getpid())) {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~TempDir() {
        std::error_code ec;
        fs::remove_all(path, ec);
    }
    std::string operator/(const std::string& name) const { return (path / name).string(); }
};

/// Writes 8-bit pixels with OIIO's writer, labelled straight (1) or
/// associated (0) when `unassociated` is not -1, with an Orientation when set.
void write_image(const std::string& path, int w, int h, int channels,
                 const std::vector<unsigned char>& px, int unassociated = -1, int orientation = 0) {
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out) << path;
    OIIO::ImageSpec spec(w, h, channels, OIIO::TypeDesc::UINT8);
    if (unassociated >= 0) spec.attribute("oiio:UnassociatedAlpha", unassociated);
    if (orientation) spec.attribute("Orientation", orientation);
    ASSERT_TRUE(out->open(path, spec)) << out->geterror();
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, px.data())) << out->geterror();
    ASSERT_TRUE(out->close());
}

void write_bytes(const std::string& path, const std::vector<unsigned char>& b) {
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

std::vector<unsigned char> file_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void expect_pixel(const RasterImage& im, int x, int y, Premul want, float tol,
                  const std::string& what) {
    const Premul& p = im.at(x, y);
    EXPECT_NEAR(p.r, want.r, tol) << what << " (" << x << ", " << y << ") r";
    EXPECT_NEAR(p.g, want.g, tol) << what << " (" << x << ", " << y << ") g";
    EXPECT_NEAR(p.b, want.b, tol) << what << " (" << x << ", " << y << ") b";
    EXPECT_NEAR(p.a, want.a, tol) << what << " (" << x << ", " << y << ") a";
}

/// Straight 8-bit RGBA as the premultiplied float color it stands for.
Premul premul8(int r, int g, int b, int a) {
    const float k = float(a) / 255;
    return {float(r) / 255 * k, float(g) / 255 * k, float(b) / 255 * k, k};
}

bool same_pixels(const RasterImage& a, const RasterImage& b) {
    if (a.width != b.width || a.height != b.height) return false;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        const Premul &p = a.pixels[i], &q = b.pixels[i];
        if (p.r != q.r || p.g != q.g || p.b != q.b || p.a != q.a) return false;
    }
    return true;
}

/// Decodes `path` from the file and from its bytes, expects both to succeed
/// with the same pixels, and returns the image.
std::shared_ptr<const RasterImage> read_both(const std::string& path) {
    const ImageReadResult f = read_image_file(path, kLimit);
    EXPECT_EQ(f.error, "") << path;
    const std::vector<unsigned char> bytes = file_bytes(path);
    const ImageReadResult m = decode_image(bytes, kLimit);
    EXPECT_EQ(m.error, "") << path;
    if (!f.image || !m.image) return nullptr;
    EXPECT_TRUE(same_pixels(*f.image, *m.image)) << path;
    return f.image;
}

TEST(ImageRead, StraightAlphaPngIsPremultipliedOnce) {
    TempDir dir;
    const std::string path = dir / "straight.png";
    write_image(path, 2, 1, 4, {200, 100, 50, 128, 10, 20, 30, 0}, 1);
    const auto im = read_both(path);
    ASSERT_TRUE(im);
    ASSERT_EQ(im->width, 2);
    ASSERT_EQ(im->height, 1);
    // Premultiplied in float: exact to float rounding, not to 1/255.
    expect_pixel(*im, 0, 0, premul8(200, 100, 50, 128), 1e-6f, "translucent");
    expect_pixel(*im, 1, 0, {0, 0, 0, 0}, 0, "transparent");
}

TEST(ImageRead, GrayAndGrayAlphaPngBecomeRgba) {
    TempDir dir;
    write_image(dir / "gray.png", 2, 1, 1, {0, 153});
    write_image(dir / "graya.png", 1, 1, 2, {102, 51}, 1);
    const auto gray = read_both(dir / "gray.png");
    ASSERT_TRUE(gray);
    expect_pixel(*gray, 0, 0, {0, 0, 0, 1}, 0, "gray");
    expect_pixel(*gray, 1, 0, premul8(153, 153, 153, 255), 1e-6f, "gray");
    const auto graya = read_both(dir / "graya.png");
    ASSERT_TRUE(graya);
    expect_pixel(*graya, 0, 0, premul8(102, 102, 102, 51), 1e-6f, "gray alpha");
}

TEST(ImageRead, JpegHasOpaqueSrgbValues) {
    TempDir dir;
    std::vector<unsigned char> px;
    for (int i = 0; i < 16 * 16; ++i) px.insert(px.end(), {200, 120, 40});
    write_image(dir / "a.jpg", 16, 16, 3, px);
    const auto im = read_both(dir / "a.jpg");
    ASSERT_TRUE(im);
    ASSERT_EQ(im->width, 16);
    // A flat color survives JPEG within a few levels; alpha is exactly 1.
    expect_pixel(*im, 7, 9, premul8(200, 120, 40, 255), 3.0f / 255, "jpeg");
    for (const Premul& p : im->pixels) ASSERT_EQ(p.a, 1.0f);
}

TEST(ImageRead, GifPaletteAndTransparency) {
    TempDir dir;
    write_image(dir / "a.gif", 3, 1, 3, {255, 0, 0, 0, 0, 255, 9, 9, 9});
    const auto im = read_both(dir / "a.gif");
    ASSERT_TRUE(im);
    ASSERT_EQ(im->width, 3);
    expect_pixel(*im, 0, 0, {1, 0, 0, 1}, 0, "gif");
    expect_pixel(*im, 1, 0, {0, 0, 1, 1}, 0, "gif");
    expect_pixel(*im, 2, 0, premul8(9, 9, 9, 255), 1e-6f, "gif");
    // OIIO's GIF writer drops alpha: a 2 x 1 GIF by hand, palette red and
    // white, red transparent (graphic control extension), pixels 0 and 1
    // (LZW, 3-bit codes: clear 4, 0, 1, end 5).
    // clang-format off
    write_bytes(dir / "t.gif", {'G', 'I', 'F', '8', '9', 'a', 2, 0, 1, 0, 0x80, 0, 0, // screen
                                0xff, 0, 0, 0xff, 0xff, 0xff,                        // palette
                                0x21, 0xf9, 4, 1, 0, 0, 0, 0,                        // GCE
                                0x2c, 0, 0, 0, 0, 2, 0, 1, 0, 0,                     // image
                                2, 2, 0x44, 0x0a, 0, 0x3b});                         // LZW, end
    // clang-format on
    const auto t = read_both(dir / "t.gif");
    ASSERT_TRUE(t);
    expect_pixel(*t, 0, 0, {0, 0, 0, 0}, 0, "gif transparent");
    expect_pixel(*t, 1, 0, {1, 1, 1, 1}, 0, "gif opaque");
}

TEST(ImageRead, TiffStraightAndAssociatedAlphaBothEndPremultiplied) {
    TempDir dir;
    // The same premultiplied color, stored once straight and once associated.
    write_image(dir / "straight.tif", 1, 1, 4, {200, 100, 50, 128}, 1);
    write_image(dir / "assoc.tif", 1, 1, 4, {100, 50, 25, 128}, 0);
    const auto straight = read_both(dir / "straight.tif");
    const auto assoc = read_both(dir / "assoc.tif");
    ASSERT_TRUE(straight && assoc);
    expect_pixel(*straight, 0, 0, premul8(200, 100, 50, 128), 1e-6f, "straight tiff");
    expect_pixel(*assoc, 0, 0, {100.0f / 255, 50.0f / 255, 25.0f / 255, 128.0f / 255}, 1e-6f,
                 "associated tiff");
}

// 2 x 2 lossless WebP made with libwebp 1.2.4's WebPEncodeLosslessRGBA from
// the straight pixels (255, 128, 64, 128) (51, 102, 153, 255) (0, 0, 0, 0)
// (10, 20, 30, 40): OIIO's WebP writer is lossy and its output unreliable.
const std::vector<unsigned char> kWebp = {
    0x52, 0x49, 0x46, 0x46, 0x42, 0x00, 0x00, 0x00, 0x57, 0x45, 0x42, 0x50, 0x56, 0x50, 0x38,
    0x4c, 0x35, 0x00, 0x00, 0x00, 0x2f, 0x01, 0x40, 0x00, 0x10, 0x1f, 0x20, 0x10, 0x20, 0x44,
    0xc8, 0xd4, 0xad, 0x49, 0x48, 0x40, 0xc8, 0xf6, 0xf8, 0xff, 0x4a, 0x57, 0xc8, 0x36, 0x02,
    0x1c, 0x1a, 0xc9, 0x7d, 0x56, 0x27, 0x10, 0x20, 0xe4, 0x48, 0x72, 0x63, 0x3d, 0x00, 0x54,
    0xf6, 0xba, 0x0f, 0xb2, 0x01, 0xca, 0x54, 0x61, 0x16, 0xd1, 0xff, 0xf8, 0x00, 0x00};

TEST(ImageRead, WebpIsPremultipliedOnce) {
    TempDir dir;
    write_bytes(dir / "a.webp", kWebp);
    const auto im = read_both(dir / "a.webp");
    ASSERT_TRUE(im);
    ASSERT_EQ(im->width, 2);
    ASSERT_EQ(im->height, 2);
    // OIIO premultiplies WebP itself, in 8 bits: within 1/255.
    const float tol = 1.0f / 255;
    expect_pixel(*im, 0, 0, premul8(255, 128, 64, 128), tol, "webp");
    expect_pixel(*im, 1, 0, premul8(51, 102, 153, 255), tol, "webp");
    expect_pixel(*im, 0, 1, {0, 0, 0, 0}, tol, "webp");
    expect_pixel(*im, 1, 1, premul8(10, 20, 30, 40), tol, "webp");
}

// Every orientation of a 3 x 2 image, stored   A B C
//                                              D E F,
// as TIFF 6.0 (8, Orientation) defines it: where the stored row 0 and
// column 0 go. Written out, not OIIO's ImageBufAlgo::reorient: OIIO 2.4
// swaps 5 and 7 (OpenImageIO issue #4661).
TEST(ImageRead, OrientationIsAppliedAsTiffDefinesIt) {
    TempDir dir;
    std::vector<unsigned char> px;
    for (int i = 0; i < 6; ++i) px.insert(px.end(), {(unsigned char)(40 * i), 7, 200});
    const std::vector<std::string> shown = {
        "ABC/DEF",  // 1: row 0 at the top, column 0 at the left
        "CBA/FED",  // 2: top, right
        "FED/CBA",  // 3: bottom, right
        "DEF/ABC",  // 4: bottom, left
        "AD/BE/CF", // 5: left, top (transpose)
        "DA/EB/FC", // 6: right, top (a quarter turn clockwise)
        "FC/EB/DA", // 7: right, bottom (transverse)
        "CF/BE/AD", // 8: left, bottom (a quarter turn anticlockwise)
    };
    for (int o = 1; o <= 8; ++o) {
        const std::string path = dir / (numbered("o", o) + ".tif");
        write_image(path, 3, 2, 3, px, -1, o);
        const auto im = read_both(path);
        ASSERT_TRUE(im) << o;
        const std::string& want = shown[std::size_t(o - 1)];
        ASSERT_EQ(im->width, int(want.find('/'))) << o;
        ASSERT_EQ(im->height, 6 / im->width) << o;
        for (int y = 0; y < im->height; ++y)
            for (int x = 0; x < im->width; ++x) {
                const int label = want[std::size_t(y * (im->width + 1) + x)] - 'A';
                expect_pixel(*im, x, y, premul8(40 * label, 7, 200, 255), 1e-6f,
                             numbered("orientation ", o));
            }
    }
    // JPEG's EXIF orientation too: 6 turns the 3 x 2 image into 2 x 3.
    write_image(dir / "o6.jpg", 3, 2, 3, px, -1, 6);
    const auto jpeg = read_both(dir / "o6.jpg");
    ASSERT_TRUE(jpeg);
    EXPECT_EQ(jpeg->width, 2);
    EXPECT_EQ(jpeg->height, 3);
}

std::uint32_t crc32(const std::vector<unsigned char>& bytes, std::size_t from) {
    std::uint32_t c = 0xffffffff;
    for (std::size_t i = from; i < bytes.size(); ++i) {
        c ^= bytes[i];
        for (int k = 0; k < 8; ++k) c = c & 1 ? 0xedb88320 ^ (c >> 1) : c >> 1;
    }
    return ~c;
}

void put32(std::vector<unsigned char>& b, std::uint32_t v) {
    for (int s = 24; s >= 0; s -= 8) b.push_back(static_cast<unsigned char>(v >> s));
}

/// A PNG signature and a valid IHDR for w x h RGBA, then a truncated IDAT.
std::vector<unsigned char> png_header(std::uint32_t w, std::uint32_t h) {
    std::vector<unsigned char> b = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
    put32(b, 13);
    const std::size_t type = b.size();
    b.insert(b.end(), {'I', 'H', 'D', 'R'});
    put32(b, w);
    put32(b, h);
    b.insert(b.end(), {8, 6, 0, 0, 0}); // 8 bits, RGBA, deflate, no filter, no interlace
    put32(b, crc32(b, type));
    put32(b, 1000);
    b.insert(b.end(), {'I', 'D', 'A', 'T', 0x78, 0x9c, 0x62});
    return b;
}

long peak_rss_kb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return u.ru_maxrss;
}

TEST(ImageRead, OversizedHeadersAreRefusedBeforeDecoding) {
    TempDir dir;
    const auto png = png_header(100000, 100000);
    write_bytes(dir / "big.png", png);
    // GIF: 65535 x 65535 logical screen; WebP: a 16383 x 16383 VP8L header.
    const std::vector<unsigned char> gif = {'G',  'I',  'F',  '8', '9', 'a', 0xff,
                                            0xff, 0xff, 0xff, 0,   0,   0,   0x3b};
    std::vector<unsigned char> webp = {'R', 'I', 'F', 'F', 30,  0,  0, 0, 'W', 'E', 'B',
                                       'P', 'V', 'P', '8', 'L', 10, 0, 0, 0,   0x2f};
    const std::uint32_t bits = 16382 | 16382u << 14 | 1u << 28;
    for (int s = 0; s < 32; s += 8) webp.push_back(static_cast<unsigned char>(bits >> s));
    webp.resize(40, 0);
    const long before = peak_rss_kb();
    const double start = cpu_seconds();
    const ImageReadResult f = read_image_file(dir / "big.png", kLimit);
    EXPECT_FALSE(f.image);
    EXPECT_NE(f.error.find("100000 x 100000"), std::string::npos) << f.error;
    EXPECT_NE(f.error.find(std::to_string(kLimit)), std::string::npos) << f.error;
    EXPECT_EQ(f.error.rfind(dir / "big.png", 0), 0u) << f.error;
    const ImageReadResult m = decode_image(png, kLimit);
    EXPECT_NE(m.error.find("100000 x 100000"), std::string::npos) << m.error;
    const ImageReadResult g = decode_image(gif, kLimit);
    EXPECT_NE(g.error.find("65535 x 65535"), std::string::npos) << g.error;
    const ImageReadResult w = decode_image(webp, kLimit);
    EXPECT_NE(w.error.find("16383 x 16383"), std::string::npos) << w.error;
    EXPECT_LT(cpu_seconds() - start, 2.0) << "CPU seconds";
    EXPECT_LT(peak_rss_kb() - before, 100 * 1024) << "KB more at peak";
    // The limit is exact: 6 pixels against a limit of 5.
    const ImageReadResult tight = decode_image(png_header(3, 2), 5);
    EXPECT_NE(tight.error.find("3 x 2"), std::string::npos) << tight.error;
}

TEST(ImageRead, BrokenInputIsAnErrorNotACrash) {
    TempDir dir;
    std::mt19937 rng(7);
    std::vector<unsigned char> noise(4096);
    for (auto& b : noise) b = static_cast<unsigned char>(rng());
    EXPECT_NE(decode_image(noise, kLimit).error, "");
    EXPECT_NE(decode_image({}, kLimit).error, "");
    // Each signature followed by noise; and a truncated body within the limit.
    const std::vector<std::vector<unsigned char>> heads = {
        {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'},
        {0xff, 0xd8, 0xff},
        {'G', 'I', 'F', '8', '9', 'a'},
        {'I', 'I', '*', 0},
        {'M', 'M', 0, '*'},
        {'R', 'I', 'F', 'F', 0, 0, 0, 0, 'W', 'E', 'B', 'P'}};
    for (const auto& head : heads) {
        std::vector<unsigned char> b = head;
        b.insert(b.end(), noise.begin(), noise.begin() + 200);
        const ImageReadResult r = decode_image(b, kLimit);
        EXPECT_FALSE(r.image) << int(head[0]);
        EXPECT_NE(r.error, "") << int(head[0]);
    }
    const ImageReadResult cut = decode_image(png_header(64, 64), kLimit);
    EXPECT_FALSE(cut.image);
    EXPECT_NE(cut.error, "");
    // The GIF reader throws on a 65535 x 65535 screen: caught, with no limit.
    const std::vector<unsigned char> gif = {'G',  'I',  'F',  '8', '9', 'a', 0xff,
                                            0xff, 0xff, 0xff, 0,   0,   0,   0x3b};
    EXPECT_NE(decode_image(gif, std::size_t(-1)).error, "");
    const ImageReadResult missing = read_image_file(dir / "missing.png", kLimit);
    EXPECT_EQ(missing.error.rfind(dir / "missing.png", 0), 0u) << missing.error;
    EXPECT_NE(read_image_file(dir.path.string(), kLimit).error, "");
}

} // namespace
} // namespace casteljau
