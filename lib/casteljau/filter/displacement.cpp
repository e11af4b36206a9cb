// feDisplacementMap (Filter Effects 1, "Filter primitive feDisplacementMap",
// #feDisplacementMapElement):
//
//   P'(x, y) <- P(x + scale_x * (XC(x, y) - 0.5), y + scale_y * (YC(x, y) - 0.5))
//
// XC and YC are the selected channels of the map (in2), unpremultiplied as
// the spec requires ("performed using non-premultiplied color values"):
// c / a, 0 where a = 0; the A channel is a itself. They are clamped to
// [0, 1], which bounds the displacement to |scale| / 2 px: a pixel depends on
// input no farther away, so a window cut elsewhere gives the same bits
// wherever that reach stays inside it.
//
// Sampling: the spec leaves the interpolation open; this takes the nearest
// pixel. Pixel x's centre x + 0.5 moves to x + 0.5 + d, which lies in pixel
// floor(x + 0.5 + d) = x + floor(d + 0.5): offsets are rounded half up
// (towards +infinity), the same rule on both sides of 0. A source pixel
// outside the window reads transparent black.
//
// P (in) stays premultiplied and is copied unchanged, so the result is as
// valid (alpha in [0, 1], colors <= alpha) as the input.
#include "casteljau/filter/displacement.h"

#include <cmath>

namespace casteljau {

namespace {

// The channel `c` of `p`, unpremultiplied and clamped to [0, 1].
double channel(const Premul& p, Channel c) {
    if (c == Channel::A) return p.a;
    if (!(p.a > 0)) return 0;
    const float v = c == Channel::R ? p.r : c == Channel::G ? p.g : p.b;
    const double u = double(v) / double(p.a);
    return u < 1 ? (u > 0 ? u : 0) : 1;
}

// x displaced by scale * (v - 0.5), rounded to a pixel; NaN (a NaN scale)
// propagates and reads as outside.
double displaced(int x, double scale, double v) { return x + std::floor(scale * (v - 0.5) + 0.5); }

} // namespace

void displacement_map(const FilterImage& in, const FilterImage& map, FilterImage& out,
                      const Subregion& sub, double scale_x, double scale_y, Channel xc,
                      Channel yc) noexcept {
    const double w = in.width(), h = in.height();
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) {
            const Premul& m = map.at(x, y);
            const double sx = displaced(x, scale_x, channel(m, xc));
            const double sy = displaced(y, scale_y, channel(m, yc));
            if (sx >= 0 && sx < w && sy >= 0 && sy < h) out.at(x, y) = in.at(int(sx), int(sy));
        }
}

} // namespace casteljau
