#include "casteljau/paint/canvas.h"

#include <algorithm>

namespace casteljau {

Canvas::Canvas(int width, int height, int ox, int oy) { reset(width, height, ox, oy); }

void Canvas::reset(int width, int height, int ox, int oy, Premul clear) {
    w_ = width, h_ = height, ox_ = ox, oy_ = oy;
    px_.assign(std::size_t(width) * std::size_t(height), clear);
}

void Canvas::fill(Premul color) { std::fill(px_.begin(), px_.end(), color); }

void Canvas::composite_span(const Span& s, Premul c) {
    Premul* d = row(s.y) + s.x;
    for (int i = 0; i < s.len; ++i) {
        const float k = s.coverage[i];
        // Opaque and fully covered: the source replaces the pixel (the
        // general formula gives the same bits, at the price of a read).
        if (k == 1.0f && c.a == 1.0f) {
            d[i] = c;
            continue;
        }
        blend_over(d[i], c, k);
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
