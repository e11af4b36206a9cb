// feMorphology (Filter Effects 1, "Filter primitive feMorphology",
// #feMorphologyElement):
//
//   erode:  out_c(x, y) = min { in_c(x + i, y + j) : |i| <= rx, |j| <= ry }
//   dilate: out_c(x, y) = max { in_c(x + i, y + j) : |i| <= rx, |j| <= ry }
//
// for each premultiplied channel c in {r, g, b, a}, with in = 0 (transparent
// black) beyond the window. The spec words the rectangle as "2 * radius"
// wide; engines take the 2 r + 1 pixels centred on the output pixel, and so
// does this.
//
// Invariants:
// * min and max round nothing, so a pixel's value is the same bits whatever
//   the algorithm and wherever the window starts: only input within the
//   rectangle matters.
// * colors stay <= alpha without clamping (the spec notes this): the minimum
//   color is <= the color, hence the alpha, of the pixel with the minimum
//   alpha; the maximum color is some pixel's color, <= its alpha <= the
//   maximum alpha.
//
// Separable: the rectangle's extreme is the extreme over its rows of the row
// extremes. Rows first, into a scratch image holding only what the column
// pass reads (sub's columns; sub's rows widened by ry, cut to the window),
// then columns. Each line uses van Herk / Gil-Werman: cut the padded line
// into blocks of w = 2 r + 1 samples; with g the running extreme from each
// block's start and h the one from each block's end, the window starting at
// k is op(h[k], g[k + w - 1]), because [k, k + w - 1] is the tail of k's block
// followed by the head of the next one. Three operations per sample whatever
// r is, so radii of hundreds of px cost what radius 1 does.
#include "casteljau/filter/morphology.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace casteljau {

namespace {

struct Min {
    static float f(float a, float b) { return std::min(a, b); }
};
struct Max {
    static float f(float a, float b) { return std::max(a, b); }
};

template <class Op>
Premul op(const Premul& p, const Premul& q) {
    return {Op::f(p.r, q.r), Op::f(p.g, q.g), Op::f(p.b, q.b), Op::f(p.a, q.a)};
}

// Scratch kept per thread: the row pass's result and one padded line.
struct Scratch {
    std::vector<Premul> rows, pad, g, h, line, res;
};

// res[i - i0] = op of src[i - r .. i + r] for i in [i0, i1), where src holds
// n samples and is 0 beyond them.
template <class Op>
void line_extreme(const Premul* src, int n, int r, int i0, int i1, Scratch& s) {
    // Past n, the window covers the whole line and a zero beyond it whatever
    // its size: clamping keeps the scratch proportional to the line.
    r = std::min(r, n);
    const int w = 2 * r + 1, base = i0 - r, len = i1 - i0 + 2 * r;
    const auto ulen = std::size_t(len);
    s.pad.assign(ulen, Premul{});
    s.g.resize(ulen);
    s.h.resize(ulen);
    s.res.resize(std::size_t(i1 - i0));
    const int lo = std::max(0, base), hi = std::min(n, base + len);
    for (int i = lo; i < hi; ++i) s.pad[std::size_t(i - base)] = src[i];
    Premul* p = s.pad.data();
    Premul* g = s.g.data();
    Premul* h = s.h.data();
    for (int b = 0; b < len; b += w) {
        const int e = std::min(b + w, len);
        g[b] = p[b];
        for (int k = b + 1; k < e; ++k) g[k] = op<Op>(g[k - 1], p[k]);
        h[e - 1] = p[e - 1];
        for (int k = e - 2; k >= b; --k) h[k] = op<Op>(h[k + 1], p[k]);
    }
    Premul* res = s.res.data();
    for (int k = 0; k < i1 - i0; ++k) res[k] = op<Op>(h[k], g[k + w - 1]);
}

template <class Op>
void separable(const FilterImage& in, FilterImage& out, const Subregion& sub, int rx, int ry) {
    static thread_local Scratch s;
    const int w = in.width(), h = in.height();
    const int sw = sub.x1 - sub.x0;
    const int y0 = std::max(0, sub.y0 - ry), y1 = std::min(h, sub.y1 + ry);
    // Row pass: rows [y0, y1) of sub's columns, stored sw wide from row y0.
    s.rows.resize(std::size_t(sw) * std::size_t(y1 - y0));
    for (int y = y0; y < y1; ++y) {
        line_extreme<Op>(&in.at(0, y), w, rx, sub.x0, sub.x1, s);
        std::copy(s.res.begin(), s.res.end(), s.rows.begin() + std::ptrdiff_t(y - y0) * sw);
    }
    // Column pass: line index 0 is row y0; rows outside [y0, y1) that a
    // window reaches lie outside the image window, hence are 0 there too.
    const int n = y1 - y0;
    s.line.resize(std::size_t(n));
    for (int x = 0; x < sw; ++x) {
        for (int k = 0; k < n; ++k) s.line[std::size_t(k)] = s.rows[std::size_t(k * sw + x)];
        // line_extreme reuses the scratch's other buffers, not `line`.
        line_extreme<Op>(s.line.data(), n, ry, sub.y0 - y0, sub.y1 - y0, s);
        for (int y = sub.y0; y < sub.y1; ++y)
            out.at(sub.x0 + x, y) = s.res[std::size_t(y - sub.y0)];
    }
}

} // namespace

void morphology(const FilterImage& in, FilterImage& out, const Subregion& sub, bool dilate, int rx,
                int ry) {
    if (sub.empty()) return;
    // Radii past the window's size give what the window's size gives (the
    // rectangle holds the whole window and a zero beyond it); clamping also
    // keeps sub.y0 - ry from overflowing.
    rx = std::clamp(rx, 0, in.width());
    ry = std::clamp(ry, 0, in.height());
    if (dilate)
        separable<Max>(in, out, sub, rx, ry);
    else
        separable<Min>(in, out, sub, rx, ry);
}

} // namespace casteljau
