// UTF-8 to code points and back. Decoding is at the border: a malformed sequence becomes U+FFFD
// (the replacement character), one per maximal bad subpart (Unicode 15, 3.9).
#pragma once

#include <string>
#include <string_view>

namespace casteljau {

std::u32string decode_utf8(std::string_view text);

/// Appends the UTF-8 form of code point `c` (at most U+10FFFF) to `out`.
void append_utf8(std::string& out, char32_t c);

} // namespace casteljau
