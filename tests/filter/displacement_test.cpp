// feDisplacementMap: a map of 0.5 everywhere (in any channel, at any
// opacity) is the identity; a constant map shifts by scale * (v - 0.5),
// rounded half up, with transparent black from beyond the window; map pixels
// with alpha 0 read 0 in every channel; channel selection; only the
// subregion is written.
#include "casteljau/filter/displacement.h"
#include "filter_images.h"

#include <gtest/gtest.h>
#include <random>

namespace casteljau {
namespace {

using testing::same;

FilterImage constant(PixelRect box, Premul p) {
    FilterImage img;
    img.reset(box, false);
    for (Premul& q : img.px) q = p;
    return img;
}

FilterImage run(const FilterImage& in, const FilterImage& map, const Subregion& sub, double sx,
                double sy, Channel xc, Channel yc) {
    FilterImage out;
    out.reset(in.box, in.linear);
    displacement_map(in, map, out, sub, sx, sy, xc, yc);
    return out;
}

// out(x, y) == in(x + dx, y + dy) (transparent beyond the window) over sub,
// transparent elsewhere.
void expect_shift(const FilterImage& in, const FilterImage& out, const Subregion& sub, int dx,
                  int dy, const char* what) {
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) {
            const Premul want = sub.contains(x, y) ? in.get(x + dx, y + dy) : Premul{};
            ASSERT_TRUE(same(out.at(x, y), want))
                << what << ": shift " << dx << "," << dy << " at " << x << "," << y;
        }
}

const PixelRect kBox{-20, 30, 4, 48};

TEST(Displacement, HalfGreyMapIsTheIdentity) {
    std::mt19937 rng(1);
    const FilterImage in = testing::random_filter_image(rng, kBox, 0.0f);
    const Subregion sub{0, 0, in.width(), in.height()};
    // 0.5 unpremultiplied: opaque 0.5, or 0.25 at alpha 0.5; alpha 0.5 for A.
    const FilterImage opaque = constant(kBox, {0.5f, 0.5f, 0.5f, 1});
    const FilterImage half = constant(kBox, {0.25f, 0.25f, 0.25f, 0.5f});
    expect_shift(in, run(in, opaque, sub, 37, -11, Channel::R, Channel::B), sub, 0, 0, "opaque");
    expect_shift(in, run(in, half, sub, 37, -11, Channel::G, Channel::R), sub, 0, 0, "half");
    expect_shift(in, run(in, half, sub, 37, -11, Channel::A, Channel::A), sub, 0, 0, "alpha");
}

TEST(Displacement, ConstantMapShifts) {
    std::mt19937 rng(2);
    const FilterImage in = testing::random_filter_image(rng, kBox, 0.0f);
    const Subregion sub{2, 1, 20, 15};
    // R = 1, G = 0, B = 0.75 (opaque): R with scale 6 moves by +3, G with
    // scale 4 by -2, B with scale 8 by +2.
    const FilterImage map = constant(kBox, {1, 0, 0.75f, 1});
    expect_shift(in, run(in, map, sub, 6, 4, Channel::R, Channel::G), sub, 3, -2, "R,G");
    expect_shift(in, run(in, map, sub, 8, 6, Channel::B, Channel::R), sub, 2, 3, "B,R");
    // A negative scale turns the shift around.
    expect_shift(in, run(in, map, sub, -6, -4, Channel::R, Channel::G), sub, -3, 2, "negative");
    // Far beyond the window: everything reads transparent.
    expect_shift(in, run(in, map, sub, 1e12, 0, Channel::R, Channel::G), sub, 1000, 0, "far");
}

// Offsets of exactly half a pixel round up: +0.5 -> +1, -0.5 -> 0, -1.5 -> -1.
TEST(Displacement, HalvesRoundUp) {
    std::mt19937 rng(3);
    const FilterImage in = testing::random_filter_image(rng, kBox, 0.0f);
    const Subregion sub{0, 0, in.width(), in.height()};
    const FilterImage map = constant(kBox, {1, 0, 0, 1}); // R - 0.5 = 0.5, G - 0.5 = -0.5
    expect_shift(in, run(in, map, sub, 1, 1, Channel::R, Channel::G), sub, 1, 0, "+-0.5");
    expect_shift(in, run(in, map, sub, 3, 3, Channel::R, Channel::G), sub, 2, -1, "+-1.5");
}

// A map pixel with alpha 0 reads 0 in every channel: the displacement is
// -scale / 2 there, while the half-grey pixels at alpha 0.5 (0.5 in every
// channel, A included) stay put.
TEST(Displacement, TransparentMapPixels) {
    std::mt19937 rng(4);
    const FilterImage in = testing::random_filter_image(rng, kBox, 0.0f);
    FilterImage map = constant(kBox, {0.25f, 0.25f, 0.25f, 0.5f});
    for (int y = 0; y < map.height(); ++y)
        for (int x = 0; x < map.width(); ++x)
            if ((x + y) % 3 == 0) map.at(x, y) = {};
    const Subregion sub{0, 0, in.width(), in.height()};
    for (Channel c : {Channel::R, Channel::G, Channel::B, Channel::A}) {
        const FilterImage out = run(in, map, sub, 4, 6, c, c);
        for (int y = 0; y < in.height(); ++y)
            for (int x = 0; x < in.width(); ++x) {
                const Premul want = (x + y) % 3 == 0 ? in.get(x - 2, y - 3) : in.at(x, y);
                ASSERT_TRUE(same(out.at(x, y), want))
                    << "channel " << int(c) << " at " << x << "," << y;
            }
    }
}

// The map is read unpremultiplied: R = 0.2 at alpha 0.4 is 0.5 (no shift),
// while the premultiplied 0.2 would have shifted by -3 at scale 10.
TEST(Displacement, MapIsUnpremultiplied) {
    std::mt19937 rng(5);
    const FilterImage in = testing::random_filter_image(rng, kBox, 0.0f);
    const FilterImage map = constant(kBox, {0.2f, 0.1f, 0, 0.4f});
    const Subregion sub{0, 0, in.width(), in.height()};
    // G: 0.1 / 0.4 = 0.25, so scale 8 moves by -2.
    expect_shift(in, run(in, map, sub, 10, 8, Channel::R, Channel::G), sub, 0, -2, "unpremul");
}

} // namespace
} // namespace casteljau
