// Image levels (paint/image_levels.h): halvings that keep the image's mean,
// weigh each input by the area it covers, are built once for every thread,
// and, chosen by the map, keep an image drawn small from aliasing.
#include "casteljau/paint/raster_image.h"
#include "casteljau/render/drawing.h"
#include "corpus.h"

#include <algorithm>
#include <gtest/gtest.h>
#include <memory>
#include <thread>

namespace casteljau {
namespace {

using testing::Rng;

RasterImage random_image(Rng& rng, int w, int h) {
    RasterImage im;
    im.width = w, im.height = h;
    im.pixels.resize(std::size_t(w) * std::size_t(h));
    for (Premul& p : im.pixels) {
        const float a = float(rng.uniform(0, 1));
        p = {a * float(rng.uniform(0, 1)), a * float(rng.uniform(0, 1)),
             a * float(rng.uniform(0, 1)), a};
    }
    return im;
}

/// The mean of an image's pixels, in double.
std::array<double, 4> mean_of(const RasterImage& im) {
    std::array<double, 4> m{};
    for (const Premul& p : im.pixels) m[0] += p.r, m[1] += p.g, m[2] += p.b, m[3] += p.a;
    for (double& v : m) v /= double(im.pixels.size());
    return m;
}

TEST(ImageLevels, SidesHalveDownToOnePixel) {
    Rng rng(71);
    for (int trial = 0; trial < 40; ++trial) {
        const int w = rng.integer(1, 70), h = rng.integer(1, 70);
        const RasterImage im = random_image(rng, w, h);
        const int last = last_level(w, h);
        for (int k = 0; k <= last + 2; ++k) {
            const RasterImage& l = im.level(k);
            const int kk = std::min(k, last);
            EXPECT_EQ(l.width, std::max(1, w >> kk)) << w << "x" << h << " level " << k;
            EXPECT_EQ(l.height, std::max(1, h >> kk)) << w << "x" << h << " level " << k;
            EXPECT_EQ(l.pixels.size(), std::size_t(l.width) * std::size_t(l.height));
        }
        EXPECT_EQ(&im.level(0), &im);
        EXPECT_EQ(im.level(last).width * im.level(last).height, 1) << w << "x" << h;
    }
}

TEST(ImageLevels, EveryLevelKeepsTheImagesMean) {
    Rng rng(72);
    for (int trial = 0; trial < 40; ++trial) {
        const int w = rng.integer(1, 60), h = rng.integer(1, 60);
        const RasterImage im = random_image(rng, w, h);
        const std::array<double, 4> m0 = mean_of(im);
        for (int k = 1; k <= last_level(w, h); ++k) {
            const std::array<double, 4> m = mean_of(im.level(k));
            for (int c = 0; c < 4; ++c)
                EXPECT_NEAR(m[std::size_t(c)], m0[std::size_t(c)], 2e-6)
                    << w << "x" << h << " level " << k << " channel " << c;
        }
    }
}

/// The mean of `im` over the rectangle [x0, x1] x [y0, y1] of its pixel
/// space, each pixel weighed by the area it has there (the reference).
Premul area_mean(const RasterImage& im, double x0, double y0, double x1, double y1) {
    double s[4] = {};
    for (int y = int(y0); y < im.height && y < y1; ++y)
        for (int x = int(x0); x < im.width && x < x1; ++x) {
            const double area = (std::min(x1, x + 1.0) - std::max(x0, double(x))) *
                                (std::min(y1, y + 1.0) - std::max(y0, double(y)));
            const Premul& p = im.at(x, y);
            s[0] += area * p.r, s[1] += area * p.g, s[2] += area * p.b, s[3] += area * p.a;
        }
    const double inv = 1 / ((x1 - x0) * (y1 - y0));
    return {float(s[0] * inv), float(s[1] * inv), float(s[2] * inv), float(s[3] * inv)};
}

TEST(ImageLevels, EachPixelIsTheMeanOfTheAreaItCovers) {
    // Every level, odd sides too: a pixel of a level m pixels wide covers
    // w / m of the image's pixels along x, fractions at its ends.
    Rng rng(73);
    for (int trial = 0; trial < 30; ++trial) {
        const int w = rng.integer(1, 40), h = rng.integer(1, 40);
        const RasterImage im = random_image(rng, w, h);
        for (int k = 1; k <= last_level(w, h); ++k) {
            const RasterImage& l = im.level(k);
            const double rx = double(w) / l.width, ry = double(h) / l.height;
            for (int y = 0; y < l.height; ++y)
                for (int x = 0; x < l.width; ++x) {
                    const Premul want = area_mean(im, x * rx, y * ry, (x + 1) * rx, (y + 1) * ry);
                    const Premul got = l.at(x, y);
                    EXPECT_NEAR(got.r, want.r, 1e-6f)
                        << w << "x" << h << " level " << k << " at " << x << "," << y;
                    EXPECT_NEAR(got.a, want.a, 1e-6f)
                        << w << "x" << h << " level " << k << " at " << x << "," << y;
                }
        }
    }
}

TEST(ImageLevels, LevelForPicksTheSmallestLevelStillAtLeastTheSizeDrawn) {
    const auto at = [](double sx, double sy) {
        return level_for(Affine::scale(sx, sy), 1024, 1024);
    };
    EXPECT_EQ(at(1, 1), 0);
    EXPECT_EQ(at(3, 3), 0) << "drawn larger";
    EXPECT_EQ(at(0.51, 0.51), 0);
    EXPECT_EQ(at(0.5, 0.5), 1);
    EXPECT_EQ(at(0.26, 0.26), 1);
    EXPECT_EQ(at(0.25, 0.25), 2);
    EXPECT_EQ(at(256.0 / 2048, 256.0 / 2048), 3);
    EXPECT_EQ(at(0.1, 0.6), 0) << "the axis shrunk least decides";
    EXPECT_EQ(at(0.6, 0.1), 0);
    EXPECT_EQ(at(0.2, -0.2), 2) << "a mirror shrinks as much";
    EXPECT_EQ(level_for(Affine::rotate(0.7) * Affine::scale(0.125), 1024, 1024), 3);
    EXPECT_EQ(at(1e-9, 1e-9), 10) << "at most the last level (1 x 1)";
    EXPECT_EQ(level_for(Affine::scale(1e-3), 1, 1), 0);
    EXPECT_EQ(at(0, 0), 0) << "singular";
    EXPECT_EQ(at(std::nan(""), 0.1), 0);
    EXPECT_EQ(at(std::numeric_limits<double>::infinity(), 1), 0);
}

TEST(ImageLevels, ThreadsShareOneBuildAndCopiesBuildTheirOwn) {
    Rng rng(74);
    const RasterImage im = random_image(rng, 300, 200);
    const RasterImage* seen[2] = {};
    std::thread t([&] { seen[0] = &im.level(4); });
    seen[1] = &im.level(4);
    t.join();
    EXPECT_EQ(seen[0], seen[1]);
    EXPECT_EQ(&im.level(2), &im.level(2));
    RasterImage copy = im;
    for (Premul& p : copy.pixels) p = {0, 0, 0, 0};
    EXPECT_EQ(copy.level(4).at(0, 0).a, 0.0f) << "the copy's own pixels";
    EXPECT_GT(im.level(4).at(0, 0).a, 0.0f);
}

/// One-pixel stripes, black and white by column.
std::shared_ptr<RasterImage> stripes(int w, int h) {
    auto im = std::make_shared<RasterImage>();
    im->width = w, im->height = h;
    im->pixels.resize(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            im->pixels[std::size_t(y * w + x)] = x % 2 ? Premul{1, 1, 1, 1} : Premul{0, 0, 0, 1};
    return im;
}

TEST(ImageLevels, StripesDrawnSmallTurnGrayNotMoire) {
    // One-pixel stripes drawn at half their size or less are a uniform 50%
    // gray wherever whole stripes fall in a pixel: point samples between
    // their pixels read a stripe or two and draw moire (stripes of black and
    // white 1 in 3 pixels apart at a third of the size).
    for (const double scale : {0.5, 1 / 2.5, 1 / 3.0, 0.2, 1 / 7.3, 1 / 16.0}) {
        const double side = 480 * scale;
        Drawing d(int(std::ceil(side)) + 4, int(std::ceil(side)) + 4);
        d.image(stripes(480, 480), {2, 2, 2 + side, 2 + side});
        Canvas c(d.width(), d.height());
        d.render(c, Premul{});
        float lo = 1, hi = 0;
        for (int y = 4; y < int(side) - 2; ++y)
            for (int x = 4; x < int(side) - 2; ++x)
                lo = std::min(lo, c.row(y)[x].r), hi = std::max(hi, c.row(y)[x].r);
        EXPECT_NEAR(lo, 0.5f, 1 / 255.0f) << "at 1/" << 1 / scale;
        EXPECT_NEAR(hi, 0.5f, 1 / 255.0f) << "at 1/" << 1 / scale;
    }
}

TEST(ImageLevels, AnImageDrawnAtAnEighthIsTheMeanOfEachEightByEightBlock) {
    // Cairo's box filter, and so rsvg-convert, draws exactly that.
    Rng rng(75);
    auto im = std::make_shared<RasterImage>(random_image(rng, 256, 192));
    Drawing d(40, 30);
    d.image(im, {4, 3, 36, 27});
    Canvas c(40, 30);
    d.render(c, Premul{});
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) {
            const Premul want = area_mean(*im, 8 * x, 8 * y, 8 * x + 8, 8 * y + 8);
            const Premul got = c.row(3 + y)[4 + x];
            EXPECT_NEAR(got.g, want.g, 1e-5f) << "at " << x << "," << y;
            EXPECT_NEAR(got.a, want.a, 1e-5f) << "at " << x << "," << y;
        }
}

} // namespace
} // namespace casteljau
