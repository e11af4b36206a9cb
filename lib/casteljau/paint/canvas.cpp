#include "casteljau/paint/canvas.h"

#include <algorithm>

namespace casteljau {

Canvas::Canvas(int width, int height, int ox, int oy) { reset(width, height, ox, oy); }

void Canvas::reset(int width, int height, int ox, int oy, Premul clear) {
    w_ = width, h_ = height, ox_ = ox, oy_ = oy;
    view_ = nullptr;
    px_.assign(std::size_t(width) * std::size_t(height), clear);
}

void Canvas::view_rows(Canvas& parent, int y0, int rows, Premul clear) {
    w_ = parent.w_, h_ = rows, ox_ = parent.ox_, oy_ = parent.oy_ + y0;
    view_ = parent.row(y0);
    fill(clear);
}

void Canvas::fill(Premul color) {
    Premul* p = pixels();
    std::fill(p, p + std::size_t(w_) * std::size_t(h_), color);
}

void Canvas::composite_span(const Span& s, Premul c) {
    Premul* d = row(s.y) + s.x;
    const float* k = s.coverage;
    if (!k) { // one coverage for the whole span
        if (c.a == 1.0f && s.solid == 1.0f)
            std::fill(d, d + s.len, c);
        else
            for (int i = 0; i < s.len; ++i) blend_over(d[i], c, s.solid);
        return;
    }
    if (c.a < 1.0f) {
        for (int i = 0; i < s.len; ++i) blend_over(d[i], c, k[i]);
        return;
    }
    // Opaque: where fully covered the source replaces the pixel (the general
    // formula gives the same bits, at the price of a read), run by run.
    for (int i = 0; i < s.len;) {
        int j = i;
        while (j < s.len && k[j] == 1.0f) ++j;
        std::fill(d + i, d + j, c);
        for (i = j; i < s.len && k[i] != 1.0f; ++i) blend_over(d[i], c, k[i]);
    }
}

void Canvas::composite_layer(const Canvas& layer, float opacity) {
    const int dx = layer.ox_ - ox_, dy = layer.oy_ - oy_;
    const int x0 = std::max(0, dx), x1 = std::min(w_, dx + layer.w_);
    const int y0 = std::max(0, dy), y1 = std::min(h_, dy + layer.h_);
    for (int y = y0; y < y1; ++y) {
        const Premul* s = layer.row(y - dy) + (x0 - dx);
        Premul* d = row(y) + x0;
        for (int i = 0; i < x1 - x0; ++i) {
            blend_over(d[i], s[i], opacity);
        }
    }
}

} // namespace casteljau
