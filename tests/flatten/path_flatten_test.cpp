#include "casteljau/curve/path_data.h"
#include "casteljau/flatten/path_flatten.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

TEST(PathFlatten, ToleranceIsInDeviceSpace) {
    // The same circle at scale 1 and scale 10: at scale 10 the device-space
    // tolerance needs ~sqrt(10) times more segments, and both meet it.
    const PathDataResult r = parse_path_data("M10 0 A10 10 0 1 1 -10 0 A10 10 0 1 1 10 0 Z");
    ASSERT_FALSE(r.error);
    std::vector<Polyline> small, big;
    const FlattenStats s1 = flatten_path(r.path, Affine::identity(), {}, small, true);
    const FlattenStats s10 = flatten_path(r.path, Affine::scale(10), {}, big, true);
    EXPECT_LE(s1.max_error, 0.25 + 1e-9);
    EXPECT_LE(s10.max_error, 0.25 + 1e-9);
    EXPECT_GT(double(s10.segments_out) / double(s1.segments_out), 2.5);
    EXPECT_LT(double(s10.segments_out) / double(s1.segments_out), 4.0);
    ASSERT_EQ(big.size(), 1u);
    EXPECT_TRUE(big[0].closed);
    EXPECT_EQ(big[0].points.front(), big[0].points.back());
    EXPECT_EQ(s1.curves_in, 4u);
}

TEST(PathFlatten, NonUniformTransformAndLinesPassThrough) {
    const PathDataResult r = parse_path_data("M0 0 L10 0 Q20 0 20 10 M5 5 h1");
    std::vector<Polyline> out;
    const FlattenStats s =
        flatten_path(r.path, Affine::scale(30, 1) * Affine::rotate(0.3), {}, out, true);
    EXPECT_LE(s.max_error, 0.25 + 1e-9);
    ASSERT_EQ(out.size(), 2u);
    EXPECT_EQ(out[1].points.size(), 2u);
    EXPECT_EQ(s.segments_out, out[0].points.size() - 1 + 1);
}

TEST(PathFlatten, MaxDepthReportsTheShortestStep) {
    const PathDataResult r = parse_path_data("M0 0 C 0 100 100 100 100 0");
    std::vector<Polyline> out;
    const FlattenStats s =
        flatten_path(r.path, Affine::identity(), {0.25, FlattenMethod::Uniform, 8}, out);
    EXPECT_EQ(s.max_depth, 3); // steps of 1/8
    EXPECT_EQ(s.segments_out, 8u);
}

} // namespace
} // namespace casteljau
