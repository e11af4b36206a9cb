// Fuzz target: the library's own image decoders (io/image_read.h): PNG by
// libpng, JPEG by libjpeg, WebP by libwebp, behind decode_image's sniffing
// and size limit (2^20 pixels here). Other formats go to OpenImageIO's
// module, which is not ours to fuzz: such inputs are skipped. A decode must
// give an image or an error, never both or neither, and an image's values
// must be premultiplied colors in [0, 1].
#include "casteljau/io/image_read.h"
#include "fuzz_target.h"

#include <cstdlib>
#include <cstring>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace casteljau;
    const auto starts = [&](const char* sig, std::size_t n, std::size_t at = 0) {
        return size >= at + n && std::memcmp(data + at, sig, n) == 0;
    };
    if (!starts("\x89PNG\r\n\x1a\n", 8) && !starts("\xff\xd8\xff", 3) &&
        !(starts("RIFF", 4) && starts("WEBP", 4, 8)))
        return 0;
    const ImageReadResult r = decode_image({data, size}, std::size_t(1) << 20);
    if (bool(r.image) == !r.error.empty()) std::abort();
    if (!r.image) return 0;
    if (r.image->pixels.size() != std::size_t(r.image->width) * std::size_t(r.image->height))
        std::abort();
    for (const Premul& p : r.image->pixels)
        if (!(p.a >= 0 && p.a <= 1 && p.r >= 0 && p.r <= p.a && p.g >= 0 && p.g <= p.a &&
              p.b >= 0 && p.b <= p.a))
            std::abort();
    return 0;
}
