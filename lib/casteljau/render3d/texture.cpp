#include "casteljau/render3d/texture.h"

#include "casteljau/io/detail/oiio_module.h"
#include "casteljau/io/image_read.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

// Squares per unit of s and of t.
constexpr double kChecks = 8;
const Rgb kLight{0.80f, 0.78f, 0.72f}, kDark{0.30f, 0.33f, 0.42f};

// The integral of the square wave that is +1 on [0, 1), -1 on [1, 2), period 2.
double triangle_wave(double x) {
    const double f = x - 2 * std::floor(x / 2); // in [0, 2)
    return f < 1 ? f : 2 - f;
}

// The square wave averaged over [x - w/2, x + w/2].
double filtered_square(double x, double w) {
    if (w < 1e-6) return x - 2 * std::floor(x / 2) < 1 ? 1 : -1;
    return (triangle_wave(x + w / 2) - triangle_wave(x - w / 2)) / w;
}

float srgb_to_linear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

} // namespace

std::string Texture::load(const std::string& path) {
    if (decodes_without_openimageio(path)) return load_decoded(path);
    const detail::OiioModule& oiio = detail::oiio_module();
    if (!oiio.codec) return path + ": " + detail::oiio_missing("reading a texture");
    // Any format OIIO reads; alpha, unused, as OIIO gives it (premultiplied).
    detail::OiioOpened in = oiio.codec->open(nullptr, path, {}, false, false);
    if (!in.reader) return path + ": cannot read the texture (" + in.error + ")";
    const detail::ImageHeader& spec = in.reader->header();
    if (const std::string e = size_error(path, spec.width, spec.height); !e.empty()) return e;
    const int channels = spec.channels;
    std::vector<float> data(std::size_t(spec.width) * spec.height * channels);
    if (const std::string e = in.reader->read(channels, data.data(), sizeof(float) * channels);
        !e.empty())
        return path + ": cannot read the texture (" + e + ")";
    w_ = spec.width;
    h_ = spec.height;
    px_.resize(std::size_t(w_) * h_);
    for (std::size_t i = 0; i < px_.size(); ++i) {
        const float* p = &data[i * channels];
        float c[3] = {p[0], p[channels > 1 ? 1 : 0], p[channels > 2 ? 2 : 0]};
        for (float& v : c) v = std::clamp(spec.linear ? v : srgb_to_linear(v), 0.0f, 1.0f);
        px_[i] = {c[0], c[1], c[2]};
    }
    return {};
}

std::string Texture::load_decoded(const std::string& path) {
    const ImageReadResult r = read_image_file(path, kMaxTexturePixels);
    if (!r.image) return r.error; // it names the path
    const RasterImage& im = *r.image;
    if (const std::string e = size_error(path, im.width, im.height); !e.empty()) return e;
    w_ = im.width;
    h_ = im.height;
    px_.resize(im.pixels.size());
    // Premultiplied sRGB-encoded values, as OIIO gave them, to linear.
    const auto linear = [](float v) { return std::clamp(srgb_to_linear(v), 0.0f, 1.0f); };
    for (std::size_t i = 0; i < px_.size(); ++i)
        px_[i] = {linear(im.pixels[i].r), linear(im.pixels[i].g), linear(im.pixels[i].b)};
    return {};
}

std::string Texture::size_error(const std::string& path, int w, int h) {
    if (w >= 1 && h >= 1 && w <= kMaxTextureSide && h <= kMaxTextureSide &&
        double(w) * h <= double(kMaxTexturePixels))
        return {};
    return path + ": texture size " + std::to_string(w) + " x " + std::to_string(h) +
           " is outside 1.." + std::to_string(kMaxTextureSide) + " a side, 2^26 pixels";
}

Rgb Texture::checker(Point st, Vec2 footprint) const {
    const double k = filtered_square(st.x * kChecks, footprint.x * kChecks) *
                     filtered_square(st.y * kChecks, footprint.y * kChecks);
    const float a = float(0.5 + 0.5 * k);
    return {kDark.r + a * (kLight.r - kDark.r), kDark.g + a * (kLight.g - kDark.g),
            kDark.b + a * (kLight.b - kDark.b)};
}

Rgb Texture::texel(int x, int y) const {
    x %= w_, y %= h_;
    return px_[std::size_t(y < 0 ? y + h_ : y) * w_ + (x < 0 ? x + w_ : x)];
}

Rgb Texture::at(Point st, Vec2 footprint) const {
    if (px_.empty()) return checker(st, footprint);
    // t runs up the image, as in OBJ and Quake texture space.
    const double x = st.x * w_ - 0.5, y = (1 - st.y) * h_ - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    const float ax = float(x - fx), ay = float(y - fy);
    const int x0 = int(std::fmod(fx, w_)), y0 = int(std::fmod(fy, h_));
    const Rgb a = texel(x0, y0), b = texel(x0 + 1, y0), c = texel(x0, y0 + 1),
              d = texel(x0 + 1, y0 + 1);
    const auto mix = [&](float p, float q, float r, float s) {
        return (1 - ay) * ((1 - ax) * p + ax * q) + ay * ((1 - ax) * r + ax * s);
    };
    return {mix(a.r, b.r, c.r, d.r), mix(a.g, b.g, c.g, d.g), mix(a.b, b.b, c.b, d.b)};
}

} // namespace casteljau
