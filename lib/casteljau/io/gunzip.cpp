#include "casteljau/io/gunzip.h"

#include <algorithm>
#include <libdeflate.h>
#include <memory>

namespace casteljau {

bool is_gzip(std::span<const unsigned char> data) {
    return data.size() >= 2 && data[0] == 0x1f && data[1] == 0x8b;
}

namespace {

// Inflates the one gzip member at the start of `data` onto `out`, keeping
// `out` within `max_bytes`; returns the member's size, 0 on failure (`error`
// set).
std::size_t inflate_member(libdeflate_decompressor* d, std::span<const unsigned char> data,
                           std::size_t max_bytes, std::string& out, std::string& error) {
    const std::size_t room = max_bytes - std::min(max_bytes, out.size());
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
    guess = std::min({std::max<std::size_t>(guess, 1), room, 1032 * data.size() + 64});
    const std::size_t at = out.size();
    for (;;) {
        out.resize(at + guess);
        std::size_t used = 0, size = 0;
        const libdeflate_result e = libdeflate_gzip_decompress_ex(
            d, data.data(), data.size(), out.data() + at, guess, &used, &size);
        if (e == LIBDEFLATE_SUCCESS) {
            out.resize(at + size);
            return used;
        }
        if (e != LIBDEFLATE_INSUFFICIENT_SPACE) {
            error = "not valid gzip data";
            return 0;
        }
        if (guess >= room) {
            error = "inflates to more than " + std::to_string(max_bytes) + " bytes (the limit)";
            return 0;
        }
        guess = guess > room / 2 ? room : 2 * guess;
    }
}

} // namespace

Gunzipped gunzip(std::span<const unsigned char> data, std::size_t max_bytes) {
    Gunzipped r;
    const std::unique_ptr<libdeflate_decompressor, void (*)(libdeflate_decompressor*)> d(
        libdeflate_alloc_decompressor(), libdeflate_free_decompressor);
    if (!d) {
        r.error = "out of memory";
        return r;
    }
    // Members one after another inflate to their data one after another
    // (RFC 1952, 2.2: `cat a.gz b.gz`); anything else after one is damage.
    for (std::size_t in = 0; in < data.size();) {
        const std::span<const unsigned char> member = data.subspan(in);
        const std::size_t used =
            is_gzip(member) ? inflate_member(d.get(), member, max_bytes, r.data, r.error) : 0;
        if (used == 0) {
            if (r.error.empty()) r.error = "not valid gzip data";
            r.data.clear();
            return r;
        }
        in += used;
    }
    return r;
}

} // namespace casteljau
