#include "casteljau/io/canvas_write.h"

#include "casteljau/io/image_write.h"
#include "casteljau/io/png_write.h"
#include "casteljau/paint/straight_rgba.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <new>
#include <vector>

namespace casteljau {

namespace {

float srgb_to_linear(float v) {
    return v <= 0.04045f ? v / 12.92f : std::pow((v + 0.055f) / 1.055f, 2.4f);
}

} // namespace

template <class Pixel>
std::string write_canvas_atomic(const std::string& path, const BasicCanvas<Pixel>& canvas) {
    const std::string ext = image_extension(path);
    const bool exr = ext == ".exr", jpeg = ext == ".jpg" || ext == ".jpeg";
    const int w = canvas.width(), h = canvas.height();
    const std::size_t values = std::size_t(w) * std::size_t(h) * 4;
    if (ext == ".png") { // straight 8-bit values, converted into the encoder's rows
        try {
            PngRows rows(w, h);
            for (int y = 0; y < h; ++y) straight_row8(canvas.row(y), w, rows.rgba(y));
            return write_png_atomic(path, std::move(rows));
        } catch (const std::bad_alloc&) {
            return path + ": out of memory";
        }
    }
    if (!stores_float(path)) { // JPEG, ...: straight 8-bit values, rounded by straight_rgba8
        std::vector<std::uint8_t> out(values);
        straight_rgba8(canvas, out, jpeg);
        return write_image_atomic(path, {.width = w, .height = h, .rgba8 = out});
    }
    std::vector<float> out(values);
    if (!exr) { // TIFF: straight float
        straight_rgba(canvas, out);
        return write_image_atomic(path, {w, h, out, Alpha::straight});
    }
    for (int y = 0; y < h; ++y) {
        const Pixel* src = canvas.row(y);
        float* dst = &out[std::size_t(y) * std::size_t(w) * 4];
        for (int x = 0; x < w; ++x, dst += 4) {
            const Premul p = to_premul(src[x]);
            const Rgba c = straight_of(p);
            dst[0] = srgb_to_linear(c.r) * p.a, dst[1] = srgb_to_linear(c.g) * p.a;
            dst[2] = srgb_to_linear(c.b) * p.a, dst[3] = c.a;
        }
    }
    return write_image_atomic(path, {w, h, out, Alpha::premultiplied});
}

template std::string write_canvas_atomic(const std::string&, const Canvas&);
template std::string write_canvas_atomic(const std::string&, const Canvas8&);

} // namespace casteljau
