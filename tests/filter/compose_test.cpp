// Flood, offset, blend, composite, merge, tile: each operator against its
// formula on premultiplied pixels.
#include "casteljau/filter/compose.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

FilterImage filled(int w, int h, Premul p) {
    FilterImage img;
    img.reset({0, 0, w, h}, false);
    for (Premul& q : img.px) q = p;
    return img;
}

void expect_pixel(const Premul& got, const Premul& want, const char* what) {
    EXPECT_NEAR(got.r, want.r, 1e-6) << what;
    EXPECT_NEAR(got.g, want.g, 1e-6) << what;
    EXPECT_NEAR(got.b, want.b, 1e-6) << what;
    EXPECT_NEAR(got.a, want.a, 1e-6) << what;
}

TEST(Composite, PorterDuffOperators) {
    using Op = Composite::Op;
    const Premul A{0.4f, 0.1f, 0, 0.5f}, B{0, 0.3f, 0.6f, 0.75f};
    const FilterImage a = filled(1, 1, A), b = filled(1, 1, B);
    FilterImage out = filled(1, 1, {});
    const Subregion all{0, 0, 1, 1};
    const auto run = [&](Op op) {
        composite(a, b, out, all, Composite{op});
        return out.at(0, 0);
    };
    const auto mix = [](Premul x, float s, Premul y, float t) {
        return Premul{x.r * s + y.r * t, x.g * s + y.g * t, x.b * s + y.b * t, x.a * s + y.a * t};
    };
    expect_pixel(run(Op::Over), mix(A, 1, B, 1 - A.a), "over");
    expect_pixel(run(Op::In), mix(A, B.a, B, 0), "in");
    expect_pixel(run(Op::Out), mix(A, 1 - B.a, B, 0), "out");
    expect_pixel(run(Op::Atop), mix(A, B.a, B, 1 - A.a), "atop");
    expect_pixel(run(Op::Xor), mix(A, 1 - B.a, B, 1 - A.a), "xor");
    expect_pixel(run(Op::Lighter), {0.4f, 0.4f, 0.6f, 1}, "lighter, alpha clamped");
}

TEST(Composite, ArithmeticIsClampedToAValidColor) {
    const FilterImage a = filled(1, 1, {0.5f, 0.5f, 0.5f, 0.5f}), b = filled(1, 1, {0, 0, 0, 1});
    FilterImage out = filled(1, 1, {});
    composite(a, b, out, {0, 0, 1, 1}, Composite{Composite::Op::Arithmetic, 0, 2, 0, 0.25f});
    // 2 * 0.5 + 0.25 = 1.25 -> 1 for every channel.
    expect_pixel(out.at(0, 0), {1, 1, 1, 1}, "clamped");
    composite(a, b, out, {0, 0, 1, 1}, Composite{Composite::Op::Arithmetic, 0, 0, 0.5f, 0});
    expect_pixel(out.at(0, 0), {0, 0, 0, 0.5f}, "k3 in2");
}

TEST(Compose, FloodOffsetTileMerge) {
    FilterImage out = filled(6, 6, {});
    flood(out, {1, 1, 3, 4}, {0.2f, 0, 0, 0.5f});
    EXPECT_EQ(out.at(1, 1).a, 0.5f);
    EXPECT_EQ(out.at(3, 1).a, 0.0f);
    FilterImage moved = filled(6, 6, {});
    offset(out, moved, {0, 0, 6, 6}, 2, 1);
    EXPECT_EQ(moved.at(3, 2).a, 0.5f);
    EXPECT_EQ(moved.at(1, 1).a, 0.0f);
    FilterImage tiled = filled(6, 6, {});
    tile(out, {1, 1, 3, 4}, tiled, {0, 0, 6, 6}); // a 2 x 3 tile of flood
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 6; ++x) ASSERT_EQ(tiled.at(x, y).a, 0.5f) << x << "," << y;
    FilterImage merged = filled(1, 1, {});
    const FilterImage lo = filled(1, 1, {0, 0, 1, 1}), hi = filled(1, 1, {0.5f, 0, 0, 0.5f});
    const FilterImage* both[] = {&lo, &hi};
    merge(both, merged, {0, 0, 1, 1});
    expect_pixel(merged.at(0, 0), {0.5f, 0, 0.5f, 1}, "hi over lo");
}

TEST(Compose, BlendPutsInOverIn2) {
    const FilterImage top = filled(1, 1, {0.5f, 0, 0, 0.5f}), under = filled(1, 1, {0, 0, 1, 1});
    FilterImage out = filled(1, 1, {});
    blend(top, under, out, {0, 0, 1, 1}, BlendMode::Normal);
    expect_pixel(out.at(0, 0), {0.5f, 0, 0.5f, 1}, "normal is source-over");
    blend(top, under, out, {0, 0, 1, 1}, BlendMode::Multiply);
    // co = cs (1 - ab) + cb (1 - as) + as ab B: R 0 + 0 + .5 * (1 * 0) = 0; B .5
    expect_pixel(out.at(0, 0), {0, 0, 0.5f, 1}, "multiply");
}

} // namespace
} // namespace casteljau
