#include "casteljau/io/detail/webp_read.h"

#include <fstream>
#include <iterator>
#include <vector>
#include <webp/decode.h>

namespace casteljau::detail {

namespace {

class WebpReader final : public ImageReader {
  public:
    const ImageHeader& header() const override { return header_; }
    std::string read(int channels, float* out, std::size_t stride) override {
        const std::size_t w = std::size_t(header_.width), h = std::size_t(header_.height);
        const std::size_t n = std::size_t(header_.channels);
        std::vector<std::uint8_t> samples(w * h * n);
        const std::uint8_t* done =
            n == 4 ? WebPDecodeRGBAInto(bytes_.data(), bytes_.size(), samples.data(),
                                        samples.size(), int(w * n))
                   : WebPDecodeRGBInto(bytes_.data(), bytes_.size(), samples.data(), samples.size(),
                                       int(w * n));
        if (!done) return "libwebp cannot decode the image data";
        for (std::size_t i = 0; i < w * h; ++i) {
            auto* dst = reinterpret_cast<float*>(reinterpret_cast<char*>(out) + i * stride);
            for (std::size_t c = 0; c < std::size_t(channels) && c < n; ++c)
                dst[c] = float(samples[i * n + c]) * kSampleScale8;
        }
        return {};
    }

    std::span<const unsigned char> bytes_;
    std::vector<unsigned char> file_; // a file's bytes, which bytes_ then views
    ImageHeader header_;
};

} // namespace

WebpOpened open_webp(const std::string& name, std::span<const unsigned char> memory,
                     bool from_memory) {
    WebpOpened r;
    auto reader = std::make_unique<WebpReader>();
    if (from_memory) {
        reader->bytes_ = memory;
    } else {
        std::ifstream in(name, std::ios::binary);
        if (!in) {
            r.error = "cannot open the file";
            return r;
        }
        reader->file_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
        reader->bytes_ = reader->file_;
    }
    WebPBitstreamFeatures f;
    if (WebPGetFeatures(reader->bytes_.data(), reader->bytes_.size(), &f) != VP8_STATUS_OK ||
        f.width <= 0 || f.height <= 0) {
        r.error = "not a WebP libwebp reads";
        return r;
    }
    if (f.has_animation) {
        r.animated = true;
        return r;
    }
    ImageHeader& h = reader->header_;
    h.width = f.width, h.height = f.height, h.depth = 1;
    h.channels = f.has_alpha ? 4 : 3;
    // Straight, as libwebp gives it (OIIO premultiplied it in 8 bits);
    // without alpha, as OIIO reports it.
    h.straight = f.has_alpha;
    r.reader = std::move(reader);
    return r;
}

} // namespace casteljau::detail
