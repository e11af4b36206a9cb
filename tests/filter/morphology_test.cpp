// feMorphology against a brute-force minimum/maximum over the rectangle on
// random images, windows and subregions (exact: min and max round nothing),
// and the lattice properties: erode <= input <= dilate, opening <= input,
// closing >= input away from the window's edges, separability, and the same
// bits from a cut window away from the cut.
#include "casteljau/filter/morphology.h"
#include "filter_images.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <random>

namespace casteljau {
namespace {

using testing::same;

Subregion random_sub(std::mt19937& rng, int w, int h) {
    std::uniform_int_distribution<int> ux(0, w - 1), uy(0, h - 1);
    int x0 = ux(rng), x1 = ux(rng), y0 = uy(rng), y1 = uy(rng);
    if (x0 > x1) std::swap(x0, x1);
    if (y0 > y1) std::swap(y0, y1);
    return {x0, y0, x1 + 1, y1 + 1};
}

Premul brute(const FilterImage& in, int x, int y, bool dilate, int rx, int ry) {
    Premul m = in.get(x, y);
    for (int j = -ry; j <= ry; ++j)
        for (int i = -rx; i <= rx; ++i) {
            const Premul p = in.get(x + i, y + j);
            if (dilate)
                m = {std::max(m.r, p.r), std::max(m.g, p.g), std::max(m.b, p.b),
                     std::max(m.a, p.a)};
            else
                m = {std::min(m.r, p.r), std::min(m.g, p.g), std::min(m.b, p.b),
                     std::min(m.a, p.a)};
        }
    return m;
}

FilterImage run(const FilterImage& in, const Subregion& sub, bool dilate, int rx, int ry) {
    FilterImage out;
    out.reset(in.box, in.linear);
    morphology(in, out, sub, dilate, rx, ry);
    return out;
}

Subregion whole(const FilterImage& img) { return {0, 0, img.width(), img.height()}; }

TEST(Morphology, MatchesBruteForceOnRandomImages) {
    std::mt19937 rng(20240611);
    std::uniform_int_distribution<int> size(1, 40), radius(0, 6), origin(-50, 50);
    for (int trial = 0; trial < 300; ++trial) {
        const int w = size(rng), h = size(rng), x0 = origin(rng), y0 = origin(rng);
        const FilterImage in =
            testing::random_filter_image(rng, {x0, y0, x0 + w, y0 + h}, 0.33f, 0.33f);
        const Subregion sub = random_sub(rng, w, h);
        const bool dilate = trial % 2 == 1;
        // Now and then a radius past the window: the whole row or column.
        const int rx = trial % 17 == 0 ? 45 : radius(rng);
        const int ry = trial % 13 == 0 ? 45 : radius(rng);
        const FilterImage out = run(in, sub, dilate, rx, ry);
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                const Premul want = sub.contains(x, y) ? brute(in, x, y, dilate, rx, ry) : Premul{};
                ASSERT_TRUE(same(out.at(x, y), want))
                    << "trial " << trial << " " << (dilate ? "dilate" : "erode") << " r " << rx
                    << "," << ry << " size " << w << "x" << h << " sub " << sub.x0 << "," << sub.y0
                    << "-" << sub.x1 << "," << sub.y1 << " at " << x << "," << y;
            }
    }
}

TEST(Morphology, ZeroRadiusCopiesTheSubregion) {
    std::mt19937 rng(7);
    const FilterImage in = testing::random_filter_image(rng, {3, 4, 23, 19}, 0.33f, 0.33f);
    const Subregion sub{2, 3, 15, 11};
    for (bool dilate : {false, true}) {
        const FilterImage out = run(in, sub, dilate, 0, 0);
        for (int y = 0; y < in.height(); ++y)
            for (int x = 0; x < in.width(); ++x)
                ASSERT_TRUE(same(out.at(x, y), sub.contains(x, y) ? in.at(x, y) : Premul{}))
                    << x << "," << y;
    }
}

// A huge radius covers the window and the transparent black beyond it: the
// erosion is transparent, the dilation the window's per-channel maximum.
TEST(Morphology, HugeRadiusCoversTheWindow) {
    std::mt19937 rng(11);
    const FilterImage in = testing::random_filter_image(rng, {0, 0, 17, 9}, 0.33f, 0.33f);
    Premul top{};
    for (const Premul& p : in.px)
        top = {std::max(top.r, p.r), std::max(top.g, p.g), std::max(top.b, p.b),
               std::max(top.a, p.a)};
    const int big = 2147483647;
    const FilterImage ero = run(in, whole(in), false, big, big);
    const FilterImage dil = run(in, whole(in), true, big, 3);
    const FilterImage dil2 = run(in, whole(in), true, big, big);
    for (int y = 0; y < in.height(); ++y)
        for (int x = 0; x < in.width(); ++x) {
            ASSERT_TRUE(same(ero.at(x, y), Premul{})) << x << "," << y;
            ASSERT_TRUE(same(dil.at(x, y), brute(in, x, y, true, in.width(), 3))) << x << "," << y;
            ASSERT_TRUE(same(dil2.at(x, y), top)) << x << "," << y;
        }
}

TEST(Morphology, LatticeProperties) {
    std::mt19937 rng(99);
    for (int trial = 0; trial < 40; ++trial) {
        const FilterImage in = testing::random_filter_image(rng, {0, 0, 30, 25}, 0.33f, 0.33f);
        const int rx = trial % 4, ry = (trial / 4) % 4;
        const FilterImage ero = run(in, whole(in), false, rx, ry);
        const FilterImage dil = run(in, whole(in), true, rx, ry);
        const FilterImage opening = run(ero, whole(in), true, rx, ry);
        const FilterImage closing = run(dil, whole(in), false, rx, ry);
        // Dilating by (rx, 0) then (0, ry) is dilating by (rx, ry).
        const FilterImage two_step = run(run(in, whole(in), true, rx, 0), whole(in), true, 0, ry);
        for (int y = 0; y < in.height(); ++y)
            for (int x = 0; x < in.width(); ++x) {
                const Premul p = in.at(x, y), e = ero.at(x, y), d = dil.at(x, y);
                const Premul o = opening.at(x, y), c = closing.at(x, y);
                const float pv[4] = {p.r, p.g, p.b, p.a}, ev[4] = {e.r, e.g, e.b, e.a};
                const float dv[4] = {d.r, d.g, d.b, d.a}, ov[4] = {o.r, o.g, o.b, o.a};
                const float cv[4] = {c.r, c.g, c.b, c.a};
                // Closing needs the doubled rectangle inside the window: beyond
                // it the dilation is unknown (transparent) to the erosion.
                const bool inner = x >= 2 * rx && y >= 2 * ry && x < in.width() - 2 * rx &&
                                   y < in.height() - 2 * ry;
                for (int k = 0; k < 4; ++k) {
                    ASSERT_LE(ev[k], pv[k]) << "trial " << trial << " at " << x << "," << y;
                    ASSERT_LE(pv[k], dv[k]) << "trial " << trial << " at " << x << "," << y;
                    ASSERT_LE(ov[k], pv[k]) << "trial " << trial << " at " << x << "," << y;
                    if (inner) {
                        ASSERT_GE(cv[k], pv[k]) << "trial " << trial << " at " << x << "," << y;
                    }
                }
                ASSERT_LE(e.r, e.a);
                ASSERT_LE(d.g, d.a);
                ASSERT_TRUE(same(two_step.at(x, y), d))
                    << "trial " << trial << " at " << x << "," << y;
            }
    }
}

// A window cut from a larger one gives the same bits wherever the rectangle
// stays inside the cut window.
TEST(Morphology, CutWindowMatchesAwayFromTheCut) {
    std::mt19937 rng(5);
    const FilterImage big = testing::random_filter_image(rng, {-10, -10, 50, 40}, 0.33f, 0.33f);
    const int rx = 3, ry = 2;
    FilterImage cut;
    cut.reset({5, 0, 37, 31}, false);
    for (int y = 0; y < cut.height(); ++y)
        for (int x = 0; x < cut.width(); ++x)
            cut.at(x, y) = big.at(x + cut.box.x0 - big.box.x0, y + cut.box.y0 - big.box.y0);
    for (bool dilate : {false, true}) {
        const FilterImage a = run(big, whole(big), dilate, rx, ry);
        const FilterImage b = run(cut, whole(cut), dilate, rx, ry);
        for (int y = ry; y < cut.height() - ry; ++y)
            for (int x = rx; x < cut.width() - rx; ++x)
                ASSERT_TRUE(same(b.at(x, y), a.at(x + 15, y + 10))) << x << "," << y;
    }
}

} // namespace
} // namespace casteljau
