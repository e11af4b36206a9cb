// Color spaces, feColorMatrix and feComponentTransfer: the sRGB curve's
// tables against the exact curve, round trips, and each matrix and
// transfer function against its formula on straight colors.
#include "casteljau/filter/color_space.h"
#include "casteljau/filter/color_transform.h"

#include <cmath>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

FilterImage one_pixel(Premul p, bool linear = false) {
    FilterImage img;
    img.reset({0, 0, 1, 1}, linear);
    img.at(0, 0) = p;
    return img;
}

constexpr Subregion kAll{0, 0, 1, 1};

TEST(ColorSpace, TablesFollowTheExactCurveWithin2e5) {
    for (int i = 0; i <= 1000; ++i) {
        const float v = float(i) / 1000;
        FilterImage img = one_pixel({v, v, v, 1});
        convert_space(img, true);
        ASSERT_NEAR(img.at(0, 0).r, srgb_to_linear(v), 2e-5) << v;
        convert_space(img, false);
        ASSERT_NEAR(img.at(0, 0).r, v, 4e-5) << "round trip " << v;
    }
}

TEST(ColorSpace, ConvertsStraightColorsAndKeepsAlpha) {
    FilterImage img = one_pixel({0.25f, 0.1f, 0, 0.5f});
    convert_space(img, true);
    EXPECT_NEAR(img.at(0, 0).r, srgb_to_linear(0.5f) * 0.5f, 2e-5);
    EXPECT_EQ(img.at(0, 0).a, 0.5f);
    EXPECT_TRUE(img.linear);
}

TEST(ColorMatrix, IdentityAndOffsets) {
    const FilterImage in = one_pixel({0.2f, 0.1f, 0.05f, 0.4f});
    FilterImage out = one_pixel({});
    color_matrix(in, out, kAll, ColorMatrix{});
    EXPECT_NEAR(out.at(0, 0).r, 0.2f, 1e-6);
    EXPECT_NEAR(out.at(0, 0).a, 0.4f, 1e-6);
    // A matrix may make a transparent pixel opaque: alpha' = 1.
    ColorMatrix m;
    m.m[18] = 0, m.m[19] = 1, m.m[4] = 1; // R' = R + 1 (clamped), A' = 1
    const FilterImage clear = one_pixel({});
    color_matrix(clear, out, kAll, m);
    EXPECT_EQ(out.at(0, 0).a, 1.0f);
    EXPECT_EQ(out.at(0, 0).r, 1.0f);
}

TEST(ColorMatrix, ShorthandsFollowTheSpec) {
    const FilterImage red = one_pixel({1, 0, 0, 1});
    FilterImage out = one_pixel({});
    color_matrix(red, out, kAll, saturate_matrix(0));
    EXPECT_NEAR(out.at(0, 0).r, 0.213f, 1e-6) << "saturate(0): the luminance";
    EXPECT_NEAR(out.at(0, 0).g, 0.213f, 1e-6);
    color_matrix(red, out, kAll, hue_rotate_matrix(0));
    EXPECT_NEAR(out.at(0, 0).r, 1.0f, 1e-6);
    EXPECT_NEAR(out.at(0, 0).g, 0.0f, 1e-6);
    color_matrix(red, out, kAll, hue_rotate_matrix(360));
    EXPECT_NEAR(out.at(0, 0).r, 1.0f, 1e-5);
    color_matrix(one_pixel({0.5f, 0.5f, 0.5f, 0.5f}), out, kAll, luminance_to_alpha_matrix());
    EXPECT_NEAR(out.at(0, 0).a, 0.2125f + 0.7154f + 0.0721f, 1e-5) << "straight white";
    EXPECT_EQ(out.at(0, 0).r, 0.0f);
}

TEST(ComponentTransfer, EachFunctionType) {
    using T = TransferFunction::Type;
    const FilterImage in = one_pixel({0.3f, 0.6f, 0.9f, 1});
    FilterImage out = one_pixel({});
    ComponentTransfer t;
    t.f[0] = {T::Table, {0, 1}};
    t.f[1] = {T::Discrete, {0.2f, 0.4f, 0.8f}};
    t.f[2].type = T::Gamma;
    t.f[2].amplitude = 0.5f, t.f[2].exponent = 2, t.f[2].offset = 0.1f;
    t.f[3].type = T::Linear;
    t.f[3].slope = 0.5f, t.f[3].intercept = 0.1f;
    component_transfer(in, out, kAll, t);
    const float a = 0.6f; // 0.5 * 1 + 0.1
    EXPECT_NEAR(out.at(0, 0).a, a, 1e-6);
    EXPECT_NEAR(out.at(0, 0).r, 0.3f * a, 1e-6) << "table [0 1]: identity";
    EXPECT_NEAR(out.at(0, 0).g, 0.4f * a, 1e-6) << "discrete: floor(0.6 * 3) = 1";
    EXPECT_NEAR(out.at(0, 0).b, (0.5f * 0.81f + 0.1f) * a, 1e-5) << "gamma";
}

TEST(ComponentTransfer, TablesInterpolateAndClamp) {
    using T = TransferFunction::Type;
    FilterImage out = one_pixel({});
    ComponentTransfer t;
    t.f[0] = {T::Table, {0, 0.5f, 2}}; // two segments: [0, .5], [.5, 2]
    t.f[1] = {T::Table, {}};           // empty: identity
    component_transfer(one_pixel({0.75f, 0.25f, 0, 1}), out, kAll, t);
    EXPECT_EQ(out.at(0, 0).r, 1.0f) << "1.25 clamped";
    EXPECT_NEAR(out.at(0, 0).g, 0.25f, 1e-6);
}

} // namespace
} // namespace casteljau
