#include "casteljau/render/output_size.h"

#include <cmath>
#include <cstdio>

namespace casteljau {

OutputSize output_size(double doc_width, double doc_height, const SizeRequest& request) {
    OutputSize out;
    out.scale = request.scale > 0    ? request.scale
                : request.width > 0  ? request.width / doc_width
                : request.height > 0 ? request.height / doc_height
                                     : 1.0;
    const double w = std::ceil(doc_width * out.scale - 1e-9);
    const double h = std::ceil(doc_height * out.scale - 1e-9);
    if (w >= 1 && h >= 1 && w <= kMaxOutputSide && h <= kMaxOutputSide &&
        w * h <= kMaxOutputPixels) {
        out.width = int(w);
        out.height = int(h);
        return out;
    }
    char text[200];
    std::snprintf(text, sizeof text,
                  "output size %.0f x %.0f px is outside the limits (1 to %d px a side, "
                  "at most %.0f pixels)",
                  w, h, kMaxOutputSide, kMaxOutputPixels);
    out.error = text;
    return out;
}

} // namespace casteljau
