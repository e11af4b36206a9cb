// Image textures (render3d/texture.h): PNG, JPEG and WebP by the library's
// decoders, the same linear texels OpenImageIO's reading gave (premultiplied
// sRGB values to linear), the size limits, and errors that name the file.
#include "casteljau/io/image_write.h"
#include "casteljau/render3d/texture.h"
#include "image_files.h"

#include <cmath>
#include <gtest/gtest.h>
#include <string>
#include <vector>

namespace casteljau {
namespace {

using testing::TempDir;

float linear(float srgb) {
    return srgb <= 0.04045f ? srgb / 12.92f : std::pow((srgb + 0.055f) / 1.055f, 2.4f);
}

TEST(Texture, PngTexelsAreTheImagesPremultipliedColorsInLinearLight) {
    TempDir dir;
    // Two pixels: opaque orange, and blue at half alpha (premultiplied, as
    // OpenImageIO gave textures: 0.5 of its blue).
    const std::vector<std::uint8_t> rgba = {255, 128, 0, 255, 0, 0, 255, 128};
    const std::string path = dir / "t.png";
    ASSERT_EQ(write_image_atomic(path, {.width = 2, .height = 1, .rgba8 = rgba}), "");
    Texture t;
    ASSERT_EQ(t.load(path), "");
    // Pixel centres: s = 1/4 and 3/4 (the texture repeats, so the bilinear
    // lookup at a centre is that pixel alone).
    const Rgb a = t.at({0.25, 0.5}, {0, 0}), b = t.at({0.75, 0.5}, {0, 0});
    EXPECT_NEAR(a.r, 1.0f, 1e-6f);
    EXPECT_NEAR(a.g, linear(128 / 255.0f), 1e-6f);
    EXPECT_NEAR(a.b, 0.0f, 1e-6f);
    EXPECT_NEAR(b.r, 0.0f, 1e-6f);
    EXPECT_NEAR(b.b, linear(128 / 255.0f), 1e-6f);
}

TEST(Texture, JpegLoadsAndLimitsAndErrorsNameTheFile) {
    TempDir dir;
    const std::string jpeg = dir / "t.jpg";
    const std::vector<std::uint8_t> gray(16 * 16 * 4, 200);
    ASSERT_EQ(write_image_atomic(jpeg, {.width = 16, .height = 16, .rgba8 = gray}), "");
    Texture t;
    ASSERT_EQ(t.load(jpeg), "");
    EXPECT_NEAR(t.at({0.5, 0.5}, {0, 0}).g, linear(200 / 255.0f), 0.01f);
    // One pixel wider than the limit, one row high: refused, by size.
    const std::string wide = dir / "wide.png";
    const std::vector<std::uint8_t> row(std::size_t(Texture::kMaxTextureSide + 1) * 4, 255);
    ASSERT_EQ(write_image_atomic(
                  wide, {.width = Texture::kMaxTextureSide + 1, .height = 1, .rgba8 = row}),
              "");
    const std::string e = Texture().load(wide);
    EXPECT_NE(e.find("wide.png: texture size 16385 x 1"), std::string::npos) << e;
    const std::string missing = Texture().load(dir / "none.png");
    EXPECT_NE(missing.find("none.png"), std::string::npos) << missing;
}

} // namespace
} // namespace casteljau
