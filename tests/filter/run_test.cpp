// Filter graphs run: inputs by index, standard inputs, color spaces
// converted at the right points, subregions, errors and limits, and a
// window cut by the graph's reach giving the whole window's pixels.
#include "casteljau/filter/color_space.h"
#include "casteljau/filter/run.h"
#include "filter_images.h"

#include <gtest/gtest.h>
#include <random>

namespace casteljau {
namespace {

FilterImage source(int w, int h, unsigned seed) {
    std::mt19937 rng(seed);
    return testing::random_filter_image(rng, {0, 0, w, h}, 0.4f);
}

FilterPrimitive prim(FilterOp op, std::vector<int> in, Rect sub, bool linear = true) {
    return {std::move(op), std::move(in), sub, linear};
}

TEST(FilterRun, AFloodInLinearLightComesBackAsItsSrgbColor) {
    FilterGraph g{{0, 0, 4, 4}, {prim(Flood{{0.5f, 0.25f, 1, 1}}, {}, {0, 0, 4, 4})}};
    FilterImage img = source(4, 4, 1);
    ASSERT_TRUE(run_filter(g, Affine::identity(), {&img}));
    EXPECT_FALSE(img.linear);
    EXPECT_NEAR(img.at(2, 2).r, 0.5f, 1e-4);
    EXPECT_NEAR(img.at(2, 2).g, 0.25f, 1e-4);
}

TEST(FilterRun, AMatrixActsInItsPrimitivesSpace) {
    // Halving red in linear light is not halving it in sRGB.
    ColorMatrix half;
    half.m[0] = 0.5f;
    for (bool linear : {false, true}) {
        FilterGraph g{{0, 0, 1, 1},
                      {prim(half, {filter_input::kSourceGraphic}, {0, 0, 1, 1}, linear)}};
        FilterImage img;
        img.reset({0, 0, 1, 1}, false);
        img.at(0, 0) = {0.8f, 0, 0, 1};
        ASSERT_TRUE(run_filter(g, Affine::identity(), {&img}));
        const float want = linear ? linear_to_srgb(0.5f * srgb_to_linear(0.8f)) : 0.4f;
        EXPECT_NEAR(img.at(0, 0).r, want, 1e-4) << "linear " << linear;
    }
}

TEST(FilterRun, ResultsAndStandardInputs) {
    // 0: SourceAlpha offset; 1: flood; 2: flood in result 0 (a shadow); 3: source over it.
    FilterGraph g{{0, 0, 10, 10},
                  {prim(Offset{2, 0}, {filter_input::kSourceAlpha}, {0, 0, 10, 10}),
                   prim(Flood{{0, 0, 1, 1}}, {}, {0, 0, 10, 10}),
                   prim(Composite{Composite::Op::In}, {1, 0}, {0, 0, 10, 10}),
                   prim(Merge{}, {2, filter_input::kSourceGraphic}, {0, 0, 10, 10})}};
    FilterImage img;
    img.reset({0, 0, 10, 10}, false);
    img.at(3, 3) = {1, 0, 0, 1};
    ASSERT_TRUE(run_filter(g, Affine::identity(), {&img}));
    EXPECT_NEAR(img.at(3, 3).r, 1, 1e-5) << "the source on top";
    EXPECT_NEAR(img.at(5, 3).b, 1, 1e-5) << "its shadow 2 px right, blue";
    EXPECT_EQ(img.at(4, 3).a, 0.0f);
}

TEST(FilterRun, SubregionsCutResults) {
    FilterGraph g{{0, 0, 10, 10}, {prim(Flood{{1, 1, 1, 1}}, {}, {2, 3, 5, 7})}};
    FilterImage img = source(10, 10, 2);
    ASSERT_TRUE(run_filter(g, Affine::scale(1, 1), {&img}));
    for (int y = 0; y < 10; ++y)
        for (int x = 0; x < 10; ++x)
            ASSERT_EQ(img.at(x, y).a, (x >= 2 && x < 5 && y >= 3 && y < 7) ? 1.0f : 0.0f)
                << x << "," << y;
}

TEST(FilterRun, ParametersScaleWithTheTransform) {
    // An offset of 2 user units at scale 3 moves 6 device px.
    FilterGraph g{{0, 0, 10, 10},
                  {prim(Offset{2, 0}, {filter_input::kSourceGraphic}, {0, 0, 10, 10})}};
    FilterImage img;
    img.reset({0, 0, 30, 30}, false);
    img.at(3, 3) = {0, 0, 0, 1};
    ASSERT_TRUE(run_filter(g, Affine::scale(3, 3), {&img}));
    EXPECT_EQ(img.at(9, 3).a, 1.0f);
}

TEST(FilterRun, ErrorsDrawNothing) {
    FilterImage img = source(4, 4, 3);
    EXPECT_FALSE(run_filter(FilterGraph{{0, 0, 4, 4}, {}}, Affine::identity(), {&img}))
        << "no primitives";
    for (const Premul& p : img.px) ASSERT_EQ(p.a, 0.0f);
    img = source(4, 4, 3);
    FilterGraph forward{{0, 0, 4, 4}, {prim(Offset{}, {1}, {0, 0, 4, 4})}};
    EXPECT_FALSE(run_filter(forward, Affine::identity(), {&img})) << "an input not before it";
    FilterGraph big{{0, 0, 4, 4}, {}};
    big.primitives.assign(kMaxFilterPrimitives + 1, prim(Flood{}, {}, {0, 0, 4, 4}));
    EXPECT_FALSE(run_filter(big, Affine::identity(), {&img})) << "over the primitive limit";
}

TEST(FilterRun, ACutWindowGivesTheWholeWindowsPixels) {
    // Blur, morphology, offset, convolution and lighting chained: a window
    // grown by filter_reach around some rows gives exactly those rows.
    Lighting light;
    light.light = DistantLight{30, 40};
    Convolve conv;
    conv.m.kernel = {0, 1, 0, 1, -4, 1, 0, 1, 0};
    conv.m.divisor = 1;
    conv.m.edge = EdgeMode::None;
    const Rect all{0, 0, 40, 80};
    const FilterGraph g{
        all,
        {prim(GaussianBlur{2.5, 1.5}, {filter_input::kSourceGraphic}, all),
         prim(Morphology{true, 2, 1}, {0}, all), prim(Offset{3, -2}, {1}, all),
         prim(conv, {2}, all), prim(LightingOp{light}, {3}, all),
         prim(Composite{Composite::Op::Arithmetic, 0.5f, 0.5f, 0.5f, 0}, {4, 2}, all)}};
    const FilterImage in = source(40, 80, 4);
    FilterImage whole = in;
    ASSERT_TRUE(run_filter(g, Affine::identity(), {&whole}));
    const int reach = int(std::ceil(filter_reach(g, Affine::identity())));
    const int y0 = 35, y1 = 45;
    FilterImage part;
    part.reset({0, y0 - reach, 40, y1 + reach}, false);
    for (int y = part.box.y0; y < part.box.y1; ++y)
        for (int x = 0; x < 40; ++x) part.at(x, y - part.box.y0) = in.at(x, y);
    ASSERT_TRUE(run_filter(g, Affine::identity(), {&part}));
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < 40; ++x) {
            const Premul a = whole.at(x, y), b = part.at(x, y - part.box.y0);
            ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a) << x << "," << y;
        }
}

// Sixteen offsets of the source, merged: the result reads the source as
// far as the longest shift, not as far as all shifts added up (which made
// the renderer's windows three times a band's height, and their memory).
TEST(FilterRun, ParallelOffsetsReachAsFarAsTheLongest) {
    const Rect all{0, 0, 60, 40};
    FilterGraph g{all, {}};
    std::vector<int> layers;
    for (int i = 0; i < 16; ++i) {
        g.primitives.push_back(prim(Offset{double(i), 0}, {filter_input::kSourceGraphic}, all));
        layers.push_back(i);
    }
    g.primitives.push_back(prim(Merge{}, layers, all));
    EXPECT_EQ(filter_reach(g, Affine::identity()), 16.0) << "15 px and a pixel of rounding";
    EXPECT_EQ(filter_reach(g, Affine::scale(2, 2)), 31.0);
    const FilterImage in = source(60, 40, 5);
    FilterImage whole = in;
    ASSERT_TRUE(run_filter(g, Affine::identity(), {&whole}));
    const int x0 = 30, x1 = 34, reach = 16;
    FilterImage part;
    part.reset({x0 - reach, 0, x1 + reach, 40}, false);
    for (int y = 0; y < 40; ++y)
        for (int x = part.box.x0; x < part.box.x1; ++x) part.at(x - part.box.x0, y) = in.at(x, y);
    ASSERT_TRUE(run_filter(g, Affine::identity(), {&part}));
    for (int y = 0; y < 40; ++y)
        for (int x = x0; x < x1; ++x) {
            const Premul a = whole.at(x, y), b = part.at(x - part.box.x0, y);
            ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a) << x << "," << y;
        }
}

// Under skew an offset moves rows by the matrix's row, not by its length
// times a column norm: matrix(0.5 1 -0.5 1 0 0) takes (70.7, 70.7) 141
// rows down, which the reach put at 113, so a band's window missed the
// source rows the shift brings in.
TEST(FilterRun, ASkewedOffsetReachesAsFarAsItMoves) {
    const Affine skew{0.5, 1, -0.5, 1, 0, 0};
    const Rect all{-400, -400, 800, 800};
    const FilterGraph g{all, {prim(Offset{70.7, 70.7}, {filter_input::kSourceGraphic}, all)}};
    const int reach = int(std::ceil(filter_reach(g, skew)));
    EXPECT_GE(reach, 141);
    const FilterImage in = source(20, 400, 6);
    FilterImage whole = in;
    ASSERT_TRUE(run_filter(g, skew, {&whole}));
    const int y0 = 200, y1 = 210;
    FilterImage part;
    part.reset({0, y0 - reach, 20, y1 + reach}, false);
    for (int y = part.box.y0; y < part.box.y1; ++y)
        for (int x = 0; x < 20; ++x) part.at(x, y - part.box.y0) = in.at(x, y);
    ASSERT_TRUE(run_filter(g, skew, {&part}));
    for (int y = y0; y < y1; ++y)
        for (int x = 0; x < 20; ++x) {
            const Premul a = whole.at(x, y), b = part.at(x, y - part.box.y0);
            ASSERT_TRUE(a.r == b.r && a.g == b.g && a.b == b.b && a.a == b.a) << x << "," << y;
        }
}

} // namespace
} // namespace casteljau
