// Canvas pixels as straight (un-premultiplied) RGBA: what PNG and other
// 8-bit image files store, and what a caller reading pixels (an array in
// Python, a texture upload) usually wants.
//
// One place owns the conversion, so that every output of the same canvas has
// the same values: the image writer (io/canvas_write.h) and the Python
// package both call it. Each channel is divided by alpha in float (dividing
// 8-bit values would lose the colour of faint pixels) and clamped to [0, 1];
// a pixel with alpha 0 is transparent black. The 8-bit form rounds 255 v to
// the nearest integer, halves away from zero: exactly what OpenImageIO's
// float to 8-bit conversion gave the PNG writer before this function did it
// (checked over every float in [0, 1]), so written files kept their bytes.
#pragma once

#include "casteljau/paint/canvas.h"
#include "casteljau/paint/color.h"

#include <algorithm>
#include <cstdint>
#include <span>

namespace casteljau {

/// The straight color of a premultiplied pixel: each channel divided by
/// alpha and clamped to [0, 1], alpha clamped to at most 1; transparent
/// black where alpha is 0.
inline Rgba straight_of(const Premul& p) {
    const float inv = p.a > 0 ? 1.0f / p.a : 0.0f;
    return {std::min(p.r * inv, 1.0f), std::min(p.g * inv, 1.0f), std::min(p.b * inv, 1.0f),
            std::min(p.a, 1.0f)};
}

/// A channel value in [0, 1] as a byte: round(255 v), halves away from zero,
/// clamped to [0, 255] (NaN gives 0).
/// (Computed without a libm call: s - trunc(s) is exact below 2^23, so
/// comparing it with 1/2 rounds as std::round(s) does.)
inline std::uint8_t channel_to_u8(float v) {
    const float s = v * 255.0f;
    if (!(s > 0.0f)) return 0;
    if (s >= 255.0f) return 255;
    const int t = int(s);
    return std::uint8_t(t + (s - float(t) >= 0.5f ? 1 : 0));
}

/// Writes canvas.width() x canvas.height() straight RGBA pixels (rows from
/// the top, 4 floats a pixel, values in [0, 1]) to `out`, which must hold
/// that many floats.
template <class Pixel>
void straight_rgba(const BasicCanvas<Pixel>& canvas, std::span<float> out);

/// The same as bytes, 4 a pixel, each channel_to_u8 of straight_rgba's
/// value. With `onto_white`, each pixel is first composited over opaque
/// white (alpha becomes 1), as a format without alpha (JPEG) wants it.
template <class Pixel>
void straight_rgba8(const BasicCanvas<Pixel>& canvas, std::span<std::uint8_t> out,
                    bool onto_white = false);

/// One row of straight_rgba8: `width` pixels from `src` to 4 bytes each
/// from `out` on (for a caller whose rows are not contiguous).
template <class Pixel>
void straight_row8(const Pixel* src, int width, std::uint8_t* out, bool onto_white = false);

} // namespace casteljau
