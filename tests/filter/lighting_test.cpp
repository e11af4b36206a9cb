// feDiffuseLighting and feSpecularLighting: a flat surface under a light
// straight above gives kd * color; a linear alpha ramp gives, at every pixel
// (edges and corners included), the normal the spec's kernels give; a single
// raised pixel checks the corner and edge kernels' factors by hand; point
// lights use device coordinates; a spot light's cone cuts the light off
// outside its angle and its exponent dims it inside; specular alpha is the
// maximum channel; clamping; only the subregion is written.
#include "casteljau/filter/lighting.h"

#include <algorithm>
#include <cmath>
#include <gtest/gtest.h>

namespace casteljau {
namespace {

FilterImage constant_alpha(PixelRect box, float a) {
    FilterImage img;
    img.reset(box, false);
    for (Premul& p : img.px) p = {0, 0, 0, a};
    return img;
}

FilterImage run(const FilterImage& in, const Lighting& l) {
    FilterImage out;
    out.reset(in.box, in.linear);
    lighting(in, out, {0, 0, in.width(), in.height()}, l);
    return out;
}

Lighting diffuse(LightSource light, double kd = 1, Premul color = {1, 1, 1, 1}) {
    Lighting l;
    l.constant = kd;
    l.color = color;
    l.light = light;
    return l;
}

TEST(Lighting, FlatSurfaceLitFromAbove) {
    const FilterImage in = constant_alpha({-3, 5, 9, 12}, 0.6f);
    const FilterImage out = run(in, diffuse(DistantLight{30, 90}, 0.8, {1, 0.5f, 0.25f, 1}));
    for (const Premul& p : out.px) {
        EXPECT_NEAR(p.r, 0.8, 1e-6);
        EXPECT_NEAR(p.g, 0.4, 1e-6);
        EXPECT_NEAR(p.b, 0.2, 1e-6);
        EXPECT_EQ(p.a, 1.0f);
    }
    // A strong kd clamps to 1; a light from below lights nothing.
    for (const Premul& p : run(in, diffuse(DistantLight{0, 90}, 3)).px) EXPECT_EQ(p.r, 1.0f);
    for (const Premul& p : run(in, diffuse(DistantLight{0, -90}, 1)).px) EXPECT_EQ(p.g, 0.0f);
}

// A(x, y) = 0.05 x + 0.02 y. Every kernel variant gives twice the slope:
// in x, interior FACTOR 1/4 times rows weighted 1 + 2 + 1 of the central
// difference 2 * 0.05 is 0.1; left column 1/2 times 4 one-sided differences
// of 0.05 is 0.1; top row 1/3 times 3 central ones, corner 2/3 times 3
// one-sided ones, likewise. So with surfaceScale 2, at every pixel,
//   N = (-2 * 0.1, -2 * 0.04, 1) / |.| = (-0.2, -0.08, 1) / sqrt(1.0464).
TEST(Lighting, LinearRampNormalsEverywhere) {
    FilterImage in;
    in.reset({0, 0, 10, 8}, false);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 10; ++x) in.at(x, y) = {0, 0, 0, 0.05f * float(x) + 0.02f * float(y)};
    const double norm = std::sqrt(0.2 * 0.2 + 0.08 * 0.08 + 1);
    struct Case {
        double azimuth, elevation, want; // want = N.L
    };
    // L = (-1, 0, 0), (0, -1, 0), (0, 0, 1).
    for (const Case c :
         {Case{180, 0, 0.2 / norm}, Case{270, 0, 0.08 / norm}, Case{0, 90, 1 / norm}}) {
        Lighting l = diffuse(DistantLight{c.azimuth, c.elevation});
        l.surface_scale = 2;
        const FilterImage out = run(in, l);
        for (int y = 0; y < 8; ++y)
            for (int x = 0; x < 10; ++x)
                ASSERT_NEAR(out.at(x, y).r, c.want, 2e-6)
                    << "azimuth " << c.azimuth << " elevation " << c.elevation << " at " << x << ","
                    << y;
    }
}

// A 3 x 3 window with alpha 1 at the top-left pixel only, surfaceScale 1.
// Top-left corner: K_x . A = -2, FACTOR_x = 2/3, so N_x = 4/3; likewise
// N_y = 4/3. Top row, middle pixel: K_x . A = -2 (weight 2 at the left of
// the centre row), FACTOR_x = 1/3: N_x = 2/3; K_y . A = -1, FACTOR_y = 1/2:
// N_y = 1/2. Left column, middle pixel: N_x = 1/2, N_y = 2/3. Interior
// centre: K_x . A = -1, FACTOR 1/4: N = (1/4, 1/4, 1).
TEST(Lighting, EdgeAndCornerKernels) {
    FilterImage in = constant_alpha({0, 0, 3, 3}, 0);
    in.at(0, 0).a = 1;
    struct Case {
        int x, y;
        double nx, ny;
    };
    const Case cases[] = {{0, 0, 4.0 / 3, 4.0 / 3}, {1, 0, 2.0 / 3, 0.5}, {0, 1, 0.5, 2.0 / 3},
                          {1, 1, 0.25, 0.25},       {2, 2, 0, 0},         {2, 0, 0, 0}};
    const FilterImage ox = run(in, diffuse(DistantLight{0, 0}));  // L = (1, 0, 0)
    const FilterImage oy = run(in, diffuse(DistantLight{90, 0})); // L = (0, 1, 0)
    const FilterImage oz = run(in, diffuse(DistantLight{0, 90})); // L = (0, 0, 1)
    for (const Case& c : cases) {
        const double norm = std::sqrt(c.nx * c.nx + c.ny * c.ny + 1);
        EXPECT_NEAR(ox.at(c.x, c.y).r, c.nx / norm, 1e-6) << c.x << "," << c.y;
        EXPECT_NEAR(oy.at(c.x, c.y).r, c.ny / norm, 1e-6) << c.x << "," << c.y;
        EXPECT_NEAR(oz.at(c.x, c.y).r, 1 / norm, 1e-6) << c.x << "," << c.y;
    }
}

// A point light's position is in device px: the pixel at device (107, 52)
// right below it gets N.L = 1; the one 30 px left of it 20 / sqrt(30^2 + 20^2)
// (surface height 0.5 * 2 = 1 below a light at z = 21).
TEST(Lighting, PointLightInDeviceCoordinates) {
    const FilterImage in = constant_alpha({100, 50, 140, 60}, 0.5f);
    Lighting l = diffuse(PointLight{107, 52, 21});
    l.surface_scale = 2;
    const FilterImage out = run(in, l);
    EXPECT_NEAR(out.at(7, 2).r, 1.0, 1e-6);
    EXPECT_NEAR(out.at(37, 2).r, 20 / std::sqrt(30.0 * 30 + 20 * 20), 1e-6);
}

// A spot light 50 px above (32, 32) pointing straight down with a 20 degree
// cone: pixels within 50 tan(20) = 18.2 px are lit, with
// N.L * pow(-L.S, 3) = c^4 for c = 50 / distance to the light; farther ones
// are dark.
TEST(Lighting, SpotLightCone) {
    const FilterImage in = constant_alpha({0, 0, 64, 64}, 0);
    SpotLight spot{32, 32, 50, 32, 32, 0, 3, 20.0};
    const FilterImage out = run(in, diffuse(spot));
    for (int dx : {0, 5, 10, 18, 19, 25, 31}) {
        const double c = 50 / std::sqrt(dx * dx + 50.0 * 50);
        const double want = dx <= 18 ? std::pow(c, 4) : 0;
        EXPECT_NEAR(out.at(32 + dx, 32).r, want, 1e-6) << "dx " << dx;
        EXPECT_NEAR(out.at(32, 32 - dx).g, want, 1e-6) << "dy " << -dx;
        EXPECT_EQ(out.at(32 + dx, 32).a, 1.0f);
    }
    // Without a cone the light falls off but does not cut.
    spot.cone_angle.reset();
    const FilterImage wide = run(in, diffuse(spot));
    EXPECT_NEAR(wide.at(32 + 25, 32).r, std::pow(50 / std::sqrt(25 * 25 + 50.0 * 50), 4), 1e-6);
    // Pointing away from the surface lights nothing.
    const FilterImage away = run(in, diffuse(SpotLight{32, 32, 50, 32, 32, 100, 1, {}}));
    EXPECT_EQ(away.at(32, 32).r, 0.0f);
}

// Specular: alpha is the largest channel, the colors as they are (already
// premultiplied, as every engine takes them).
TEST(Lighting, SpecularAlphaIsTheMaximumChannel) {
    const FilterImage in = constant_alpha({0, 0, 6, 5}, 0.3f);
    Lighting l = diffuse(DistantLight{0, 90}, 0.6, {1, 0.5f, 0.25f, 1});
    l.specular = true;
    l.specular_exponent = 20;
    // Straight above: H = (0, 0, 1), N.H = 1: straight RGB = 0.6 * color.
    FilterImage out = run(in, l);
    for (const Premul& p : out.px) {
        EXPECT_NEAR(p.a, 0.6, 1e-6);
        EXPECT_NEAR(p.r, 0.6, 1e-6);
        EXPECT_NEAR(p.g, 0.3, 1e-6);
        EXPECT_NEAR(p.b, 0.15, 1e-6);
    }
    // Elevation 60: H = normalize(L + (0, 0, 1)), N.H = cos(15 degrees).
    l.light = DistantLight{45, 60};
    l.color = {0.2f, 0.9f, 0.4f, 1};
    l.constant = 1.5;
    out = run(in, l);
    const double k = 1.5 * std::pow(std::cos(15 * std::acos(-1.0) / 180), 20);
    for (const Premul& p : out.px) {
        const double a = std::min(1.0, k * 0.9);
        EXPECT_NEAR(p.a, a, 1e-6);
        EXPECT_NEAR(p.g, a, 1e-6);
        EXPECT_NEAR(p.r, k * 0.2, 1e-6);
        EXPECT_LE(p.r, p.a);
    }
    // A bright highlight clamps every channel to 1: opaque white.
    l.constant = 10;
    l.color = {1, 1, 1, 1};
    for (const Premul& p : run(in, l).px) {
        EXPECT_EQ(p.a, 1.0f);
        EXPECT_EQ(p.b, 1.0f);
    }
}

TEST(Lighting, WritesOnlyTheSubregion) {
    const FilterImage in = constant_alpha({0, 0, 8, 8}, 1);
    FilterImage out;
    out.reset(in.box, false);
    const Subregion sub{2, 3, 6, 5};
    lighting(in, out, sub, diffuse(DistantLight{0, 90}));
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(out.at(x, y).a, sub.contains(x, y) ? 1.0f : 0.0f);
}

} // namespace
} // namespace casteljau
