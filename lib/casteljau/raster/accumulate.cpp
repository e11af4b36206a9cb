#include "casteljau/raster/accumulate.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

void CoverageRow::reset(int width) {
    width_ = width;
    acc_.assign(std::size_t(width) + 2, 0.0f);
    marks_.assign((std::size_t(width) + 2 + 63) / 64, 0);
    begin_ = width_ + 1, end_ = 0;
}

void CoverageRow::touch(int i0, int i1) {
    begin_ = std::min(begin_, i0);
    end_ = std::max(end_, i1);
    // Bits [i0, i1): the words' masks from the first bit and to the last one.
    // An edge usually touches a few columns, within one word.
    constexpr std::uint64_t kOnes = ~std::uint64_t(0);
    const std::size_t w0 = std::size_t(i0) >> 6, w1 = std::size_t(i1 - 1) >> 6;
    const std::uint64_t from = kOnes << (i0 & 63), to = kOnes >> (63 - ((i1 - 1) & 63));
    if (w0 == w1) {
        marks_[w0] |= from & to;
        return;
    }
    marks_[w0] |= from;
    for (std::size_t w = w0 + 1; w < w1; ++w) marks_[w] = kOnes;
    marks_[w1] |= to;
}

void CoverageRow::clear_range() {
    if (begin_ < end_)
        for (std::size_t w = std::size_t(begin_) >> 6; w <= std::size_t(end_ - 1) >> 6; ++w)
            marks_[w] = 0;
    begin_ = width_ + 1, end_ = 0;
}

void CoverageRow::add_segment(float xa, float ya, float xb, float yb, float dir) {
    const float h = (yb - ya) * dir;
    if (xa == xb) {
        const int i = std::min(int(xa), width_);
        const float frac = xa - float(i);
        acc_[std::size_t(i)] += h * (1.0f - frac);
        acc_[std::size_t(i) + 1] += h * frac;
        touch(i, i + 2);
        return;
    }
    const float x_left = std::min(xa, xb), x_right = std::max(xa, xb);
    const float h_per_x = h / (x_right - x_left);
    const int first = std::min(int(x_left), width_), last = std::min(int(x_right), width_);
    if (first == last) { // within one column (a steep edge): the loop below, unrolled
        const float c =
            (x_right - x_left) * h_per_x * (float(first + 1) - 0.5f * (x_left + x_right));
        acc_[std::size_t(first)] += c;
        acc_[std::size_t(first) + 1] += h - c;
        touch(first, first + 2);
        return;
    }
    float passed = 0, prev = 0; // sum of h_j for j < i; c_{i-1}
    for (int i = first; i <= last; ++i) {
        const float s0 = std::max(x_left, float(i)), s1 = std::min(x_right, float(i + 1));
        const float hi = (s1 - s0) * h_per_x;
        const float c = passed + hi * (float(i + 1) - 0.5f * (s0 + s1));
        acc_[std::size_t(i)] += c - prev;
        prev = c;
        passed += hi;
    }
    acc_[std::size_t(last) + 1] += h - prev;
    touch(first, last + 2);
}

} // namespace casteljau
