// The PNG encoder (io/png_write.h), read back by another decoder
// (OpenImageIO's, which uses libpng): every pixel as given, for every filter
// and level, RGB when opaque; and the same pixel values as the OpenImageIO
// writer that wrote PNG before it, from the same canvas.
#include "casteljau/io/canvas_write.h"
#include "casteljau/io/detail/oiio_module.h"
#include "casteljau/io/png_write.h"
#include "casteljau/paint/straight_rgba.h"
#include "casteljau/render/renderer.h"
#include "casteljau/svg/reader.h"
#include "corpus.h"

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>
#include <cstdio>
#include <fstream>
#include <gtest/gtest.h>
#include <iterator>
#include <string>
#include <vector>

namespace casteljau {
namespace {

/// A PNG file's pixels as RGBA bytes (alpha 255 when the file has none),
/// decoded by OIIO from memory with straight alpha kept; and its channels.
struct Decoded {
    int width = 0, height = 0, channels = 0;
    std::vector<std::uint8_t> rgba;
};

Decoded decode(const std::vector<std::uint8_t>& png) {
    Decoded d;
    OIIO::Filesystem::IOMemReader memory(png.data(), png.size());
    OIIO::Filesystem::IOProxy* proxy = &memory;
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    config.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto in = OIIO::ImageInput::create("png");
    OIIO::ImageSpec spec;
    if (!in || !in->open("memory.png", spec, config)) {
        ADD_FAILURE() << "cannot decode: " << (in ? in->geterror() : OIIO::geterror());
        return d;
    }
    d.width = spec.width, d.height = spec.height, d.channels = spec.nchannels;
    d.rgba.assign(std::size_t(d.width) * std::size_t(d.height) * 4, 255);
    if (!in->read_image(0, 0, 0, std::min(d.channels, 4), OIIO::TypeDesc::UINT8, d.rgba.data(), 4))
        ADD_FAILURE() << "cannot read the pixels: " << in->geterror();
    return d;
}

/// The first differing byte of two equal-sized pixel arrays, or -1.
long first_difference(const std::vector<std::uint8_t>& a, const std::vector<std::uint8_t>& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i] != b[i]) return long(i);
    return -1;
}

enum class Content { random, opaque, faint, flat };

/// Test pixels: random bytes whose alpha is 0, 255, faint (1 to 3) or
/// anything; opaque ones; faint ones; or flat runs with edges (what renders
/// look like, where filters and matches matter).
std::vector<std::uint8_t> pixels(int w, int h, Content content, testing::Rng& rng) {
    std::vector<std::uint8_t> px(std::size_t(w) * std::size_t(h) * 4);
    const auto byte = [&] { return std::uint8_t(rng.integer(0, 255)); };
    for (std::size_t i = 0; i < px.size(); i += 4) {
        for (int c = 0; c < 3; ++c) px[i + std::size_t(c)] = byte();
        const int kind = rng.integer(0, 3);
        px[i + 3] = content == Content::opaque  ? 255
                    : content == Content::faint ? std::uint8_t(rng.integer(1, 3))
                    : kind == 0                 ? 0
                    : kind == 1                 ? 255
                    : kind == 2                 ? std::uint8_t(rng.integer(1, 3))
                                                : byte();
        if (content == Content::flat && i >= 4 && rng.integer(0, 15) != 0)
            std::copy_n(&px[i - 4], 4, &px[i]); // mostly a copy of the pixel before
    }
    return px;
}

// Every filter and level, sizes from 1 x 1 to odd widths: the decoder gets
// back every byte.
TEST(PngWrite, RoundTripsEveryPixelThroughAnotherDecoder) {
    testing::Rng rng(2501);
    const int sizes[][2] = {{1, 1}, {1, 2}, {2, 1}, {3, 5}, {17, 9}, {33, 31}, {127, 3}, {5, 140}};
    const PngFilter filters[] = {PngFilter::none,     PngFilter::sub,   PngFilter::up,
                                 PngFilter::average,  PngFilter::paeth, PngFilter::adaptive,
                                 PngFilter::automatic};
    for (const auto& size : sizes)
        for (const Content content :
             {Content::random, Content::opaque, Content::faint, Content::flat})
            for (const PngFilter filter : filters)
                for (const int level : {1, 4, 12}) {
                    const int w = size[0], h = size[1];
                    const auto px = pixels(w, h, content, rng);
                    const auto png = encode_png(px, w, h, {level, filter});
                    ASSERT_FALSE(png.empty());
                    const Decoded d = decode(png);
                    ASSERT_EQ(d.width, w);
                    ASSERT_EQ(d.height, h);
                    bool opaque = true;
                    for (std::size_t i = 3; i < px.size(); i += 4) opaque &= px[i] == 255;
                    EXPECT_EQ(d.channels, opaque ? 3 : 4);
                    EXPECT_EQ(first_difference(d.rgba, px), -1)
                        << w << " x " << h << " content " << int(content) << " filter "
                        << int(filter) << " level " << level;
                }
}

// IHDR's color type (PNG 11.2.2, byte 25 of the file): RGB exactly when every
// pixel is opaque, and then the file is smaller than the same pixels as RGBA.
TEST(PngWrite, OpaqueImagesAreWrittenAsRgb) {
    testing::Rng rng(2502);
    auto px = pixels(40, 30, Content::flat, rng);
    for (std::size_t i = 3; i < px.size(); i += 4) px[i] = 255;
    const auto rgb = encode_png(px, 40, 30);
    px[7] = 254; // one pixel not quite opaque
    const auto rgba = encode_png(px, 40, 30);
    ASSERT_GT(rgb.size(), 25u);
    ASSERT_GT(rgba.size(), 25u);
    EXPECT_EQ(rgb[25], 2);
    EXPECT_EQ(rgba[25], 6);
    EXPECT_LT(rgb.size(), rgba.size());
}

TEST(PngWrite, RefusesSizesThatDisagreeWithThePixels) {
    const std::vector<std::uint8_t> px(4 * 6);
    EXPECT_TRUE(encode_png(px, 0, 6).empty());
    EXPECT_TRUE(encode_png(px, 2, 2).empty());
    EXPECT_TRUE(encode_png(px, -1, -6).empty());
    EXPECT_FALSE(encode_png(px, 2, 3).empty());
}

/// A picture with every kind of pixel a render makes: the filters example
/// (blurs, translucency, antialiased edges over transparency).
Canvas example_canvas() {
    SvgResult doc = read_svg_file(CASTELJAU_EXAMPLES "/svg/filters.svg");
    EXPECT_TRUE(doc.scene) << doc.error;
    Canvas canvas(200, 150);
    if (doc.scene)
        Renderer().render(*doc.scene, Affine::scale(200 / doc.scene->width), canvas,
                          RenderOptions{});
    return canvas;
}

// write_canvas_atomic's PNG holds exactly straight_rgba8's bytes, as the
// OpenImageIO writer it replaces did: the same canvas written through OIIO's
// PNG writer decodes to the same pixels.
TEST(PngWrite, ACanvasDecodesToThePixelsOpenImageIOWrote) {
    const Canvas canvas = example_canvas();
    const int w = canvas.width(), h = canvas.height();
    std::vector<std::uint8_t> expected(std::size_t(w) * std::size_t(h) * 4);
    straight_rgba8(canvas, expected);
    int translucent = 0;
    for (std::size_t i = 3; i < expected.size(); i += 4)
        translucent += expected[i] > 0 && expected[i] < 255;
    EXPECT_GT(translucent, 1000) << "the example should exercise un-premultiplying";

    const std::string path = ::testing::TempDir() + "png_write_canvas.png";
    ASSERT_EQ(write_canvas_atomic(path, canvas), "");
    std::ifstream in(path, std::ios::binary);
    const std::vector<std::uint8_t> ours{std::istreambuf_iterator<char>(in), {}};
    std::remove(path.c_str());
    const Decoded mine = decode(ours);
    ASSERT_EQ(mine.rgba.size(), expected.size());
    EXPECT_EQ(first_difference(mine.rgba, expected), -1);

    const detail::OiioModule& oiio = detail::oiio_module();
    ASSERT_TRUE(oiio.codec) << oiio.error;
    std::vector<unsigned char> theirs;
    ASSERT_EQ(
        oiio.codec->write("old.png", {.width = w, .height = h, .pixels = expected.data()}, &theirs),
        "");
    const Decoded old = decode({theirs.begin(), theirs.end()});
    ASSERT_EQ(old.rgba.size(), mine.rgba.size());
    EXPECT_EQ(first_difference(mine.rgba, old.rgba), -1);
}

// The default (automatic) chooses between leaving the rows unfiltered and
// filtering each: its file is byte for byte one of those two, though it
// filters in place in rows it did not sample.
TEST(PngWrite, AutomaticIsOneOfItsTwoCandidates) {
    const Canvas canvas = example_canvas();
    std::vector<std::uint8_t> px(std::size_t(canvas.width()) * std::size_t(canvas.height()) * 4);
    straight_rgba8(canvas, px);
    const auto automatic = encode_png(px, canvas.width(), canvas.height());
    const auto none = encode_png(px, canvas.width(), canvas.height(), {4, PngFilter::none});
    const auto adaptive = encode_png(px, canvas.width(), canvas.height(), {4, PngFilter::adaptive});
    EXPECT_TRUE(automatic == none || automatic == adaptive)
        << automatic.size() << " bytes; none " << none.size() << ", adaptive " << adaptive.size();
}

// The choice itself, where it is clear: a smooth gradient compresses far
// better with its rows filtered (their differences repeat); one flat color,
// sampled in bands (256 rows), no better. At 64 rows the trial compresses
// the whole image both ways, and its winning stream is the one written: the
// file must be, byte for byte, what the chosen filter asked for explicitly
// writes (for the flat color either: filtered, its rows are zeros, which
// deflate takes a few bytes smaller, and the whole-image trial takes it).
TEST(PngWrite, AutomaticFiltersAGradientAndNotAFlatColor) {
    for (const int h : {256, 64}) {
        const int w = 256;
        std::vector<std::uint8_t> flat(std::size_t(w) * std::size_t(h) * 4), ramp(flat.size());
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                std::uint8_t* f = &flat[(std::size_t(y) * w + std::size_t(x)) * 4];
                std::uint8_t* r = &ramp[(std::size_t(y) * w + std::size_t(x)) * 4];
                f[0] = 40, f[1] = 90, f[2] = 200, f[3] = 255;
                r[0] = std::uint8_t(x), r[1] = std::uint8_t(4 * y),
                r[2] = std::uint8_t((x + y) / 2), r[3] = 255;
            }
        const auto flat_auto = encode_png(flat, w, h);
        const auto flat_none = encode_png(flat, w, h, {4, PngFilter::none});
        if (h == 256) {
            EXPECT_EQ(flat_auto, flat_none);
        } else {
            EXPECT_TRUE(flat_auto == flat_none ||
                        flat_auto == encode_png(flat, w, h, {4, PngFilter::adaptive}));
        }
        EXPECT_EQ(encode_png(ramp, w, h), encode_png(ramp, w, h, {4, PngFilter::adaptive})) << h;
        EXPECT_NE(encode_png(ramp, w, h), encode_png(ramp, w, h, {4, PngFilter::none})) << h;
    }
}

// The zlib stream cut into several IDAT chunks (as a stream over 1 GiB is):
// every chunk at most the size asked for, and another decoder joins them to
// the same pixels.
TEST(PngWrite, StreamSplitIntoIdatChunksDecodesTheSame) {
    testing::Rng rng(7);
    const int w = 40, h = 30;
    std::vector<std::uint8_t> px(std::size_t(w) * h * 4);
    for (std::uint8_t& b : px) b = std::uint8_t(rng.integer(0, 255));
    const std::vector<std::uint8_t> png = encode_png(px, w, h, {4, PngFilter::none, 100});
    int chunks = 0;
    for (std::size_t at = 8; at + 8 <= png.size();) { // PNG 5.3: length, type, data, CRC
        const std::size_t len = std::size_t(png[at]) << 24 | std::size_t(png[at + 1]) << 16 |
                                std::size_t(png[at + 2]) << 8 | png[at + 3];
        if (std::string(png.begin() + long(at) + 4, png.begin() + long(at) + 8) == "IDAT") {
            ++chunks;
            EXPECT_LE(len, 100u);
        }
        at += 12 + len;
    }
    EXPECT_GT(chunks, 40); // 4,800 random bytes hardly compress
    const Decoded d = decode(png);
    EXPECT_EQ(d.width, w);
    EXPECT_EQ(d.height, h);
    EXPECT_EQ(first_difference(d.rgba, px), -1);
}

} // namespace
} // namespace casteljau
