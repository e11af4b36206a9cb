// UTF-8 decoding (Unicode 15, 3.9, table 3-7 of well-formed sequences): a
// lead byte's continuation bytes are checked against the ranges the table
// allows, which rules out overlong forms, surrogates and values past
// U+10FFFF; each maximal ill-formed subpart becomes one U+FFFD.
#include "casteljau/text/utf8.h"

namespace casteljau {

std::u32string decode_utf8(std::string_view text) {
    std::u32string out;
    out.reserve(text.size());
    const auto byte = [&](std::size_t i) { return static_cast<unsigned char>(text[i]); };
    for (std::size_t i = 0; i < text.size();) {
        const unsigned char b = byte(i);
        if (b < 0x80) {
            out.push_back(b);
            ++i;
            continue;
        }
        int length = 0;
        char32_t c = 0;
        unsigned char lo = 0x80, hi = 0xBF; // the second byte's range (table 3-7)
        if (b >= 0xC2 && b <= 0xDF)
            length = 2, c = b & 0x1F;
        else if (b >= 0xE0 && b <= 0xEF) {
            length = 3, c = b & 0x0F;
            if (b == 0xE0) lo = 0xA0;
            if (b == 0xED) hi = 0x9F;
        } else if (b >= 0xF0 && b <= 0xF4) {
            length = 4, c = b & 0x07;
            if (b == 0xF0) lo = 0x90;
            if (b == 0xF4) hi = 0x8F;
        }
        std::size_t j = i + 1;
        for (int k = 1; k < length; ++k, ++j) {
            if (j >= text.size() || byte(j) < lo || byte(j) > hi) break;
            c = c << 6 | (byte(j) & 0x3F);
            lo = 0x80, hi = 0xBF;
        }
        const bool whole = length > 0 && j == i + std::size_t(length);
        out.push_back(whole ? c : U'\uFFFD');
        i = length > 0 ? j : i + 1;
    }
    return out;
}

void append_utf8(std::string& out, char32_t c) {
    if (c < 0x80) {
        out += char(c);
    } else if (c < 0x800) {
        out += char(0xC0 | (c >> 6));
        out += char(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
        out += char(0xE0 | (c >> 12));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
    } else {
        out += char(0xF0 | (c >> 18));
        out += char(0x80 | ((c >> 12) & 0x3F));
        out += char(0x80 | ((c >> 6) & 0x3F));
        out += char(0x80 | (c & 0x3F));
    }
}

} // namespace casteljau
