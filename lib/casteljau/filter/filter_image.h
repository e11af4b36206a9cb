// The pixels a filter primitive reads and writes (Filter Effects 1, 9).
//
// Every image of one filter run covers the same window of device pixels
// (`box`): the filter region mapped to the device, cut to what the target
// needs (see filter/run.h). Outside its window an image is transparent
// black, which is what the spec says of everything outside a primitive's
// subregion. Pixels are premultiplied RGBA in float, encoded in sRGB or in
// linear light (`linear`), the two color spaces color-interpolation-filters
// chooses between; filter/color_space.h converts.
#pragma once

#include "casteljau/paint/color.h"
#include "casteljau/raster/edge.h"

#include <cstddef>
#include <vector>

namespace casteljau {

/// A window of premultiplied float pixels in device space.
struct FilterImage {
    PixelRect box;          ///< the device pixels covered, [x0, x1) x [y0, y1)
    std::vector<Premul> px; ///< box.width() * box.height(), row-major
    bool linear = false;    ///< linear-light (linearRGB) channels, else sRGB-encoded

    int width() const { return box.width(); }   ///< columns
    int height() const { return box.height(); } ///< rows
    /// Makes this a transparent black image over `b`, keeping its storage.
    void reset(const PixelRect& b, bool linear_light) {
        box = b;
        linear = linear_light;
        px.assign(std::size_t(b.width()) * std::size_t(b.height()), Premul{});
    }
    /// The pixel at window column x, row y (0-based in the window).
    Premul& at(int x, int y) {
        return px[std::size_t(y) * std::size_t(box.width()) + std::size_t(x)];
    }
    /// The pixel at window column x, row y, read-only.
    const Premul& at(int x, int y) const {
        return px[std::size_t(y) * std::size_t(box.width()) + std::size_t(x)];
    }
    /// The pixel at window column x, row y, transparent black outside the window.
    Premul get(int x, int y) const {
        if (x < 0 || y < 0 || x >= box.width() || y >= box.height()) return {};
        return at(x, y);
    }
};

/// v clamped to [0, 1], NaN to 0: parameters of up to 1e308 become infinite
/// in float, and infinity times a transparent 0 is NaN, which must not
/// reach a pixel.
inline float unit_clamp(float v) { return v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f; }

/// A valid premultiplied pixel near p: alpha in [0, 1], each color in
/// [0, alpha], NaN as 0.
inline Premul valid_pixel(Premul p) {
    p.a = unit_clamp(p.a);
    const auto below = [&](float v) { return v > 0.0f ? (v < p.a ? v : p.a) : 0.0f; };
    return {below(p.r), below(p.g), below(p.b), p.a};
}

/// How a neighbourhood operation reads pixels beyond the input's edges
/// (feConvolveMatrix and feGaussianBlur edgeMode).
enum class EdgeMode : unsigned char { None, Duplicate, Wrap };

/// The index in [0, n) that position i on an axis of n pixels reads under
/// `edge`, or -1 for transparent black (None, beyond the edge).
inline int edge_index(int i, int n, EdgeMode edge) {
    if (i >= 0 && i < n) return i;
    switch (edge) {
    case EdgeMode::None:
        return -1;
    case EdgeMode::Duplicate:
        return i < 0 ? 0 : n - 1;
    case EdgeMode::Wrap:
        return ((i % n) + n) % n;
    }
    return -1;
}

/// The part of a window a primitive writes: its subregion, in window
/// coordinates (0-based), already cut to the window.
struct Subregion {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    /// Whether window pixel (x, y) is in the subregion.
    bool contains(int x, int y) const { return x >= x0 && x < x1 && y >= y0 && y < y1; }
    /// Whether the subregion has no pixel.
    bool empty() const { return x1 <= x0 || y1 <= y0; }
};

} // namespace casteljau
