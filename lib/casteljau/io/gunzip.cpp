#include "casteljau/io/gunzip.h"

#include <algorithm>
#include <libdeflate.h>
#include <memory>

namespace casteljau {

bool is_gzip(std::span<const unsigned char> data) {
    return data.size() >= 2 && data[0] == 0x1f && data[1] == 0x8b;
}

Gunzipped gunzip(std::span<const unsigned char> data, std::size_t max_bytes) {
    Gunzipped r;
    const std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> d(
        libdeflate_alloc_decompressor(), libdeflate_free_decompressor);
    if (!d) {
        r.error = "out of memory";
        return r;
    }
    // The trailer's last four bytes are the size modulo 2^32 (RFC 1952,
    // 2.3.1): the first guess, which a wrong or wrapped one only makes grow
    // by doubling, up to the limit. Deflate inflates 1032 times at most (a
    // run: 258 bytes from 2 bits), which bounds a lying trailer's guess.
    std::size_t guess = 4096;
    if (data.size() >= 18) {
        const unsigned char* t = data.data() + data.size() - 4;
        guess = std::size_t(t[0]) | std::size_t(t[1]) << 8 | std::size_t(t[2]) << 16 |
                std::size_t(t[3]) << 24;
    }
    guess = std::clamp<std::size_t>(guess, 1, std::min(max_bytes, 1032 * data.size() + 64));
    for (;;) {
        r.data.resize(guess);
        std::size_t size = 0;
        const libdeflate_result e = libdeflate_gzip_decompress(d.get(), data.data(), data.size(),
                                                               r.data.data(), guess, &size);
        if (e == LIBDEFLATE_SUCCESS) {
            r.data.resize(size);
            return r;
        }
        if (e != LIBDEFLATE_INSUFFICIENT_SPACE) {
            r.error = "not valid gzip data";
            break;
        }
        if (guess >= max_bytes) {
            r.error = "inflates to more than " + std::to_string(max_bytes) + " bytes (the limit)";
            break;
        }
        guess = guess > max_bytes / 2 ? max_bytes : 2 * guess;
    }
    r.data.clear();
    return r;
}

} // namespace casteljau
