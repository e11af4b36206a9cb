// Random filter images and exact pixel comparison, for the filter tests.
#pragma once

#include "casteljau/filter/filter_image.h"

#include <random>

namespace casteljau::testing {

/// Whether two pixels are equal in every bit of every channel.
inline bool same(const Premul& a, const Premul& b) {
    return a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a;
}

/// A random premultiplied sRGB image over `box`: a share `clear` of its
/// pixels transparent, a share `opaque` opaque (so that extremes tie and
/// clamps are reached), the rest of random alpha; colors random below alpha.
inline FilterImage random_filter_image(std::mt19937& rng, PixelRect box, float clear = 0.2f,
                                       float opaque = 0.0f) {
    FilterImage img;
    img.reset(box, false);
    std::uniform_real_distribution<float> u(0, 1);
    for (Premul& p : img.px) {
        const float pick = u(rng);
        const float a = pick < clear ? 0.0f : pick < clear + opaque ? 1.0f : u(rng);
        p = {u(rng) * a, u(rng) * a, u(rng) * a, a};
    }
    return img;
}

} // namespace casteljau::testing
