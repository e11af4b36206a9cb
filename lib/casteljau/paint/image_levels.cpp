#include "casteljau/paint/image_levels.h"

#include "casteljau/paint/raster_image.h"

#include <algorithm>
#include <cmath>

namespace casteljau {

namespace {

/// The area filter of one axis (image_levels.h): output pixel i weighs
/// inputs taps[i].first + t with weights[taps[i].at + t], t < taps[i].n.
struct AxisFilter {
    struct Taps {
        int first = 0, n = 0;
        std::size_t at = 0;
    };
    std::vector<Taps> taps;
    std::vector<float> weights;

    /// An axis of `from` pixels shrunk to `to` (1 <= to <= from).
    AxisFilter(int from, int to) : taps(std::size_t(to)) {
        const double r = double(from) / to;
        for (int i = 0; i < to; ++i) {
            const double lo = i * r, hi = std::min(double(from), (i + 1) * r);
            Taps& t = taps[std::size_t(i)];
            t.first = int(lo);
            t.at = weights.size();
            // The inputs overlapping [lo, hi) by a positive length.
            for (int j = t.first; j < from && j < hi; ++j, ++t.n)
                weights.push_back(float((std::min(hi, j + 1.0) - std::max(lo, double(j))) / r));
        }
    }
};

} // namespace

ImageLevels::ImageLevels() noexcept = default;
ImageLevels::ImageLevels(const ImageLevels&) noexcept {}
ImageLevels& ImageLevels::operator=(const ImageLevels& other) noexcept {
    if (this != &other) {
        const std::lock_guard lock(mutex_);
        levels_.clear();
    }
    return *this;
}
ImageLevels::~ImageLevels() = default;

const RasterImage& ImageLevels::get(const RasterImage& image, int k) const {
    k = std::min(k, last_level(image.width, image.height));
    if (k <= 0) return image;
    const std::lock_guard lock(mutex_);
    if (int(levels_.size()) < k) levels_.resize(std::size_t(k));
    std::unique_ptr<RasterImage>& level = levels_[std::size_t(k - 1)];
    if (!level)
        level = std::make_unique<RasterImage>(
            shrink_by_area(image, std::max(1, image.width >> k), std::max(1, image.height >> k)));
    return *level;
}

RasterImage shrink_by_area(const RasterImage& image, int w, int h) {
    const AxisFilter across(image.width, w), down(image.height, h);
    RasterImage out;
    out.width = w, out.height = h;
    out.pixels.resize(std::size_t(w) * std::size_t(h));
    // A row at a time: the input rows under it weighed together (runs of
    // floats, which the compiler vectorizes; each input row read once),
    // then that row's columns.
    std::vector<Premul> weighed(std::size_t(image.width));
    const std::size_t floats = 4 * std::size_t(image.width);
    float* sum = &weighed[0].r;
    for (int y = 0; y < h; ++y) {
        const AxisFilter::Taps& v = down.taps[std::size_t(y)];
        for (int t = 0; t < v.n; ++t) {
            const float* in = &image.at(0, v.first + t).r;
            const float wt = down.weights[v.at + std::size_t(t)];
            if (t == 0)
                for (std::size_t i = 0; i < floats; ++i) sum[i] = wt * in[i];
            else
                for (std::size_t i = 0; i < floats; ++i) sum[i] += wt * in[i];
        }
        Premul* row = out.pixels.data() + std::size_t(y) * std::size_t(w);
        for (int x = 0; x < w; ++x) {
            const AxisFilter::Taps& u = across.taps[std::size_t(x)];
            Premul s{};
            for (int t = 0; t < u.n; ++t) {
                const Premul& q = weighed[std::size_t(u.first + t)];
                const float wt = across.weights[u.at + std::size_t(t)];
                s = {s.r + wt * q.r, s.g + wt * q.g, s.b + wt * q.b, s.a + wt * q.a};
            }
            row[x] = s;
        }
    }
    return out;
}

int last_level(int w, int h) {
    int k = 0;
    for (int n = std::max(w, h); n > 1; n /= 2) ++k;
    return k;
}

int level_for(const Affine& to_device, int w, int h) {
    const double scale =
        std::max(std::hypot(to_device.a, to_device.b), std::hypot(to_device.c, to_device.d));
    if (!(scale > 0) || !std::isfinite(scale)) return 0;
    // Halve while the level after still covers the size drawn: scale 2^(k+1)
    // <= 1. The slack absorbs the rounding of a map built from decimal
    // sizes (a 2048 px image drawn at 256 px is scale 2^-3, not a hair
    // above it); doubling is exact, so it accumulates nothing.
    const int last = last_level(w, h);
    int k = 0;
    for (double s = 2 * scale; s <= 1 + 1e-9 && k < last; s *= 2) ++k;
    return k;
}

} // namespace casteljau
