// Flood, offset, blend, composite, merge and tile: the primitives that move
// and combine pixels without looking at their neighbours.
//
// On premultiplied channels, A = in, B = in2 (Filter Effects 1, 15.8, and
// Compositing 1, 9.1):
//   over  A + B (1 - aA)        in    A aB           out  A (1 - aB)
//   atop  A aB + B (1 - aA)     xor   A (1 - aB) + B (1 - aA)
//   lighter  A + B, clamped     arithmetic  k1 A B + k2 A + k3 B + k4
// Arithmetic is clamped to [0, 1] per channel, and the colors to the alpha
// so that the result stays a valid premultiplied color (15.8: "clamped to
// the range [0..1]"; browsers also keep color <= alpha).
// feBlend's `in` is the top layer and `in2` the backdrop (15.5).
// feOffset moves by whole device pixels (rounded to nearest): a fractional
// shift would have to resample, which resvg and Chrome do not do either.
#include "casteljau/filter/compose.h"

#include <algorithm>

namespace casteljau {

namespace {

// a A + b B, channel by channel.
Premul mix(const Premul& A, float a, const Premul& B, float b) {
    return {A.r * a + B.r * b, A.g * a + B.g * b, A.b * a + B.b * b, A.a * a + B.a * b};
}

Premul porter_duff(const Premul& A, const Premul& B, const Composite& c) {
    using Op = Composite::Op;
    switch (c.op) {
    case Op::Over:
        return mix(A, 1, B, 1 - A.a);
    case Op::In:
        return mix(A, B.a, B, 0);
    case Op::Out:
        return mix(A, 1 - B.a, B, 0);
    case Op::Atop:
        return mix(A, B.a, B, 1 - A.a);
    case Op::Xor:
        return mix(A, 1 - B.a, B, 1 - A.a);
    case Op::Lighter:
        return valid_pixel(mix(A, 1, B, 1));
    case Op::Arithmetic:
        return valid_pixel({c.k1 * A.r * B.r + c.k2 * A.r + c.k3 * B.r + c.k4,
                            c.k1 * A.g * B.g + c.k2 * A.g + c.k3 * B.g + c.k4,
                            c.k1 * A.b * B.b + c.k2 * A.b + c.k3 * B.b + c.k4,
                            c.k1 * A.a * B.a + c.k2 * A.a + c.k3 * B.a + c.k4});
    }
    return A;
}

int floor_mod(int a, int n) { return ((a % n) + n) % n; }

} // namespace

void flood(FilterImage& out, const Subregion& sub, const Premul& color) {
    for (int y = sub.y0; y < sub.y1; ++y) std::fill_n(&out.at(sub.x0, y), sub.x1 - sub.x0, color);
}

void offset(const FilterImage& in, FilterImage& out, const Subregion& sub, int dx, int dy) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) out.at(x, y) = in.get(x - dx, y - dy);
}

void blend(const FilterImage& in, const FilterImage& in2, FilterImage& out, const Subregion& sub,
           BlendMode mode) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x) out.at(x, y) = blend(in2.at(x, y), in.at(x, y), mode);
}

void composite(const FilterImage& in, const FilterImage& in2, FilterImage& out,
               const Subregion& sub, const Composite& c) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x)
            out.at(x, y) = porter_duff(in.at(x, y), in2.at(x, y), c);
}

void merge(std::span<const FilterImage* const> inputs, FilterImage& out, const Subregion& sub) {
    for (const FilterImage* img : inputs)
        for (int y = sub.y0; y < sub.y1; ++y)
            for (int x = sub.x0; x < sub.x1; ++x) {
                const Premul& s = img->at(x, y);
                Premul& d = out.at(x, y);
                d = mix(s, 1, d, 1 - s.a);
            }
}

void tile(const FilterImage& in, const Subregion& t, FilterImage& out, const Subregion& sub) {
    const int w = t.x1 - t.x0, h = t.y1 - t.y0;
    if (w <= 0 || h <= 0) return;
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x)
            out.at(x, y) = in.get(t.x0 + floor_mod(x - t.x0, w), t.y0 + floor_mod(y - t.y0, h));
}

} // namespace casteljau
