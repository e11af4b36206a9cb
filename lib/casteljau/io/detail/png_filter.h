// PNG's row filters (ISO/IEC 15948:2004, the PNG specification, 9): each
// byte x of a row is stored as x minus a prediction from its neighbours a
// (left, bpp bytes back), b (above) and c (above-left), modulo 256; bytes
// outside the image count as 0. Types: 0 none, 1 sub (a), 2 up (b),
// 3 average (floor((a + b) / 2)), 4 Paeth (9.4: the one of a, b, c nearest
// to a + b - c).
//
// The adaptive choice is 12.8's heuristic, libpng's too: the type whose
// output has the least sum of magnitudes, each byte read as a signed value
// (small differences of either sign are cheap to code).
#pragma once

#include <cstddef>
#include <cstdint>

namespace casteljau::detail {

inline constexpr int kPngFilterTypes = 5;

/// The filter type with the least cost for `row` (`n` bytes, `bpp` a
/// pixel) under `prior` (the row above; zeros for the first row); the lowest
/// type on ties.
int best_png_filter(const std::uint8_t* row, const std::uint8_t* prior, std::size_t n,
                    std::size_t bpp);

/// Writes `row` filtered with `type` (0 to 4) to out[0..n); `out` may not
/// overlap `row` or `prior`.
void png_filter_row(int type, const std::uint8_t* row, const std::uint8_t* prior, std::size_t n,
                    std::size_t bpp, std::uint8_t* out);

} // namespace casteljau::detail
