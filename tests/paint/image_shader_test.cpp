// Image shading: exact pixels at pixel centres, nearest against bilinear
// under scaling, tiling and edge extension, opacity, a rotated map against a
// direct computation, rows shaded at once against the same, coordinates far
// outside the double range of sense, and span painting equal to at() pixel
// by pixel.
#include "casteljau/paint/canvas.h"
#include "casteljau/paint/image_shader.h"
#include "corpus.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <gtest/gtest.h>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace casteljau {
namespace {

RasterImage random_image(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<float> unit(0, 1);
    RasterImage im;
    im.width = w, im.height = h;
    for (int i = 0; i < w * h; ++i) {
        const float a = unit(rng);
        im.pixels.push_back({unit(rng) * a, unit(rng) * a, unit(rng) * a, a});
    }
    return im;
}

bool same(const Premul& p, const Premul& q) {
    return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
}

// Streamed, not "(" + std::to_string(...): GCC 12 at -O3 warns (-Wrestrict)
// about a false overlap in that operator+.
std::string str(const Premul& p) {
    std::ostringstream s;
    s << "(" << p.r << ", " << p.g << ", " << p.b << ", " << p.a << ")";
    return s.str();
}

std::string where(int x, int y) {
    std::ostringstream s;
    s << "(" << x << ", " << y << ")";
    return s.str();
}

void expect_near(const Premul& p, const Premul& q, float tol, const std::string& what) {
    EXPECT_NEAR(p.r, q.r, tol) << what;
    EXPECT_NEAR(p.g, q.g, tol) << what;
    EXPECT_NEAR(p.b, q.b, tol) << what;
    EXPECT_NEAR(p.a, q.a, tol) << what;
}

Premul mix(const Premul& a, const Premul& b, double t) {
    const auto m = [&](float x, float y) { return float((1 - t) * x + t * y); };
    return {m(a.r, b.r), m(a.g, b.g), m(a.b, b.b), m(a.a, b.a)};
}

/// Column or row k of an image `size` pixels long: tiled by floor-mod, or padded.
int tiled_or_padded(int k, int size, bool repeat) {
    return repeat ? ((k % size) + size) % size : std::clamp(k, 0, size - 1);
}

/// The four combinations of smooth and repeat.
constexpr bool kModes[4][2] = {{false, false}, {false, true}, {true, false}, {true, true}};

TEST(ImageShader, RefusesEmptyImagesAndSingularMaps) {
    const RasterImage im = random_image(2, 2, 1);
    ImageShader sh;
    EXPECT_FALSE(sh.prepare(RasterImage{}, Affine::identity(), 1, true, false));
    EXPECT_FALSE(sh.prepare(im, Affine::scale(0, 1), 1, true, false));
    EXPECT_FALSE(sh.prepare(im, {1, 2, 2, 4, 0, 0}, 1, true, false));
    EXPECT_FALSE(sh.prepare(im, {1, 0, 0, 1, NAN, 0}, 1, true, false));
    EXPECT_FALSE(sh.prepare(im, {1e200, 0, 0, 1e200, 0, 0}, 1, true, false)); // det = inf
    EXPECT_TRUE(sh.prepare(im, Affine::identity(), 1, true, false));
}

TEST(ImageShader, IdentityGivesExactPixelsAtCentres) {
    // The identity is copied (a translation by whole pixels); mirrors and the
    // half turn are sampled, their pixel centres landing on the image's: both
    // give each pixel exactly.
    const RasterImage im = random_image(5, 4, 2);
    const int w = im.width, h = im.height;
    struct Map {
        Affine to_device;
        bool flip_x, flip_y;
    };
    const Map maps[] = {
        {Affine::identity(), false, false},
        {Affine::translate({double(w), 0}) * Affine::scale(-1, 1), true, false},
        {Affine::translate({0, double(h)}) * Affine::scale(1, -1), false, true},
        {Affine::translate({double(w), double(h)}) * Affine::scale(-1, -1), true, true}};
    for (const Map& m : maps)
        for (const auto& [smooth, repeat] : kModes) {
            ImageShader sh;
            ASSERT_TRUE(sh.prepare(im, m.to_device, 1, smooth, repeat));
            for (int y = 0; y < h; ++y)
                for (int x = 0; x < w; ++x) {
                    const Premul want = im.at(m.flip_x ? w - 1 - x : x, m.flip_y ? h - 1 - y : y);
                    EXPECT_TRUE(same(sh.at(x, y), want))
                        << smooth << repeat << m.flip_x << m.flip_y << " (" << x << ", " << y
                        << ") " << str(sh.at(x, y));
                }
        }
}

TEST(ImageShader, NearestAndBilinearOnATwoByTwoImageScaledByFour) {
    RasterImage im;
    im.width = im.height = 2;
    im.pixels = {{1, 0, 0, 1}, {0, 1, 0, 1}, {0, 0, 0.5f, 0.5f}, {0, 0, 0, 0}};
    ImageShader nearest, pad, tile;
    ASSERT_TRUE(nearest.prepare(im, Affine::scale(4), 1, false, false));
    ASSERT_TRUE(pad.prepare(im, Affine::scale(4), 1, true, false));
    ASSERT_TRUE(tile.prepare(im, Affine::scale(4), 1, true, true));
    // Device centre x + 0.5 is image point (x + 0.5) / 4; between centres
    // u = (x + 0.5) / 4 - 0.5: -0.375, -0.125, 0.125, ... 1.375 for x = 0..7.
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const std::string at = where(x, y);
            EXPECT_TRUE(same(nearest.at(x, y), im.at(x / 4, y / 4))) << at;
            const double u = (x + 0.5) / 4 - 0.5, v = (y + 0.5) / 4 - 0.5;
            // Pad: clamped between the centres.
            const double cu = std::clamp(u, 0.0, 1.0), cv = std::clamp(v, 0.0, 1.0);
            const Premul want_pad =
                mix(mix(im.at(0, 0), im.at(1, 0), cu), mix(im.at(0, 1), im.at(1, 1), cu), cv);
            expect_near(pad.at(x, y), want_pad, 1e-6f, "pad " + at);
            // Repeat: u = -0.375 lies between pixel 1 (of the tile to the
            // left) and pixel 0, 0.625 of the way to pixel 0.
            const double wu = u < 0 ? -u : u > 1 ? 2 - u : u; // weight of pixel 1
            const double wv = v < 0 ? -v : v > 1 ? 2 - v : v;
            const Premul want_tile =
                mix(mix(im.at(0, 0), im.at(1, 0), wu), mix(im.at(0, 1), im.at(1, 1), wu), wv);
            expect_near(tile.at(x, y), want_tile, 1e-6f, "repeat " + at);
        }
    // Spot values: 0.375 of the way from red to green; and at the corner
    // seam, weights 0.625 and 0.375 on each axis.
    expect_near(pad.at(3, 0), {0.625f, 0.375f, 0, 1}, 1e-6f, "pad (3, 0)");
    expect_near(tile.at(0, 0), {0.390625f, 0.234375f, 0.1171875f, 0.7421875f}, 1e-6f,
                "repeat (0, 0)");
    expect_near(pad.at(0, 0), im.at(0, 0), 0, "pad corner");
}

TEST(ImageShader, RepeatTilesThePlane) {
    const RasterImage im = random_image(3, 5, 3);
    std::mt19937 rng(4);
    std::uniform_int_distribution<int> k(-1000, 1000), px(0, 40);
    for (const bool smooth : {false, true}) {
        ImageShader sh;
        ASSERT_TRUE(sh.prepare(im, Affine::scale(2), 1, smooth, true)); // period 6 x 10
        for (int trial = 0; trial < 500; ++trial) {
            const int x = px(rng), y = px(rng), kx = k(rng), ky = k(rng);
            EXPECT_TRUE(same(sh.at(x + 6 * kx, y + 10 * ky), sh.at(x, y)))
                << smooth << " (" << x << ", " << y << ") + (" << kx << ", " << ky << ") periods";
        }
    }
}

// Wrapping multiplies by the reciprocal of the width, and the quotient can
// round across an integer: 15^- x (1/5) gives 3, 49 x (1/49) gives
// 0.99999... The point must still wrap to the right pixel: the last one of
// the tile just below its end, the first one at its end.
TEST(ImageShader, RepeatWrapsRightWhereTheQuotientRounds) {
    struct Case {
        int width;
        double x;  // image point, at device pixel (0, 0)'s centre
        int pixel; // the column it lies in
    };
    for (const Case& c : {Case{5, std::nextafter(15.0, 0.0), 4}, Case{49, 49.0, 0}}) {
        const RasterImage im = random_image(c.width, 2, 10);
        ImageShader sh;
        ASSERT_TRUE(sh.prepare(im, Affine::translate({-(c.x - 0.5), 0}), 1, false, true));
        EXPECT_TRUE(same(sh.at(0, 0), im.at(c.pixel, 0))) << c.width;
    }
}

TEST(ImageShader, PadExtendsTheEdgePixels) {
    const RasterImage im = random_image(4, 3, 5);
    for (const bool smooth : {false, true}) {
        ImageShader sh;
        ASSERT_TRUE(sh.prepare(im, Affine::identity(), 1, smooth, false));
        for (int y = 0; y < im.height; ++y)
            for (int d : {1, 2, 17, 100000}) {
                EXPECT_TRUE(same(sh.at(-d, y), im.at(0, y))) << smooth << " left " << d;
                EXPECT_TRUE(same(sh.at(im.width - 1 + d, y), im.at(im.width - 1, y)))
                    << smooth << " right " << d;
            }
        for (int x = 0; x < im.width; ++x) {
            EXPECT_TRUE(same(sh.at(x, -9), im.at(x, 0))) << smooth;
            EXPECT_TRUE(same(sh.at(x, im.height + 9), im.at(x, im.height - 1))) << smooth;
        }
        EXPECT_TRUE(same(sh.at(-5, -5), im.at(0, 0))) << smooth;
        EXPECT_TRUE(same(sh.at(50, 50), im.at(im.width - 1, im.height - 1))) << smooth;
    }
}

TEST(ImageShader, OpacityScalesEveryChannel) {
    const RasterImage im = random_image(3, 3, 6);
    const Affine m = Affine::translate({0.3, -0.2}) * Affine::scale(1.7);
    for (const auto& [smooth, repeat] : kModes) {
        ImageShader full, part;
        ASSERT_TRUE(full.prepare(im, m, 1, smooth, repeat));
        ASSERT_TRUE(part.prepare(im, m, 0.3f, smooth, repeat));
        for (int y = -2; y < 7; ++y)
            for (int x = -2; x < 7; ++x) {
                const Premul f = full.at(x, y), p = part.at(x, y);
                EXPECT_FLOAT_EQ(p.r, f.r * 0.3f);
                EXPECT_FLOAT_EQ(p.g, f.g * 0.3f);
                EXPECT_FLOAT_EQ(p.b, f.b * 0.3f);
                EXPECT_FLOAT_EQ(p.a, f.a * 0.3f);
            }
    }
}

/// Index k of a row or column of n pixels, padded or tiled.
int index_of(int k, int n, bool repeat) {
    return repeat ? ((k % n) + n) % n : std::clamp(k, 0, n - 1);
}

/// Bilinear or nearest sampling, padded or tiled, computed directly from the
/// formulas.
Premul reference(const RasterImage& im, double px, double py, bool smooth, bool repeat = false) {
    const auto at = [&](int i, int j) {
        return im.at(index_of(i, im.width, repeat), index_of(j, im.height, repeat));
    };
    if (!smooth) return at(int(std::floor(px)), int(std::floor(py)));
    // Pad: the point clamped between the first and last pixel centres.
    const double u = repeat ? px - 0.5 : std::clamp(px - 0.5, 0.0, im.width - 1.0);
    const double v = repeat ? py - 0.5 : std::clamp(py - 0.5, 0.0, im.height - 1.0);
    const int i = int(std::floor(u)), j = int(std::floor(v));
    return mix(mix(at(i, j), at(i + 1, j), u - i), mix(at(i, j + 1), at(i + 1, j + 1), u - i),
               v - j);
}

TEST(ImageShader, RotatedMapMatchesADirectComputation) {
    const RasterImage im = random_image(7, 5, 7);
    const double angle = 0.4, sx = 2.5, sy = 1.5, tx = 10.3, ty = 4.7;
    const Affine m = Affine::translate({tx, ty}) * Affine::rotate(angle) * Affine::scale(sx, sy);
    for (const bool smooth : {false, true}) {
        ImageShader sh;
        ASSERT_TRUE(sh.prepare(im, m, 1, smooth, false));
        for (int y = -3; y < 25; ++y)
            for (int x = -3; x < 25; ++x) {
                // Undo the translation, the rotation and the scale, in turn.
                const double dx = x + 0.5 - tx, dy = y + 0.5 - ty;
                const double rx = std::cos(angle) * dx + std::sin(angle) * dy;
                const double ry = -std::sin(angle) * dx + std::cos(angle) * dy;
                const double px = rx / sx, py = ry / sy;
                // Nearest: a point within rounding of a pixel edge may go either way.
                const double edge = 1e-9;
                if (!smooth && (std::fabs(px - std::round(px)) < edge ||
                                std::fabs(py - std::round(py)) < edge))
                    continue;
                expect_near(sh.at(x, y), reference(im, px, py, smooth), smooth ? 1e-5f : 0,
                            (smooth ? "bilinear " : "nearest ") + where(x, y));
            }
    }
}

TEST(ImageShader, RowsShadeAsTheFormulasSay) {
    // Maps that keep rows level (scale, flip, translation: p.y computed once
    // a row), translations by whole pixels (copied) and a map that does not
    // keep rows level, in every mode, on rows longer than the span painter's
    // chunk and rows of one pixel.
    const RasterImage im = random_image(9, 7, 11);
    const Affine maps[] = {
        Affine::translate({3.3, -2.1}) * Affine::scale(2.7, 1.9),
        Affine::translate({40.5, 30.25}) * Affine::scale(-1.5, -3.25),
        Affine::translate({1, 2}) * Affine::scale(0.37),
        Affine::translate({5, 5}) * Affine::rotate(0.7) * Affine::scale(2.2),
        Affine::identity(),
        Affine::translate({-3, 5}),
        Affine::translate({1e6, -7}),
    };
    testing::Rng rng(23);
    for (const Affine& m : maps)
        for (const auto& [smooth, repeat] : kModes) {
            ImageShader sh;
            ASSERT_TRUE(sh.prepare(im, m, 1, smooth, repeat));
            const Affine inv = m.inverse();
            for (const int n : {1, 2, 63, 64, 65, 200}) {
                const int x = rng.integer(-60, 60), y = rng.integer(-60, 60);
                std::vector<Premul> row(static_cast<std::size_t>(n));
                sh.shade(x, y, n, row.data());
                for (int i = 0; i < n; ++i) {
                    const Point p = inv * Point{x + i + 0.5, y + 0.5};
                    // Nearest: a point within rounding of a pixel edge may go either way.
                    const double edge = 1e-9;
                    if (!smooth && (std::fabs(p.x - std::round(p.x)) < edge ||
                                    std::fabs(p.y - std::round(p.y)) < edge))
                        continue;
                    expect_near(row[std::size_t(i)], reference(im, p.x, p.y, smooth, repeat),
                                smooth ? 1e-5f : 0,
                                (smooth ? "bilinear" : "nearest") +
                                    std::string(repeat ? ", repeat " : ", pad ") + where(x + i, y));
                }
            }
        }
}

// Translations by whole pixels copy rows (whole stretches of the image's
// row, tiled or padded): against the pixel each device pixel lies on, at
// opacity 1 (a plain copy) and below it, on rows that start left of, inside
// and right of the image and wrap around it several times.
TEST(ImageShader, CopiedRowsArePixelByPixelTheImagesPixels) {
    const RasterImage im = random_image(7, 3, 31);
    testing::Rng rng(37);
    for (const float opacity : {1.0f, 0.6f})
        for (const bool repeat : {false, true})
            for (int trial = 0; trial < 200; ++trial) {
                const int tx = rng.integer(-30, 30), ty = rng.integer(-5, 5);
                ImageShader sh;
                ASSERT_TRUE(sh.prepare(im, Affine::translate({double(tx), double(ty)}), opacity,
                                       true, repeat));
                const int x = rng.integer(-40, 40), y = rng.integer(-6, 6);
                const int n = rng.integer(1, 40);
                std::vector<Premul> row(static_cast<std::size_t>(n));
                sh.shade(x, y, n, row.data());
                for (int i = 0; i < n; ++i) {
                    const Premul p = im.at(tiled_or_padded(x + i - tx, im.width, repeat),
                                           tiled_or_padded(y - ty, im.height, repeat));
                    const Premul want{p.r * opacity, p.g * opacity, p.b * opacity, p.a * opacity};
                    EXPECT_TRUE(same(row[std::size_t(i)], want))
                        << (repeat ? "repeat" : "pad") << " opacity " << opacity << " translate "
                        << where(tx, ty) << " row " << where(x, y) << " n " << n << " pixel " << i
                        << ": " << str(row[std::size_t(i)]) << " want " << str(want);
                }
            }
}

// An opaque image's 8-bit copy is its pixels quantized; one alpha short of
// exactly 1 leaves the image without one.
TEST(ImageShader, OnlyOpaqueImagesCarryTheir8BitCopy) {
    RasterImage im = random_image(5, 4, 41);
    im.find_opaque8();
    EXPECT_TRUE(im.opaque8.empty());
    for (Premul& p : im.pixels) p = {p.r, p.g, p.b, 1.0f};
    im.find_opaque8();
    ASSERT_EQ(im.opaque8.size(), im.pixels.size());
    for (std::size_t i = 0; i < im.pixels.size(); ++i)
        EXPECT_EQ(im.opaque8[i], quantize(im.pixels[i])) << "pixel " << i;
    im.pixels[7].a = std::nextafter(1.0f, 0.0f);
    im.find_opaque8();
    EXPECT_TRUE(im.opaque8.empty());
}

// Where an opaque image is translated by whole pixels at opacity 1, spans of
// coverage 1 on an 8-bit canvas take its stored bytes: the canvas comes out
// as the composite of the pixel each device pixel lies on (found here),
// byte for byte, over a translucent background, tiled and padded, on rows
// left of, inside and right of the image. Elsewhere nothing is stored.
TEST(ImageShader, OpaqueImagesStoreTheBytesTheirCompositeGives) {
    RasterImage im = random_image(7, 3, 43);
    for (Premul& p : im.pixels) p = {p.r, p.g, p.b, 1.0f};
    im.find_opaque8();
    ASSERT_FALSE(im.opaque8.empty());
    const Premul bg{0.1f, 0.3f, 0.2f, 0.5f};
    testing::Rng rng(47);
    for (const bool repeat : {false, true})
        for (int trial = 0; trial < 100; ++trial) {
            const int tx = rng.integer(-30, 30), ty = rng.integer(-5, 5);
            ImageShader sh;
            ASSERT_TRUE(
                sh.prepare(im, Affine::translate({double(tx), double(ty)}), 1, true, repeat));
            const int x = rng.integer(-40, 40), y = rng.integer(-6, 6), n = rng.integer(1, 40);
            // The canvas: columns [-40, 80) of row y.
            Canvas8 canvas(120, 1, -40, y), expected(120, 1, -40, y);
            canvas.fill(bg);
            expected.fill(bg);
            std::vector<Premul8> stored(static_cast<std::size_t>(n));
            EXPECT_TRUE(sh.store_opaque(x, y, n, stored.data()));
            ImageSpanPainter<Premul8> painter(canvas, sh);
            painter.span({y, x, n, nullptr, 1.0f});
            for (int i = 0; i < n; ++i) {
                Premul8& want = expected.row(0)[x + i + 40];
                blend_over(want,
                           im.at(tiled_or_padded(x + i - tx, im.width, repeat),
                                 tiled_or_padded(y - ty, im.height, repeat)),
                           1);
                EXPECT_EQ(stored[std::size_t(i)], want)
                    << (repeat ? "repeat" : "pad") << " translate " << where(tx, ty) << " row "
                    << where(x, y) << " pixel " << i;
            }
            for (int i = 0; i < 120; ++i)
                EXPECT_EQ(canvas.row(0)[i], expected.row(0)[i])
                    << (repeat ? "repeat" : "pad") << " translate " << where(tx, ty) << " row "
                    << where(x, y) << " n " << n << " column " << i - 40;
        }
    Premul8 out[4];
    ImageShader sh;
    ASSERT_TRUE(sh.prepare(im, Affine::translate({2, 1}), 0.6f, true, false));
    EXPECT_FALSE(sh.store_opaque(0, 0, 4, out)) << "opacity below 1";
    ASSERT_TRUE(sh.prepare(im, Affine::translate({2.5, 1}), 1, true, false));
    EXPECT_FALSE(sh.store_opaque(0, 0, 4, out)) << "half a pixel off the grid";
    const RasterImage translucent = random_image(7, 3, 43);
    ASSERT_TRUE(sh.prepare(translucent, Affine::translate({2, 1}), 1, true, false));
    EXPECT_FALSE(sh.store_opaque(0, 0, 4, out)) << "no 8-bit copy";
}

// Where a scaled (level, tabulated) opaque image is drawn at opacity 1,
// spans of coverage 1 on an 8-bit canvas store its quantized samples: the
// canvas comes out as the composite of each pixel's sample (from a shader
// that samples each pixel alone), byte for byte, over a translucent
// background, scaled up, down and mirrored, tiled and padded. A translucent
// pixel in the image rows a span samples, or an opacity below 1, and
// nothing is stored, and the span composites as before.
TEST(ImageShader, LevelOpaqueImagesStoreTheBytesTheirCompositeGives) {
    RasterImage im = random_image(11, 9, 59);
    for (Premul& p : im.pixels) p = {p.r, p.g, p.b, 1.0f};
    RasterImage one_translucent = im; // its row 5 at half alpha
    for (int i = 5 * 11; i < 6 * 11; ++i) {
        Premul& p = one_translucent.pixels[std::size_t(i)];
        p = {p.r * 0.5f, p.g * 0.5f, p.b * 0.5f, 0.5f};
    }
    const Affine maps[] = {
        Affine::translate({3.3, -2.1}) * Affine::scale(2.7, 1.9),
        Affine::translate({40.5, 30.25}) * Affine::scale(-1.5, -3.25),
        Affine::translate({1, 2}) * Affine::scale(0.37, 5),
        Affine::translate({0.5, 0.5}),
    };
    const Premul bg{0.1f, 0.3f, 0.2f, 0.5f};
    testing::Rng rng(61);
    for (const RasterImage* image : {&im, &one_translucent})
        for (const Affine& m : maps)
            for (const bool repeat : {false, true})
                for (const float opacity : {1.0f, 0.75f}) {
                    ImageShader plain, tabulated;
                    ASSERT_TRUE(plain.prepare(*image, m, opacity, true, repeat));
                    ASSERT_TRUE(tabulated.prepare(*image, m, opacity, true, repeat));
                    tabulated.tabulate(-40, 80);
                    int stored = 0;
                    for (int y = -12; y < 40; ++y) {
                        const int x = rng.integer(-40, 40), n = rng.integer(1, 40);
                        // The canvas: columns [-40, 80) of row y.
                        Canvas8 canvas(120, 1, -40, y), expected(120, 1, -40, y);
                        canvas.fill(bg);
                        expected.fill(bg);
                        ImageSpanPainter<Premul8> painter(canvas, tabulated);
                        std::vector<Premul8> bytes(static_cast<std::size_t>(n));
                        stored += tabulated.store_opaque(x, y, n, bytes.data());
                        painter.span({y, x, n, nullptr, 1.0f});
                        for (int i = 0; i < n; ++i)
                            blend_over(expected.row(0)[x + i + 40], plain.at(x + i, y), 1);
                        for (int i = 0; i < 120; ++i)
                            ASSERT_EQ(canvas.row(0)[i], expected.row(0)[i])
                                << (repeat ? "repeat" : "pad") << " opacity " << opacity
                                << " map e " << m.e << " row " << where(x, y) << " n " << n
                                << " column " << i - 40;
                    }
                    // 52 rows: the device rows beside image row 5 sample
                    // a translucent row, the others only opaque ones.
                    if (opacity < 1) {
                        EXPECT_EQ(stored, 0) << "opacity " << opacity;
                    } else if (image == &im) {
                        EXPECT_EQ(stored, 52) << "every span of an opaque image";
                    } else {
                        EXPECT_TRUE(stored > 0 && stored < 52) << stored << " map e " << m.e;
                    }
                }
}

// The image rows kept for the next span know whether the columns added on
// either side are opaque: one translucent pixel reached by extending the
// columns held, left or right, and the span is composited, not stored.
TEST(ImageShader, KeptRowsGrownOverATranslucentPixelAreNotStored) {
    RasterImage im = random_image(11, 9, 67);
    for (Premul& p : im.pixels) p = {p.r, p.g, p.b, 1.0f};
    im.pixels[5 * 11 + 4] = {0.2f, 0.1f, 0.1f, 0.5f}; // column 4, row 5
    // Scaled by 3: device columns 12 to 14 lie on image column 4, and
    // device row 16 samples image rows 4 and 5.
    const Affine m = Affine::scale(3);
    const auto check = [&](const std::pair<int, int>& first, const std::pair<int, int>& second) {
        ImageShader plain, sh;
        ASSERT_TRUE(plain.prepare(im, m, 1, true, false));
        ASSERT_TRUE(sh.prepare(im, m, 1, true, false));
        sh.tabulate(0, 60);
        std::vector<Premul8> bytes(60);
        EXPECT_TRUE(sh.store_opaque(first.first, 16, first.second - first.first, bytes.data()))
            << "columns " << first.first << ".." << first.second;
        EXPECT_FALSE(sh.store_opaque(second.first, 16, second.second - second.first, bytes.data()))
            << "columns " << second.first << ".." << second.second;
        Canvas8 canvas(60, 1, 0, 16), expected(60, 1, 0, 16);
        canvas.fill({0.1f, 0.3f, 0.2f, 0.5f});
        expected.fill({0.1f, 0.3f, 0.2f, 0.5f});
        ImageSpanPainter<Premul8>(canvas, sh)
            .span({16, second.first, second.second - second.first, nullptr, 1.0f});
        for (int x = second.first; x < second.second; ++x)
            blend_over(expected.row(0)[x], plain.at(x, 16), 1);
        for (int x = 0; x < 60; ++x)
            EXPECT_EQ(canvas.row(0)[x], expected.row(0)[x]) << "column " << x;
    };
    check({30, 40}, {5, 35});  // grown to the left
    check({0, 10}, {0, 20});   // grown to the right
    check({30, 40}, {10, 16}); // apart from the columns held
}

TEST(ImageShader, TabulatedColumnsShadeTheSameBits) {
    // A map that keeps rows level and columns upright: each column's
    // horizontal half of the sample, tabulated once, and each image row
    // sampled along the columns, kept for the next device row, give every
    // row exactly what computing it per pixel gives; rows reaching past the
    // table, and a map of another kind, are computed as before. Scaled up,
    // down and mirrored.
    const RasterImage im = random_image(11, 9, 29);
    const Affine maps[] = {
        Affine::translate({3.3, -2.1}) * Affine::scale(2.7, 1.9),
        Affine::translate({40.5, 30.25}) * Affine::scale(-1.5, -3.25),
        Affine::translate({1, 2}) * Affine::scale(0.37, 5),
        Affine::translate({-2.5, 7.25}) * Affine::scale(4, 0.3),
        Affine::translate({0.5, 0.5}),
        Affine::translate({5, 5}) * Affine::rotate(0.7) * Affine::scale(2.2), // not tabulated
        Affine::translate({-3, 5}),                                           // copied
    };
    testing::Rng rng(31);
    for (const Affine& m : maps)
        for (const bool repeat : {false, true}) {
            ImageShader plain, tabulated;
            ASSERT_TRUE(plain.prepare(im, m, 0.75f, true, repeat));
            ASSERT_TRUE(tabulated.prepare(im, m, 0.75f, true, repeat));
            tabulated.tabulate(-20, 70);
            for (int trial = 0; trial < 40; ++trial) {
                const int x = rng.integer(-40, 80), y = rng.integer(-60, 60);
                const int n = rng.integer(1, 90);
                std::vector<Premul> a(static_cast<std::size_t>(n)), b(a);
                plain.shade(x, y, n, a.data());
                tabulated.shade(x, y, n, b.data());
                for (int i = 0; i < n; ++i) {
                    const Premul &p = a[std::size_t(i)], &q = b[std::size_t(i)];
                    EXPECT_TRUE(p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a)
                        << (repeat ? "repeat " : "pad ") << where(x + i, y) << " map e " << m.e;
                }
            }
            // Rows in order, as a shape's spans come (each image row sampled
            // along the columns is kept for the next device row): chunks to
            // the left of, across, inside and right of the columns already
            // sampled, and apart from them.
            for (int y = -12; y < 50; ++y) {
                const int a = rng.integer(-20, 60), b = rng.integer(a, 70);
                const std::pair<int, int> chunks[] = {
                    {a, b}, {a - 5, b + 3}, {a + 2, a + 4}, {b, b + 6}, {-20, -18}};
                for (const auto& [x0, x1] : chunks) {
                    const int n = x1 - x0;
                    if (n <= 0) continue;
                    std::vector<Premul> p(static_cast<std::size_t>(n)), q(p);
                    plain.shade(x0, y, n, p.data());
                    tabulated.shade(x0, y, n, q.data());
                    for (int i = 0; i < n; ++i)
                        EXPECT_TRUE(same(p[std::size_t(i)], q[std::size_t(i)]))
                            << (repeat ? "repeat " : "pad ") << where(x0 + i, y) << " of chunk "
                            << x0 << ".." << x1 << " map e " << m.e;
                }
            }
            // prepare() drops the table: another map shades as its own.
            ASSERT_TRUE(tabulated.prepare(im, maps[0], 1, true, repeat));
            ASSERT_TRUE(plain.prepare(im, maps[0], 1, true, repeat));
            const Premul p = plain.at(10, 10), q = tabulated.at(10, 10);
            EXPECT_TRUE(p.r == q.r && p.a == q.a);
        }
}

// Turned maps shade a row's pixels two at a time where the CPU has SSE2
// (padded, bilinear), and the last odd one alone: every pixel of a row gets
// the bits that shading it alone (at()) gives, in every mode, with points
// far outside the image and one whose image x is NaN (the first column).
TEST(ImageShader, TurnedRowsShadeAsEachPixelAlone) {
    const RasterImage im = random_image(9, 7, 13);
    const Affine maps[] = {
        Affine::translate({5, 5}) * Affine::rotate(0.7) * Affine::scale(2.2),
        Affine::translate({-20.5, 3.25}) * Affine::rotate(-2.9) * Affine::scale(0.4, 3),
        Affine{1, 0.5, 0, 1, 2, 2}, // a skew
        Affine::rotate(1) * Affine::scale(1e-5) * Affine::translate({1e303, 1e303}),
        {2e-300, -1e-300, -1, 1, 0, 0}, // at (7e8, -7e8) the image x is inf - inf: NaN
    };
    testing::Rng rng(53);
    for (const Affine& m : maps)
        for (const auto& [smooth, repeat] : kModes) {
            ImageShader sh;
            ASSERT_TRUE(sh.prepare(im, m, 0.9f, smooth, repeat));
            for (const int n : {2, 3, 64, 65, 200}) {
                const bool far = m.a < 1e-200;
                const int x = far ? 700000000 : rng.integer(-60, 60);
                const int y = far ? -700000000 : rng.integer(-60, 60);
                std::vector<Premul> row(static_cast<std::size_t>(n));
                sh.shade(x, y, n, row.data());
                for (int i = 0; i < n; ++i)
                    EXPECT_TRUE(same(row[std::size_t(i)], sh.at(x + i, y)))
                        << (smooth ? "bilinear" : "nearest") << (repeat ? ", repeat " : ", pad ")
                        << where(x + i, y) << " map b " << m.b;
            }
        }
}

bool in_unit_range(const Premul& p) {
    const auto ok = [](float v) { return v >= 0 && v <= 1; };
    return ok(p.r) && ok(p.g) && ok(p.b) && ok(p.a);
}

TEST(ImageShader, HugeAndNonFiniteCoordinatesGiveValidPixels) {
    const RasterImage im = random_image(3, 2, 8);
    const Affine maps[] = {
        Affine::translate({1e300, -1e300}),
        Affine::translate({-1.7e308, 1.7e308}),
        {1e-5, 0, 0, 1e-5, 1e300, 0},      // inverse translation -1e305
        {1e-5, 0, 0, 1e-5, 1e305, -1e305}, // inverse translation overflows to inf
        Affine::rotate(1) * Affine::scale(1e-5) * Affine::translate({1e303, 1e303}),
    };
    const int coords[] = {0, 1, -1, INT_MAX, INT_MIN, INT_MAX / 3};
    for (const Affine& m : maps)
        for (const auto& [smooth, repeat] : kModes) {
            ImageShader sh;
            if (!sh.prepare(im, m, 1, smooth, repeat)) continue;
            for (int x : coords)
                for (int y : coords) EXPECT_TRUE(in_unit_range(sh.at(x, y))) << m.e << " " << x;
        }
}

template <class Pixel>
void check_span_painting() {
    const RasterImage im = random_image(6, 4, 9);
    ImageShader sh;
    ASSERT_TRUE(
        sh.prepare(im, Affine::translate({2.25, 1.5}) * Affine::rotate(0.3) * Affine::scale(1.9),
                   0.8f, true, true));
    // A canvas placed at (3, 2) of the frame, over a background color.
    const Premul bg{0.1f, 0.2f, 0.05f, 0.4f};
    BasicCanvas<Pixel> canvas(20, 6, 3, 2), expected(20, 6, 3, 2);
    canvas.fill(bg);
    expected.fill(bg);
    ImageSpanPainter<Pixel> painter(canvas, sh);
    std::vector<float> coverage(12);
    for (std::size_t i = 0; i < coverage.size(); ++i) coverage[i] = float(i) / 11;
    const Span spans[] = {
        {2, 4, 12, coverage.data(), 0}, {3, 3, 20, nullptr, 1.0f}, {5, 10, 7, nullptr, 0.5f}};
    for (const Span& s : spans) {
        painter.span(s);
        Pixel* row = expected.row(s.y - 2);
        for (int i = 0; i < s.len; ++i) blend_over(row[s.x + i - 3], sh.at(s.x + i, s.y), s.at(i));
    }
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 20; ++x)
            EXPECT_TRUE(same(to_premul(canvas.row(y)[x]), to_premul(expected.row(y)[x])))
                << "(" << x << ", " << y << ")";
}

TEST(ImageShader, SpanPaintingEqualsAtPerPixel) {
    check_span_painting<Premul>();
    check_span_painting<Premul8>();
}

} // namespace
} // namespace casteljau
