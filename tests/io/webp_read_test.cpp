// The library's WebP reader (io/detail/webp_read.h) against OpenImageIO's,
// which decoded WebP for <image> before it: lossy and lossless, with and
// without alpha, at odd sizes; both report the same header and the same
// float values, bit for bit. The files are written here with libwebp.
#include "casteljau/io/detail/oiio_module.h"
#include "casteljau/io/detail/webp_read.h"
#include "casteljau/io/image_read.h"
#include "corpus.h"
#include "reader_compare.h"

#include <gtest/gtest.h>
#include <string>
#include <vector>
#include <webp/encode.h>

namespace casteljau {
namespace {

/// A w x h WebP of ramps and noise from `rng`, with alpha when `alpha`
/// (a quarter of it transparent), lossless or lossy.
std::vector<unsigned char> make_webp(bool lossless, bool alpha, int w, int h, testing::Rng& rng) {
    const int n = alpha ? 4 : 3;
    std::vector<std::uint8_t> samples(std::size_t(w * h * n));
    for (int i = 0; i < w * h; ++i)
        for (int c = 0; c < n; ++c)
            samples[std::size_t(i * n + c)] =
                c == 3 && i % 4 == 0 ? 0
                                     : std::uint8_t(std::clamp(
                                           (i * 29 + c * 70) % 256 + rng.integer(-30, 30), 0, 255));
    std::uint8_t* out = nullptr;
    const std::size_t size =
        lossless ? (alpha ? WebPEncodeLosslessRGBA(samples.data(), w, h, w * n, &out)
                          : WebPEncodeLosslessRGB(samples.data(), w, h, w * n, &out))
                 : (alpha ? WebPEncodeRGBA(samples.data(), w, h, w * n, 75, &out)
                          : WebPEncodeRGB(samples.data(), w, h, w * n, 75, &out));
    EXPECT_GT(size, 0u);
    std::vector<unsigned char> bytes(out, out + size);
    WebPFree(out);
    return bytes;
}

void expect_same_as_oiio(const std::vector<unsigned char>& webp, const std::string& what) {
    detail::WebpOpened ours = detail::open_webp("memory", webp, true);
    testing::expect_same_as_oiio(testing::read_all(std::move(ours.reader), ours.error), "webp",
                                 webp, what);
}

// With alpha, OIIO 2.4's reader premultiplied the colors in 8 bits, asked
// for straight alpha or not; the library's keeps them straight, which
// image_read.cpp premultiplies in float, as it does PNG's. The same alpha,
// and colors premultiplied within half an 8-bit step of OIIO's.
void expect_oiio_premultiplied(const std::vector<unsigned char>& webp, const std::string& what) {
    detail::WebpOpened ours = detail::open_webp("memory", webp, true);
    const testing::Read a = testing::read_all(std::move(ours.reader), ours.error);
    const detail::OiioModule& oiio = detail::oiio_module();
    ASSERT_TRUE(oiio.codec) << oiio.error;
    detail::OiioOpened theirs = oiio.codec->open("webp", "memory", webp, true, true);
    const testing::Read b = testing::read_all(std::move(theirs.reader), theirs.error);
    ASSERT_EQ(a.error, "") << what;
    ASSERT_EQ(b.error, "") << what;
    ASSERT_EQ(a.header.channels, 4) << what;
    ASSERT_EQ(b.header.channels, 4) << what;
    EXPECT_TRUE(a.header.straight) << what;
    EXPECT_FALSE(b.header.straight) << what;
    ASSERT_EQ(a.values.size(), b.values.size()) << what;
    for (std::size_t i = 0; i < a.values.size(); i += 4) {
        EXPECT_EQ(a.values[i + 3], b.values[i + 3]) << what << ": pixel " << i / 4;
        for (std::size_t c = 0; c < 3; ++c)
            EXPECT_NEAR(a.values[i + c] * a.values[i + 3], b.values[i + c], 0.5f / 255 + 1e-6f)
                << what << ": pixel " << i / 4 << " channel " << c;
    }
}

TEST(WebpRead, LossyAndLosslessWithAndWithoutAlphaDecodeAsOpenImageIODid) {
    testing::Rng rng(2510);
    for (const bool lossless : {false, true})
        for (const bool alpha : {false, true})
            for (const auto& size :
                 {std::pair{1, 1}, std::pair{13, 9}, std::pair{3, 17}, std::pair{37, 23}}) {
                const auto webp = make_webp(lossless, alpha, size.first, size.second, rng);
                const std::string what = std::string(lossless ? "lossless" : "lossy") +
                                         (alpha ? " alpha " : " ") + std::to_string(size.first) +
                                         "x" + std::to_string(size.second);
                if (alpha)
                    expect_oiio_premultiplied(webp, what);
                else
                    expect_same_as_oiio(webp, what);
            }
}

// A file cut short, or bytes that are no WebP past the signature, are
// errors with a message.
TEST(WebpRead, BrokenFilesAreErrors) {
    testing::Rng rng(2511);
    const auto webp = make_webp(false, true, 37, 23, rng);
    for (const std::size_t cut : {std::size_t(12), std::size_t(30), webp.size() / 2}) {
        const std::vector<unsigned char> head(webp.begin(), webp.begin() + std::ptrdiff_t(cut));
        const ImageReadResult r = decode_image(head, 1000);
        EXPECT_FALSE(r.image) << cut;
        EXPECT_NE(r.error, "") << cut;
    }
}

} // namespace
} // namespace casteljau
