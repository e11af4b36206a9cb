// feConvolveMatrix (Filter Effects 1, "Filter primitive feConvolveMatrix",
// #feConvolveMatrixElement), the spec's formula as it is written:
//
//   SUM_c(X,Y) = sum_{I=0}^{orderY-1} sum_{J=0}^{orderX-1}
//                SOURCE_c(X - targetX + J, Y - targetY + I)
//                * kernelMatrix[orderX - J - 1, orderY - I - 1]
//
// where kernelMatrix[col, row] = kernel[row * orderX + col]: the kernel turned
// by 180 degrees against the image, as in textbook convolution.
//
// preserveAlpha false, every premultiplied channel:
//   ALPHA = clamp(SUM_a / divisor + bias, 0, 1)
//   COLOR = clamp(SUM_c / divisor + bias * ALPHA, 0, ALPHA)
// The spec's color formula ends in "/ divisor + bias * ALPHA_{X,Y}": in
// premultiplied storage a bias of 0.5 must add 0.5 * alpha to be mid-grey at
// any opacity. ALPHA is the clamped result alpha, the one actually stored.
//
// preserveAlpha true: the kernel applies to unpremultiplied colors (c / a, 0
// where a = 0) and the alpha is the source's:
//   ALPHA = SOURCE_a(X,Y)
//   color = clamp(SUM_c / divisor + bias, 0, 1),   COLOR = color * ALPHA
// Premultiplied, that is SUM / divisor * ALPHA + bias * ALPHA: the same rule
// (bias scaled by the result's alpha) on straight colors, so a bias means the
// same thing in both modes.
//
// Edge modes, relative to the window: None reads transparent black, Duplicate
// the nearest edge pixel, Wrap the pixel at the coordinate modulo the
// window's size.
//
// Invariants: results are clamped (alpha in [0, 1], colors in [0, alpha]).
// Each pixel is its own fixed-order sum in double, so a window cut elsewhere
// gives the same bits wherever the kernel's footprint stays inside it.
#include "casteljau/filter/convolve.h"

#include <cstddef>

namespace casteljau {

namespace {

// v clamped to [0, hi]; NaN (a NaN kernel entry) gives 0.
double clamp_to(double v, double hi) { return v > 0 ? (v < hi ? v : hi) : 0; }

// What a tap reads: the premultiplied pixel, or with preserveAlpha its
// unpremultiplied color (the alpha is not summed then).
template <bool PreserveAlpha>
Premul tap(const Premul& p) {
    if constexpr (PreserveAlpha) {
        if (!(p.a > 0)) return {};
        return {p.r / p.a, p.g / p.a, p.b / p.a, p.a};
    } else {
        return p;
    }
}

template <bool PreserveAlpha>
Premul convolve_pixel(const FilterImage& in, const ConvolveMatrix& m, int x, int y) {
    const int w = in.width(), h = in.height(), ox = m.order_x, oy = m.order_y;
    double s[4] = {0, 0, 0, 0};
    for (int i = 0; i < oy; ++i) {
        const int sy = edge_index(y - m.target_y + i, h, m.edge);
        if (sy < 0) continue;
        const float* krow = m.kernel.data() + std::size_t(oy - i - 1) * std::size_t(ox);
        for (int j = 0; j < ox; ++j) {
            const int sx = edge_index(x - m.target_x + j, w, m.edge);
            if (sx < 0) continue;
            const double k = krow[ox - j - 1];
            const Premul p = tap<PreserveAlpha>(in.at(sx, sy));
            s[0] += k * p.r;
            s[1] += k * p.g;
            s[2] += k * p.b;
            s[3] += k * p.a;
        }
    }
    const double div = m.divisor, bias = m.bias;
    if constexpr (PreserveAlpha) {
        const float a = in.at(x, y).a;
        return {float(clamp_to(s[0] / div + bias, 1)) * a,
                float(clamp_to(s[1] / div + bias, 1)) * a,
                float(clamp_to(s[2] / div + bias, 1)) * a, a};
    } else {
        const double a = clamp_to(s[3] / div + bias, 1);
        return {float(clamp_to(s[0] / div + bias * a, a)),
                float(clamp_to(s[1] / div + bias * a, a)),
                float(clamp_to(s[2] / div + bias * a, a)), float(a)};
    }
}

template <bool PreserveAlpha>
void convolve_sub(const FilterImage& in, FilterImage& out, const Subregion& sub,
                  const ConvolveMatrix& m) {
    for (int y = sub.y0; y < sub.y1; ++y)
        for (int x = sub.x0; x < sub.x1; ++x)
            out.at(x, y) = convolve_pixel<PreserveAlpha>(in, m, x, y);
}

} // namespace

bool valid_kernel(const ConvolveMatrix& m) noexcept {
    return m.order_x > 0 && m.order_y > 0 &&
           m.kernel.size() == std::size_t(m.order_x) * std::size_t(m.order_y) && m.divisor != 0 &&
           m.target_x >= 0 && m.target_x < m.order_x && m.target_y >= 0 && m.target_y < m.order_y;
}

void convolve(const FilterImage& in, FilterImage& out, const Subregion& sub,
              const ConvolveMatrix& m) noexcept {
    if (!valid_kernel(m)) { // a pass-through filter
        for (int y = sub.y0; y < sub.y1; ++y)
            for (int x = sub.x0; x < sub.x1; ++x) out.at(x, y) = in.at(x, y);
        return;
    }
    if (m.preserve_alpha)
        convolve_sub<true>(in, out, sub, m);
    else
        convolve_sub<false>(in, out, sub, m);
}

} // namespace casteljau
