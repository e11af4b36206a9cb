// Marker positions and directions (SVG 2, 9.4 and 13.7.3), by hand.
#include "casteljau/curve/path_data.h"
#include "casteljau/svg/marker_vertices.h"

#include <gtest/gtest.h>

namespace casteljau {
namespace {

std::vector<MarkerVertex> of(const char* d) { return marker_vertices(parse_path_data(d).path); }

void expect_vertex(const MarkerVertex& v, Point at, double angle, MarkerSlot slot, int i) {
    EXPECT_NEAR(v.at.x, at.x, 1e-12) << "vertex " << i;
    EXPECT_NEAR(v.at.y, at.y, 1e-12) << "vertex " << i;
    EXPECT_NEAR(v.angle_deg, angle, 1e-9) << "vertex " << i;
    EXPECT_EQ(v.slot, slot) << "vertex " << i;
}

TEST(MarkerVertices, OpenPolylineBisectsItsCorners) {
    const auto v = of("M0 0 L10 0 L10 10");
    ASSERT_EQ(v.size(), 3u);
    expect_vertex(v[0], {0, 0}, 0, MarkerSlot::Start, 0);
    expect_vertex(v[1], {10, 0}, 45, MarkerSlot::Mid, 1); // in 0, out 90
    expect_vertex(v[2], {10, 10}, 90, MarkerSlot::End, 2);
}

TEST(MarkerVertices, ClosedSubpathsTakeTheClosingSegmentAtTheirEnds) {
    // M L L Z: four vertices, the closing line's end is the fourth.
    const auto v = of("M0 0 L10 0 L10 10 Z");
    ASSERT_EQ(v.size(), 4u);
    // Start: in along the closing line (from 10,10 to 0,0: -135), out 0.
    expect_vertex(v[0], {0, 0}, -67.5, MarkerSlot::Start, 0);
    expect_vertex(v[3], {0, 0}, -67.5, MarkerSlot::End, 3);
}

TEST(MarkerVertices, AnglesAverageAcrossTheSmallerArc) {
    // In at 170 degrees (up-left), out at -170: the bisector is 180, not 0.
    const double r = 3.14159265358979323846 / 180;
    Path p;
    p.move_to({0, 0});
    p.line_to({std::cos(170 * r), std::sin(170 * r)});
    p.line_to({std::cos(170 * r) + std::cos(-170 * r), std::sin(170 * r) + std::sin(-170 * r)});
    const auto v = marker_vertices(p);
    EXPECT_NEAR(std::fmod(v[1].angle_deg + 360, 360), 180, 1e-9);
}

TEST(MarkerVertices, ZeroLengthSegmentsBorrowTheirNeighboursDirections) {
    const auto v = of("M0 0 L10 0 L10 0 L10 10");
    ASSERT_EQ(v.size(), 4u);
    expect_vertex(v[1], {10, 0}, 45, MarkerSlot::Mid, 1); // in 0, out from the next nonzero: 90
    expect_vertex(v[2], {10, 0}, 45, MarkerSlot::Mid, 2); // in from the last nonzero: 0
    // Curves: the tangent, not the chord.
    const auto c = of("M0 0 C0 10 10 10 10 0");
    expect_vertex(c[0], {0, 0}, 90, MarkerSlot::Start, 0);
    expect_vertex(c[1], {10, 0}, -90, MarkerSlot::End, 1);
}

TEST(MarkerVertices, EverySubpathStartIsAMidVertex) {
    const auto v = of("M0 0 H10 M20 0 V10");
    ASSERT_EQ(v.size(), 4u);
    expect_vertex(v[1], {10, 0}, 0, MarkerSlot::Mid, 1);
    expect_vertex(v[2], {20, 0}, 90, MarkerSlot::Mid, 2);
    expect_vertex(v[3], {20, 10}, 90, MarkerSlot::End, 3);
}

} // namespace
} // namespace casteljau
