#include "casteljau/io/canvas_write.h"

#include "casteljau/io/image_write.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <vector>

namespace casteljau {

namespace {

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

} // namespace

template <class Pixel>
std::string write_canvas_atomic(const std::string& path, const BasicCanvas<Pixel>& canvas) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return std::tolower(c); });
    const bool exr = ext == ".exr", jpeg = ext == ".jpg" || ext == ".jpeg";
    const int w = canvas.width(), h = canvas.height();
    std::vector<float> out(std::size_t(w) * std::size_t(h) * 4);
    for (int y = 0; y < h; ++y) {
        const Pixel* src = canvas.row(y);
        float* dst = &out[std::size_t(y) * std::size_t(w) * 4];
        for (int x = 0; x < w; ++x, dst += 4) {
            Premul p = to_premul(src[x]);
            if (jpeg) { // over white
                const float k = 1.0f - p.a;
                p = {p.r + k, p.g + k, p.b + k, 1.0f};
            }
            const float inv = p.a > 0 ? 1.0f / p.a : 0.0f;
            float c[3] = {std::min(p.r * inv, 1.0f), std::min(p.g * inv, 1.0f),
                          std::min(p.b * inv, 1.0f)};
            if (exr)
                for (float& v : c) v = srgb_to_linear(v) * p.a;
            dst[0] = c[0], dst[1] = c[1], dst[2] = c[2], dst[3] = std::min(p.a, 1.0f);
        }
    }
    return write_image_atomic(path, {w, h, out, exr ? Alpha::premultiplied : Alpha::straight});
}

template std::string write_canvas_atomic(const std::string&, const Canvas&);
template std::string write_canvas_atomic(const std::string&, const Canvas8&);

} // namespace casteljau
