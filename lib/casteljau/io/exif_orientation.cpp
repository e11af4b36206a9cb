#include "casteljau/io/detail/exif_orientation.h"

namespace casteljau::detail {

namespace {

// TIFF 6.0, 8: the Orientation tag, of type SHORT (3).
constexpr unsigned kOrientationTag = 0x0112, kShort = 3;

} // namespace

int exif_orientation(const unsigned char* d, std::size_t n) {
    if (n < 8 || !((d[0] == 'I' && d[1] == 'I') || (d[0] == 'M' && d[1] == 'M'))) return 1;
    const bool le = d[0] == 'I';
    const auto u16 = [&](std::size_t i) {
        return le ? unsigned(d[i] | d[i + 1] << 8) : unsigned(d[i] << 8 | d[i + 1]);
    };
    const auto u32 = [&](std::size_t i) {
        return le ? u16(i) | std::size_t(u16(i + 2)) << 16 : std::size_t(u16(i)) << 16 | u16(i + 2);
    };
    if (u16(2) != 42) return 1;
    const std::size_t ifd = u32(4);
    if (ifd > n - 2) return 1;
    const std::size_t entries = u16(ifd);
    for (std::size_t k = 0; k < entries; ++k) {
        const std::size_t e = ifd + 2 + 12 * k;
        if (e + 12 > n) break;
        if (u16(e) != kOrientationTag) continue;
        const unsigned v = u16(e + 8); // a SHORT sits at the start of the value field
        return u16(e + 2) == kShort && u32(e + 4) >= 1 && v >= 1 && v <= 8 ? int(v) : 1;
    }
    return 1;
}

} // namespace casteljau::detail
