// A small JSON reader (RFC 8259) that remembers the line of every value, so
// that the patch scene reader can say which line holds the bad number.
// Nesting deeper than kMaxJsonDepth is an error, not a stack overflow.
#pragma once

#include "casteljau/io/detail/tokens.h"

#include <string>
#include <string_view>
#include <vector>

namespace casteljau::detail {

inline constexpr int kMaxJsonDepth = 64;

struct JsonValue {
    enum class Kind { Null, Bool, Number, String, Array, Object } kind = Kind::Null;
    int line = 0;
    bool boolean = false;
    double number = 0;
    std::string string;
    // An array's elements, or an object's member values in file order with
    // their names in `keys` (two vectors, not one of pairs: a pair of an
    // incomplete type is not allowed, and libc++/clang reject it).
    std::vector<JsonValue> items;
    std::vector<std::string> keys;

    // The member named `key`, or nullptr.
    const JsonValue* find(std::string_view key) const;
};

// Throws ReadError (with the line) on malformed text.
JsonValue parse_json(std::string_view text);

} // namespace casteljau::detail
