// gzip data (RFC 1952) inflated under a size limit: SVGZ, the compressed
// SVG that Inkscape saves and icon themes ship, which librsvg and browsers
// read. The limit holds against a zip bomb (a 1 GiB run of one byte
// compresses to about 1 MiB): decompression stops there.
#pragma once

#include <cstddef>
#include <span>
#include <string>

namespace casteljau {

/// Whether `data` starts as gzip data does (its two magic bytes).
bool is_gzip(std::span<const unsigned char> data);

/// The inflated data, or why there is none.
struct Gunzipped {
    std::string data;
    std::string error; ///< "" on success
};

/// Inflates the gzip data `data` (one member or several, one after another)
/// to at most `max_bytes`.
Gunzipped gunzip(std::span<const unsigned char> data, std::size_t max_bytes);

} // namespace casteljau
